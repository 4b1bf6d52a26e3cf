/* playground._engine._libm: math.atan2 over arrays, element by element, in one C call.
 *
 * The compiled helper of playground/_engine/libm.py. numpy's arctan2 is not the C library's:
 * on a CPU with AVX-512 its SIMD loop gives another last bit for about one pair in thirteen, and
 * a crowd's balance torque would differ from the same controller's alone (which uses
 * math.atan2). This loop is CPython's own math.atan2 (m_atan2 in Modules/mathmodule.c: its
 * special cases, then the C library's atan2, the same symbol CPython calls), so it gives
 * math.atan2's result bit for bit. It is optional: without a compiler libm.py maps math.atan2
 * over the elements, the same results (tests/_engine/test_libm.py).
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <math.h>
#include <string.h>

/* CPython 3.11-3.13's m_atan2, verbatim but for the names. */
static double
m_atan2(double y, double x)
{
    if (isnan(x) || isnan(y))
        return NAN;
    if (isinf(y)) {
        if (isinf(x)) {
            if (copysign(1., x) == 1.)
                /* atan2(+-inf, +inf) == +-pi/4 */
                return copysign(0.25 * M_PI, y);
            else
                /* atan2(+-inf, -inf) == +-pi*3/4 */
                return copysign(0.75 * M_PI, y);
        }
        /* atan2(+-inf, x) == +-pi/2 for finite x */
        return copysign(0.5 * M_PI, y);
    }
    if (isinf(x) || y == 0.) {
        if (copysign(1., x) == 1.)
            /* atan2(+-y, +inf) = atan2(+-0, +x) = +-0. */
            return copysign(0., y);
        else
            /* atan2(+-y, -inf) = atan2(+-0., -x) = +-pi. */
            return copysign(M_PI, y);
    }
    return atan2(y, x);
}

/* A C-contiguous buffer of float64 ('d'). */
static int
get_doubles(PyObject *obj, Py_buffer *view, int writable, const char *name)
{
    int flags = PyBUF_C_CONTIGUOUS | PyBUF_FORMAT | (writable ? PyBUF_WRITABLE : 0);
    if (PyObject_GetBuffer(obj, view, flags) < 0)
        return -1;
    const char *format = view->format ? view->format : "B";
    if (view->itemsize != (Py_ssize_t)sizeof(double) || strcmp(format, "d") != 0) {
        PyErr_Format(PyExc_TypeError, "%s: expected float64 items, got '%s'", name, format);
        PyBuffer_Release(view);
        return -1;
    }
    return 0;
}

PyDoc_STRVAR(atan2_doc,
"atan2(y, x, out) -> None\n\n"
"out[i] = math.atan2(y[i], x[i]) for every i (rad): three C-contiguous float64 buffers of one\n"
"length.");

static PyObject *
atan2_each(PyObject *self, PyObject *args)
{
    PyObject *y_obj, *x_obj, *out_obj;
    if (!PyArg_ParseTuple(args, "OOO:atan2", &y_obj, &x_obj, &out_obj))
        return NULL;
    Py_buffer y, x, out;
    if (get_doubles(y_obj, &y, 0, "y") < 0)
        return NULL;
    if (get_doubles(x_obj, &x, 0, "x") < 0) {
        PyBuffer_Release(&y);
        return NULL;
    }
    if (get_doubles(out_obj, &out, 1, "out") < 0) {
        PyBuffer_Release(&y);
        PyBuffer_Release(&x);
        return NULL;
    }
    PyObject *result = NULL;
    if (y.len != x.len || y.len != out.len) {
        PyErr_SetString(PyExc_ValueError, "atan2: y, x and out must have one length");
    } else {
        const double *yp = (const double *)y.buf, *xp = (const double *)x.buf;
        double *op = (double *)out.buf;
        Py_ssize_t n = y.len / (Py_ssize_t)sizeof(double);
        for (Py_ssize_t i = 0; i < n; i++)
            op[i] = m_atan2(yp[i], xp[i]);
        result = Py_None;
        Py_INCREF(result);
    }
    PyBuffer_Release(&y);
    PyBuffer_Release(&x);
    PyBuffer_Release(&out);
    return result;
}

static PyMethodDef methods[] = {
    {"atan2", atan2_each, METH_VARARGS, atan2_doc},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef module = {
    PyModuleDef_HEAD_INIT,
    "playground._engine._libm",
    "math.atan2 over arrays in one C call (see playground._engine.libm, the only caller).",
    -1,
    methods,
    NULL,
    NULL,
    NULL,
    NULL,
};

PyMODINIT_FUNC
PyInit__libm(void)
{
    return PyModule_Create(&module);
}
