/* playground._engine._nearest: many probes' nearest-hit segment queries in one C call.
 *
 * The compiled helper of playground/_engine/sweep.py (``Sweeps``): for each probe it calls
 * Chipmunk's cpSpaceSegmentQuery with a C callback that keeps exactly what sweep.py's Python
 * callback ``_keep_nearest`` keeps (the strictly nearest non-sensor hit, so of equally near hits
 * the first visited), and writes the hit point and normal into arrays. Chipmunk is not linked
 * here: its functions, the spaces and the shape filters come in as addresses taken from pymunk's
 * cffi module (sweep.py checks there that the declarations below match pymunk's), so this file
 * needs only Python's headers. It is optional: without a compiler sweep.py answers through the
 * Python callback, bit for bit the same (tests/_engine/test_sweep.py).
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <math.h>
#include <stdint.h>

/* Chipmunk's types as pymunk 7 declares them (cpFloat double, cpBool unsigned char, cpGroup
 * uintptr_t, cpBitmask unsigned int); sweep.py compares them with pymunk's cffi before use. */
typedef struct { double x, y; } cpVect;
typedef struct { uintptr_t group; unsigned int categories; unsigned int mask; } cpShapeFilter;
typedef struct cpShape cpShape;
typedef struct cpSpace cpSpace;
typedef void (*QueryFunc)(cpShape *, cpVect, cpVect, double, void *);
typedef void (*SegmentQuery)(cpSpace *, cpVect, cpVect, double, cpShapeFilter, QueryFunc, void *);
typedef unsigned char (*GetSensor)(cpShape *);

typedef struct {
    double alpha;
    cpShape *shape;
    cpVect point, normal;
    GetSensor is_sensor;
} Best;

/* sweep.py's _keep_nearest: strictly nearer only, sensors skipped. */
static void
keep_nearest(cpShape *shape, cpVect point, cpVect normal, double alpha, void *data)
{
    Best *best = (Best *)data;
    if (alpha < best->alpha && !best->is_sensor(shape)) {
        best->alpha = alpha;
        best->shape = shape;
        best->point = point;
        best->normal = normal;
    }
}

/* A C-contiguous buffer of n items of `itemsize` bytes whose format ends in one of `kinds`. */
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

enum { SPACES, FILTERS, ROWS, X0, Y0, X1, Y1, RADIUS, WHICH, SHAPES, HITS, N_BUFFERS };

PyDoc_STRVAR(segment_queries_doc,
"segment_queries(query, is_sensor, spaces, filters, rows, x0, y0, x1, y1, radius, which, shapes, hits)\n"
"--\n\n"
"For each k, the nearest non-sensor hit of a circle of radius[k] (m) swept from (x0[k], y0[k])\n"
"to (x1[k], y1[k]) (m) through spaces[rows[k]] among the shapes filters[rows[k]] lets through;\n"
"returns the number of distinct shapes hit.\n\n"
"query, is_sensor: addresses of cpSpaceSegmentQuery and cpShapeGetSensor. spaces, filters:\n"
"uintp arrays of cpSpace* and cpShapeFilter* addresses. rows: intp. x0 ... radius: float64, one\n"
"per k. Written: which[k] (intp) the index in shapes of the shape hit, -1 if none; shapes\n"
"(uintp, as long as rows) the distinct cpShape* hit, in the order first hit; hits (float64,\n"
"4 x len(rows)) the hit point's x, y and the normal's x, y (NaN where none).");

static PyObject *
segment_queries(PyObject *self, PyObject *args)
{
    (void)self;
    PyObject *query_obj, *sensor_obj, *objs[N_BUFFERS];
    if (!PyArg_ParseTuple(args, "OOOOOOOOOOOOO:segment_queries", &query_obj, &sensor_obj,
                          &objs[SPACES], &objs[FILTERS], &objs[ROWS], &objs[X0], &objs[Y0],
                          &objs[X1], &objs[Y1], &objs[RADIUS], &objs[WHICH], &objs[SHAPES],
                          &objs[HITS]))
        return NULL;
    SegmentQuery query = (SegmentQuery)PyLong_AsVoidPtr(query_obj);
    if (query == NULL && PyErr_Occurred())
        return NULL;
    GetSensor is_sensor = (GetSensor)PyLong_AsVoidPtr(sensor_obj);
    if (is_sensor == NULL && PyErr_Occurred())
        return NULL;
    if (query == NULL || is_sensor == NULL) {
        PyErr_SetString(PyExc_ValueError, "query and is_sensor must not be null");
        return NULL;
    }

    static const char *names[N_BUFFERS] = {"spaces", "filters", "rows", "x0", "y0", "x1", "y1",
                                           "radius", "which", "shapes", "hits"};
    Py_buffer views[N_BUFFERS];
    int got = 0;
    PyObject *result = NULL;
    for (; got < N_BUFFERS; got++) {
        Py_ssize_t size = sizeof(double);
        const char *kinds = "d";
        int writable = got >= WHICH;
        if (got == SPACES || got == FILTERS || got == SHAPES) {
            size = sizeof(void *);
            kinds = "LQN";
        } else if (got == ROWS || got == WHICH) {
            size = sizeof(Py_ssize_t);
            kinds = "lqn";
        }
        if (get_buffer(objs[got], &views[got], size, kinds, writable, names[got]) < 0)
            goto done;
    }
    Py_ssize_t probes = views[SPACES].len / (Py_ssize_t)sizeof(void *);
    Py_ssize_t m = views[ROWS].len / (Py_ssize_t)sizeof(Py_ssize_t);
    if (views[FILTERS].len != views[SPACES].len || views[SHAPES].len / (Py_ssize_t)sizeof(void *) != m
        || views[HITS].len / (Py_ssize_t)sizeof(double) != 4 * m) {
        PyErr_SetString(PyExc_ValueError, "spaces and filters, or rows, shapes and hits, differ in length");
        goto done;
    }
    for (int b = X0; b <= WHICH; b++) {
        if (views[b].len / views[b].itemsize != m) {
            PyErr_Format(PyExc_ValueError, "%s: %zd items, rows has %zd", names[b],
                         views[b].len / views[b].itemsize, m);
            goto done;
        }
    }
    const uintptr_t *spaces = views[SPACES].buf, *filters = views[FILTERS].buf;
    const Py_ssize_t *rows = views[ROWS].buf;
    const double *x0 = views[X0].buf, *y0 = views[Y0].buf, *x1 = views[X1].buf,
                 *y1 = views[Y1].buf, *radius = views[RADIUS].buf;
    Py_ssize_t *which = views[WHICH].buf;
    uintptr_t *shapes = views[SHAPES].buf;
    double *hits = views[HITS].buf;
    for (Py_ssize_t k = 0; k < m; k++) {
        if (rows[k] < 0 || rows[k] >= probes) {
            PyErr_Format(PyExc_IndexError, "rows[%zd] = %zd is not a probe (%zd probes)", k,
                         rows[k], probes);
            goto done;
        }
    }

    Py_ssize_t distinct = 0;
    Py_ssize_t last = -1; /* the index of the last shape hit: most probes of a crowd hit one floor */
    for (Py_ssize_t k = 0; k < m; k++) {
        Py_ssize_t r = rows[k];
        Best best = {INFINITY, NULL, {0.0, 0.0}, {0.0, 0.0}, is_sensor};
        cpShapeFilter filter = *(const cpShapeFilter *)filters[r];
        query((cpSpace *)spaces[r], (cpVect){x0[k], y0[k]}, (cpVect){x1[k], y1[k]}, radius[k],
              filter, keep_nearest, &best);
        if (best.shape == NULL) {
            which[k] = -1;
            hits[k] = hits[m + k] = hits[2 * m + k] = hits[3 * m + k] = NAN;
            continue;
        }
        uintptr_t s = (uintptr_t)best.shape;
        Py_ssize_t j = last;
        if (j < 0 || shapes[j] != s) {
            for (j = 0; j < distinct && shapes[j] != s; j++)
                ;
            if (j == distinct)
                shapes[distinct++] = s;
        }
        which[k] = last = j;
        hits[k] = best.point.x;
        hits[m + k] = best.point.y;
        hits[2 * m + k] = best.normal.x;
        hits[3 * m + k] = best.normal.y;
    }
    result = PyLong_FromSsize_t(distinct);
done:
    for (int b = 0; b < got; b++)
        PyBuffer_Release(&views[b]);
    return result;
}

static PyMethodDef methods[] = {
    {"segment_queries", segment_queries, METH_VARARGS, segment_queries_doc},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef module = {
    PyModuleDef_HEAD_INIT,
    "playground._engine._nearest",
    "Many probes' nearest-hit segment queries through Chipmunk in one C call (see "
    "playground._engine.sweep.Sweeps, the only caller).",
    -1,
    methods,
    NULL,
    NULL,
    NULL,
    NULL,
};

PyMODINIT_FUNC
PyInit__nearest(void)
{
    return PyModule_Create(&module);
}
