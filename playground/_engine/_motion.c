/* playground._engine._motion: many bodies' velocity, angular velocity, force and torque in one C
 * call, as Python floats.
 *
 * The compiled helper of playground/_engine/motion.py (``Motions``): for each body it calls
 * Chipmunk's cpBodyGetVelocity and cpBodyGetAngularVelocity (and cpBodyGetForce and
 * cpBodyGetTorque), the getters pymunk's properties call, so it reads the very doubles they read.
 * Chipmunk is not linked here: the getters and the bodies come in as addresses taken from
 * pymunk's cffi module (motion.py checks there that the declarations below match pymunk's), so
 * this file needs only Python's headers. It is optional: without a compiler motion.py calls the
 * getters through cffi, body by body, bit for bit the same (tests/_engine/test_motion.py).
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <stdint.h>
#include <string.h>

typedef struct cpBody cpBody;
typedef struct cpVect {
    double x, y;
} cpVect;
typedef cpVect (*GetVect)(cpBody *);
typedef double (*GetFloat)(cpBody *);

/* A function address from a Python int; NULL with an exception set if it is not one. */
static void *
address(PyObject *obj, const char *name)
{
    void *p = PyLong_AsVoidPtr(obj);
    if (p == NULL && !PyErr_Occurred())
        PyErr_Format(PyExc_ValueError, "%s must not be null", name);
    return p;
}

/* A tuple of `n` floats, or NULL with an exception set. */
static PyObject *
floats(const double *values, int n)
{
    PyObject *out = PyTuple_New(n);
    if (out == NULL)
        return NULL;
    for (int c = 0; c < n; c++) {
        PyObject *x = PyFloat_FromDouble(values[c]);
        if (x == NULL) {
            Py_DECREF(out);
            return NULL;
        }
        PyTuple_SET_ITEM(out, c, x);
    }
    return out;
}

PyDoc_STRVAR(motion_doc,
"motion(get_velocity, get_angular_velocity, get_force, get_torque, bodies, forces)\n"
"--\n\n"
"A new list of one tuple a body of `bodies`, in order: (vx, vy, w) (m/s, rad/s), and with\n"
"`forces` true (vx, vy, w, fx, fy, t) (N, N m), read through the getters at the given\n"
"addresses (cpBodyGetVelocity, cpBodyGetAngularVelocity, cpBodyGetForce, cpBodyGetTorque).\n"
"bodies: a C-contiguous buffer of cpBody* addresses (uintp), each of a live body.");

static PyObject *
motion(PyObject *self, PyObject *const *args, Py_ssize_t nargs)
{
    (void)self;
    if (nargs != 6) {
        PyErr_Format(PyExc_TypeError, "motion: expected 6 arguments, got %zd", nargs);
        return NULL;
    }
    GetVect get_velocity = (GetVect)address(args[0], "get_velocity");
    if (get_velocity == NULL)
        return NULL;
    GetFloat get_angular_velocity = (GetFloat)address(args[1], "get_angular_velocity");
    if (get_angular_velocity == NULL)
        return NULL;
    GetVect get_force = (GetVect)address(args[2], "get_force");
    if (get_force == NULL)
        return NULL;
    GetFloat get_torque = (GetFloat)address(args[3], "get_torque");
    if (get_torque == NULL)
        return NULL;
    int forces = PyObject_IsTrue(args[5]);
    if (forces < 0)
        return NULL;
    Py_buffer bodies;
    if (PyObject_GetBuffer(args[4], &bodies, PyBUF_C_CONTIGUOUS | PyBUF_FORMAT) < 0)
        return NULL;
    PyObject *result = NULL;
    const char *format = bodies.format ? bodies.format : "B";
    char kind = format[strlen(format) - 1];
    if (bodies.itemsize != (Py_ssize_t)sizeof(void *) || kind == '\0' ||
        strchr("LQN", kind) == NULL) {
        PyErr_Format(PyExc_TypeError, "bodies: expected items of %zd bytes of format L, Q or N, "
                     "got '%s'", (Py_ssize_t)sizeof(void *), format);
        goto done;
    }
    Py_ssize_t n = bodies.len / (Py_ssize_t)sizeof(void *);
    const uintptr_t *body = bodies.buf;
    for (Py_ssize_t k = 0; k < n; k++) {
        if (body[k] == 0) {
            PyErr_Format(PyExc_ValueError, "bodies[%zd] is null", k);
            goto done;
        }
    }
    PyObject *out = PyList_New(n);
    if (out == NULL)
        goto done;
    for (Py_ssize_t k = 0; k < n; k++) {
        cpBody *b = (cpBody *)body[k];
        double values[6];
        cpVect v = get_velocity(b);
        values[0] = v.x;
        values[1] = v.y;
        values[2] = get_angular_velocity(b);
        if (forces) {
            cpVect f = get_force(b);
            values[3] = f.x;
            values[4] = f.y;
            values[5] = get_torque(b);
        }
        PyObject *row = floats(values, forces ? 6 : 3);
        if (row == NULL) {
            Py_DECREF(out);
            goto done;
        }
        PyList_SET_ITEM(out, k, row);
    }
    result = out;
done:
    PyBuffer_Release(&bodies);
    return result;
}

static PyMethodDef methods[] = {
    {"motion", (PyCFunction)(void (*)(void))motion, METH_FASTCALL, motion_doc},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef module = {
    PyModuleDef_HEAD_INIT,
    "playground._engine._motion",
    "Many bodies' velocity, angular velocity, force and torque through Chipmunk's getters in one "
    "C call (see playground._engine.motion.Motions, the only caller).",
    -1,
    methods,
    NULL,
    NULL,
    NULL,
    NULL,
};

PyMODINIT_FUNC
PyInit__motion(void)
{
    return PyModule_Create(&module);
}
