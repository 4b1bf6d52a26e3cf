/* playground._engine._impulses: each tracked body's arbiter impulses summed in one C call.
 *
 * The compiled helper of playground/_engine/impulses.py (``sum_impulses``). It takes the doubles
 * of one read of every arbiter of a space (jx, jy, nx, ny each: the impulse on body A, N s, and
 * the normal from A to B), a plan of which arbiters' terms go to which row, and the rows' sums
 * so far; it works out each term as the scalar contact split does in Python floats (J and its
 * normal part (J.n)n, body B's the negation), puts each row's terms in the order Python sorts
 * their tuples (jx, then jy, jnx, jny) and adds them in that order. Every operation is one IEEE
 * double operation in the order the Python code makes it, so the sums are its sums, bit for bit
 * (tests/_engine/test_impulses.py compares the two); pyproject.toml builds this file with
 * -ffp-contract=off, so no multiply and add are fused into one rounding. It is optional:
 * without a compiler impulses.py sums in Python floats.
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <string.h>

#define TERM 4     /* doubles of one term: jx, jy, jnx, jny */
#define ON_STACK 32 /* terms of one row kept on the stack; more are allocated */

/* A C-contiguous buffer of Py_ssize_t items (an array('l') or ('q'), or numpy intp). */
static int
get_indices(PyObject *obj, Py_buffer *view, const char *name)
{
    if (PyObject_GetBuffer(obj, view, PyBUF_C_CONTIGUOUS | PyBUF_FORMAT) < 0)
        return -1;
    const char *format = view->format ? view->format : "B";
    char kind = format[strlen(format) - 1];
    if (view->itemsize != (Py_ssize_t)sizeof(Py_ssize_t) || kind == '\0' ||
        strchr("nlq", kind) == NULL) {
        PyErr_Format(PyExc_TypeError, "%s: expected items of %zd bytes of format n, l or q, "
                     "got '%s'", name, (Py_ssize_t)sizeof(Py_ssize_t), format);
        PyBuffer_Release(view);
        return -1;
    }
    return 0;
}

/* b < a as Python compares two tuples of floats: the first pair of items that are not equal
 * decides; none: not less. */
static int
before(const double *b, const double *a)
{
    for (int c = 0; c < TERM; c++) {
        if (!(a[c] == b[c]))
            return b[c] < a[c];
    }
    return 0;
}

/* Term `term` of the read: arbiter `term` for its body A (J, (J.n)n) when term < m, else the
 * negation for body B of arbiter term - m; the same operations as the Python code's. */
static void
make_term(const double *values, Py_ssize_t m, Py_ssize_t term, double *out)
{
    const double *v = values + TERM * (term < m ? term : term - m);
    double jx = v[0], jy = v[1], nx = v[2], ny = v[3];
    double dot = jx * nx + jy * ny;
    double jnx = nx * dot, jny = ny * dot;
    if (term < m) {
        out[0] = jx;
        out[1] = jy;
        out[2] = jnx;
        out[3] = jny;
    }
    else {
        out[0] = -jx;
        out[1] = -jy;
        out[2] = -jnx;
        out[3] = -jny;
    }
}

/* Row sums from +0.0 (fresh) or from the row's previous tuple, then each term in order. */
static PyObject *
row_sums(const double *terms, Py_ssize_t k, PyObject *previous)
{
    double sum[TERM] = {0.0, 0.0, 0.0, 0.0};
    if (previous != NULL) {
        if (!PyTuple_Check(previous) || PyTuple_GET_SIZE(previous) != TERM) {
            PyErr_SetString(PyExc_TypeError, "previous: expected tuples of 4 floats");
            return NULL;
        }
        for (int c = 0; c < TERM; c++) {
            sum[c] = PyFloat_AsDouble(PyTuple_GET_ITEM(previous, c));
            if (sum[c] == -1.0 && PyErr_Occurred())
                return NULL;
        }
    }
    for (Py_ssize_t t = 0; t < k; t++) {
        for (int c = 0; c < TERM; c++)
            sum[c] = sum[c] + terms[TERM * t + c];
    }
    PyObject *out = PyTuple_New(TERM);
    if (out == NULL)
        return NULL;
    for (int c = 0; c < TERM; c++) {
        PyObject *x = PyFloat_FromDouble(sum[c]);
        if (x == NULL) {
            Py_DECREF(out);
            return NULL;
        }
        PyTuple_SET_ITEM(out, c, x);
    }
    return out;
}

PyDoc_STRVAR(sums_doc,
"sums(values, starts, terms, previous)\n"
"--\n\n"
"Each row's sums (jx, jy, jnx, jny), N s: a new list of n tuples of 4 floats.\n\n"
"values: the doubles of one read of m arbiters, 4 each (jx, jy, nx, ny: the impulse on body A\n"
"and the normal), any C-contiguous buffer of 32 m bytes. starts: n + 1 indices (Py_ssize_t),\n"
"row k's terms being terms[starts[k]:starts[k + 1]]. terms: indices < 2 m, i < m naming\n"
"arbiter i's term for its body A (J and its normal part), m + i the negation for its body B.\n"
"previous: None (each sum starts at +0.0) or a list of n tuples of 4 floats to add to.\n"
"A row's terms are added in the order Python sorts their tuples.");

static PyObject *
sums(PyObject *self, PyObject *const *args, Py_ssize_t nargs)
{
    (void)self;
    if (nargs != 4) {
        PyErr_Format(PyExc_TypeError, "sums: expected 4 arguments, got %zd", nargs);
        return NULL;
    }
    PyObject *previous = args[3];
    if (previous != Py_None && !PyList_Check(previous)) {
        PyErr_SetString(PyExc_TypeError, "previous: expected None or a list");
        return NULL;
    }
    Py_buffer values, starts, terms;
    if (PyObject_GetBuffer(args[0], &values, PyBUF_C_CONTIGUOUS) < 0)
        return NULL;
    if (get_indices(args[1], &starts, "starts") < 0) {
        PyBuffer_Release(&values);
        return NULL;
    }
    if (get_indices(args[2], &terms, "terms") < 0) {
        PyBuffer_Release(&values);
        PyBuffer_Release(&starts);
        return NULL;
    }
    PyObject *result = NULL;
    double stack[TERM * ON_STACK];
    double *row = stack;
    Py_ssize_t room = ON_STACK;
    if (values.len % (Py_ssize_t)(TERM * sizeof(double)) != 0) {
        PyErr_Format(PyExc_ValueError, "values: %zd bytes, not a whole number of arbiters",
                     values.len);
        goto done;
    }
    Py_ssize_t m = values.len / (Py_ssize_t)(TERM * sizeof(double));
    Py_ssize_t n = starts.len / (Py_ssize_t)sizeof(Py_ssize_t) - 1;
    Py_ssize_t count = terms.len / (Py_ssize_t)sizeof(Py_ssize_t);
    const Py_ssize_t *start = starts.buf;
    const Py_ssize_t *term = terms.buf;
    if (n < 0 || start[0] != 0 || start[n] != count) {
        PyErr_SetString(PyExc_ValueError, "starts: expected n + 1 indices from 0 to len(terms)");
        goto done;
    }
    for (Py_ssize_t k = 0; k < n; k++) {
        if (start[k + 1] < start[k]) {
            PyErr_Format(PyExc_ValueError, "starts: decreases at %zd", k);
            goto done;
        }
    }
    for (Py_ssize_t t = 0; t < count; t++) {
        if (term[t] < 0 || term[t] >= 2 * m) {
            PyErr_Format(PyExc_ValueError, "terms[%zd] = %zd: not below 2 x %zd arbiters", t,
                         term[t], m);
            goto done;
        }
    }
    if (previous != Py_None && PyList_GET_SIZE(previous) != n) {
        PyErr_Format(PyExc_ValueError, "previous: %zd rows, starts has %zd",
                     PyList_GET_SIZE(previous), n);
        goto done;
    }
    const double *v = values.buf;
    PyObject *out = PyList_New(n);
    if (out == NULL)
        goto done;
    for (Py_ssize_t k = 0; k < n; k++) {
        Py_ssize_t size = start[k + 1] - start[k];
        if (size > room) {
            double *more = PyMem_Realloc(row == stack ? NULL : row, TERM * sizeof(double) *
                                         (size_t)size);
            if (more == NULL) {
                PyErr_NoMemory();
                Py_DECREF(out);
                goto done;
            }
            row = more;
            room = size;
        }
        /* The row's terms, in Python's sorted order: a stable insertion sort. */
        for (Py_ssize_t t = 0; t < size; t++) {
            double x[TERM];
            make_term(v, m, term[start[k] + t], x);
            Py_ssize_t at = t;
            while (at > 0 && before(x, row + TERM * (at - 1))) {
                memcpy(row + TERM * at, row + TERM * (at - 1), sizeof x);
                at--;
            }
            memcpy(row + TERM * at, x, sizeof x);
        }
        PyObject *prev = previous == Py_None ? NULL : PyList_GET_ITEM(previous, k);
        PyObject *sum = row_sums(row, size, prev);
        if (sum == NULL) {
            Py_DECREF(out);
            goto done;
        }
        PyList_SET_ITEM(out, k, sum);
    }
    result = out;
done:
    if (row != stack)
        PyMem_Free(row);
    PyBuffer_Release(&values);
    PyBuffer_Release(&starts);
    PyBuffer_Release(&terms);
    return result;
}

static PyMethodDef methods[] = {
    {"sums", (PyCFunction)(void (*)(void))sums, METH_FASTCALL, sums_doc},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef module = {
    PyModuleDef_HEAD_INIT,
    "playground._engine._impulses",
    "Each tracked body's arbiter impulses summed in one C call (see "
    "playground._engine.impulses.sum_impulses, the only caller).",
    -1,
    methods,
    NULL,
    NULL,
    NULL,
    NULL,
};

PyMODINIT_FUNC
PyInit__impulses(void)
{
    return PyModule_Create(&module);
}
