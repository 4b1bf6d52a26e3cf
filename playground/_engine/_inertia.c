/* playground._engine._inertia: many bodies' mass and moment of inertia in one C call.
 *
 * The compiled helper of playground/_engine/inertia.py (``Inertia``): for each body it calls
 * Chipmunk's cpBodyGetMass and cpBodyGetMoment, the getters pymunk's ``body.mass`` and
 * ``body.moment`` call, so it reads the very doubles they read. Chipmunk is not linked here: the
 * two getters and the bodies come in as addresses taken from pymunk's cffi module (inertia.py
 * checks there that the declaration below matches pymunk's), so this file needs only Python's
 * headers. It is optional: without a compiler inertia.py calls the getters through cffi, one
 * body at a time, bit for bit the same (tests/_engine/test_inertia.py).
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <stdint.h>
#include <string.h>

typedef struct cpBody cpBody;
typedef double (*GetFloat)(cpBody *);

/* A C-contiguous buffer of items of `itemsize` bytes whose format ends in one of `kinds`. */
static int
get_buffer(PyObject *obj, Py_buffer *view, Py_ssize_t itemsize, const char *kinds, int writable,
           const char *name)
{
    int flags = PyBUF_C_CONTIGUOUS | PyBUF_FORMAT | (writable ? PyBUF_WRITABLE : 0);
    if (PyObject_GetBuffer(obj, view, flags) < 0)
        return -1;
    const char *format = view->format ? view->format : "B";
    char kind = format[strlen(format) - 1];
    if (view->itemsize != itemsize || strchr(kinds, kind) == NULL || kind == '\0') {
        PyErr_Format(PyExc_TypeError, "%s: expected items of %zd bytes of format %s, got '%s'",
                     name, itemsize, kinds, format);
        PyBuffer_Release(view);
        return -1;
    }
    return 0;
}

PyDoc_STRVAR(mass_moment_doc,
"mass_moment(get_mass, get_moment, bodies, out)\n"
"--\n\n"
"For each k, out[k] = get_mass(bodies[k]) (kg) and out[n + k] = get_moment(bodies[k]) (kg m^2),\n"
"n = len(bodies).\n\n"
"get_mass, get_moment: addresses of cpBodyGetMass and cpBodyGetMoment. bodies: a uintp array\n"
"of cpBody* addresses, each of a live body. out: a writable float64 array of 2 x n.");

static PyObject *
mass_moment(PyObject *self, PyObject *args)
{
    (void)self;
    PyObject *mass_obj, *moment_obj, *bodies_obj, *out_obj;
    if (!PyArg_ParseTuple(args, "OOOO:mass_moment", &mass_obj, &moment_obj, &bodies_obj,
                          &out_obj))
        return NULL;
    GetFloat get_mass = (GetFloat)PyLong_AsVoidPtr(mass_obj);
    if (get_mass == NULL && PyErr_Occurred())
        return NULL;
    GetFloat get_moment = (GetFloat)PyLong_AsVoidPtr(moment_obj);
    if (get_moment == NULL && PyErr_Occurred())
        return NULL;
    if (get_mass == NULL || get_moment == NULL) {
        PyErr_SetString(PyExc_ValueError, "get_mass and get_moment must not be null");
        return NULL;
    }
    Py_buffer bodies, out;
    if (get_buffer(bodies_obj, &bodies, sizeof(void *), "LQN", 0, "bodies") < 0)
        return NULL;
    if (get_buffer(out_obj, &out, sizeof(double), "d", 1, "out") < 0) {
        PyBuffer_Release(&bodies);
        return NULL;
    }
    PyObject *result = NULL;
    Py_ssize_t n = bodies.len / (Py_ssize_t)sizeof(void *);
    if (out.len / (Py_ssize_t)sizeof(double) != 2 * n) {
        PyErr_Format(PyExc_ValueError, "out: %zd items, 2 x %zd bodies need %zd",
                     out.len / (Py_ssize_t)sizeof(double), n, 2 * n);
        goto done;
    }
    const uintptr_t *body = bodies.buf;
    double *values = out.buf;
    for (Py_ssize_t k = 0; k < n; k++) {
        if (body[k] == 0) {
            PyErr_Format(PyExc_ValueError, "bodies[%zd] is null", k);
            goto done;
        }
    }
    for (Py_ssize_t k = 0; k < n; k++) {
        values[k] = get_mass((cpBody *)body[k]);
        values[n + k] = get_moment((cpBody *)body[k]);
    }
    Py_INCREF(Py_None);
    result = Py_None;
done:
    PyBuffer_Release(&bodies);
    PyBuffer_Release(&out);
    return result;
}

static PyMethodDef methods[] = {
    {"mass_moment", mass_moment, METH_VARARGS, mass_moment_doc},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef module = {
    PyModuleDef_HEAD_INIT,
    "playground._engine._inertia",
    "Many bodies' mass and moment of inertia through Chipmunk's getters in one C call (see "
    "playground._engine.inertia.Inertia, the only caller).",
    -1,
    methods,
    NULL,
    NULL,
    NULL,
    NULL,
};

PyMODINIT_FUNC
PyInit__inertia(void)
{
    return PyModule_Create(&module);
}
