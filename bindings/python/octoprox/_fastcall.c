/*
 * octoprox._fastcall: the usual call of Query.collide and Query.distance
 * (the keywords of the call before, no world) in one C function, so that a
 * tiny query from Python costs little more than its C call.
 *
 * The module does not link liboctoprox: octoprox._calls hands it the
 * address of a C function the package's ctypes library resolved, and gets
 * back a callable for it.  Every function bound here has the shape of
 * opx_query_collide and opx_query_distance:
 *     opx_status f(opx_query *, const opx_octree *, const opx_linkset *,
 *                  const request *, result *)
 * The callable,
 *     call(tree, links, query_address, tree_address, links_address,
 *          request_address, cached_key, *key),
 * serves the call when tree and links are of the bound types and `key`
 * (the method's keyword values) equals `cached_key` (those of the request
 * at request_address, the RequestCache's last): it makes a new result of
 * the bound ctypes struct type with its struct_size set to its size, calls
 * the function on the four addresses (the handles' `_address` ints, 0 for a
 * closed handle, which the library refuses) with the GIL released, as
 * ctypes does, and returns the result when the status is 0, else the
 * status (a negative int).  Any other call returns None: the method's
 * ctypes path serves it and raises what it raises.
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <stdint.h>
#include <string.h>

typedef int32_t (*query_function)(void *query, const void *tree, const void *links,
                                  const void *request, void *result);

/* bind()'s arguments, kept as the callable's `self` (a tuple). */
enum { BOUND_ADDRESS, BOUND_RESULT_TYPE, BOUND_TREE_TYPE, BOUND_LINKS_TYPE, BOUND_COUNT };
/* The callable's arguments before the key's values. */
enum { ARG_TREE, ARG_LINKS, ARG_QUERY_ADDRESS, ARG_TREE_ADDRESS, ARG_LINKS_ADDRESS,
       ARG_REQUEST_ADDRESS, ARG_CACHED_KEY, ARG_KEY };

static PyObject *empty_tuple;

/* The int `value` as a pointer into *out: 1, or 0 when it is no int. */
static int int_pointer(PyObject *value, void **out) {
    if (!PyLong_CheckExact(value)) return 0;
    *out = PyLong_AsVoidPtr(value);
    if (*out == NULL && PyErr_Occurred()) {
        PyErr_Clear();
        return 0;
    }
    return 1;
}

/* 1 when `cached` is a tuple equal to the `count` values of `key`, as
 * Python's == compares tuples; 0 otherwise, also when a comparison raises
 * (an array among the values). */
static int key_matches(PyObject *cached, PyObject *const *key, Py_ssize_t count) {
    int same = PyTuple_Check(cached) && PyTuple_GET_SIZE(cached) == count;
    for (Py_ssize_t i = 0; same && i < count; ++i) {
        PyObject *item = PyTuple_GET_ITEM(cached, i);
        if (item == key[i]) continue;  /* the usual case: the method's defaults */
        same = PyObject_RichCompareBool(item, key[i], Py_EQ);
        if (same < 0) {
            PyErr_Clear();
            same = 0;
        }
    }
    return same;
}

/* A new instance of the ctypes struct type `type` and its buffer, whose
 * first field (uint32 struct_size) is set to the struct's size. */
static PyObject *new_result(PyObject *type, Py_buffer *view) {
    PyTypeObject *struct_type = (PyTypeObject *)type;  /* its tp_new alone: no fields to set */
    PyObject *result = struct_type->tp_new(struct_type, empty_tuple, NULL);
    if (result == NULL) return NULL;
    if (PyObject_GetBuffer(result, view, PyBUF_WRITABLE) != 0) {
        Py_DECREF(result);
        return NULL;
    }
    if (view->len < (Py_ssize_t)sizeof(uint32_t) || view->len > (Py_ssize_t)UINT32_MAX) {
        PyBuffer_Release(view);
        Py_DECREF(result);
        PyErr_SetString(PyExc_TypeError, "octoprox._fastcall: the result type is no versioned struct");
        return NULL;
    }
    const uint32_t size = (uint32_t)view->len;
    memcpy(view->buf, &size, sizeof size);
    return result;
}

/* The C call itself; the result, or the failing status as an int. */
static PyObject *call_function(PyObject *bound, void *const pointers[4]) {
    const query_function function =
        (query_function)PyLong_AsVoidPtr(PyTuple_GET_ITEM(bound, BOUND_ADDRESS));
    Py_buffer view;
    PyObject *result = new_result(PyTuple_GET_ITEM(bound, BOUND_RESULT_TYPE), &view);
    if (result == NULL) return NULL;
    int32_t status;
    Py_BEGIN_ALLOW_THREADS
    status = function(pointers[0], pointers[1], pointers[2], pointers[3], view.buf);
    Py_END_ALLOW_THREADS
    PyBuffer_Release(&view);
    if (status == 0) return result;
    Py_DECREF(result);
    return PyLong_FromLong((long)status);
}

static PyObject *call_bound(PyObject *bound, PyObject *const *args, Py_ssize_t nargs) {
    if (nargs < ARG_KEY) {
        PyErr_Format(PyExc_TypeError, "octoprox._fastcall: %d arguments and the key's values "
                     "expected, got %zd", (int)ARG_KEY, nargs);
        return NULL;
    }
    void *pointers[4];
    const int served =
        PyObject_TypeCheck(args[ARG_TREE], (PyTypeObject *)PyTuple_GET_ITEM(bound, BOUND_TREE_TYPE)) &&
        PyObject_TypeCheck(args[ARG_LINKS], (PyTypeObject *)PyTuple_GET_ITEM(bound, BOUND_LINKS_TYPE)) &&
        key_matches(args[ARG_CACHED_KEY], args + ARG_KEY, nargs - ARG_KEY) &&
        int_pointer(args[ARG_QUERY_ADDRESS], &pointers[0]) &&
        int_pointer(args[ARG_TREE_ADDRESS], &pointers[1]) &&
        int_pointer(args[ARG_LINKS_ADDRESS], &pointers[2]) &&
        int_pointer(args[ARG_REQUEST_ADDRESS], &pointers[3]) && pointers[3] != NULL;
    if (!served) Py_RETURN_NONE;
    return call_function(bound, pointers);
}

static PyMethodDef call_bound_def = {
    "cached_call", (PyCFunction)(void (*)(void))call_bound, METH_FASTCALL,
    "cached_call(tree, links, query_address, tree_address, links_address, request_address, "
    "cached_key, *key) -> result, status or None (see the module)."};

static PyObject *bind(PyObject *module, PyObject *const *args, Py_ssize_t nargs) {
    (void)module;
    if (nargs != BOUND_COUNT || !PyLong_Check(args[BOUND_ADDRESS]) ||
        !PyType_Check(args[BOUND_RESULT_TYPE]) || !PyType_Check(args[BOUND_TREE_TYPE]) ||
        !PyType_Check(args[BOUND_LINKS_TYPE])) {
        PyErr_SetString(PyExc_TypeError, "octoprox._fastcall.bind(address: int, result_type, "
                        "tree_type, links_type)");
        return NULL;
    }
    if (PyLong_AsVoidPtr(args[BOUND_ADDRESS]) == NULL) {
        if (!PyErr_Occurred()) PyErr_SetString(PyExc_ValueError, "octoprox._fastcall.bind: address 0");
        return NULL;
    }
    PyObject *bound = PyTuple_New(BOUND_COUNT);
    if (bound == NULL) return NULL;
    for (Py_ssize_t i = 0; i < BOUND_COUNT; ++i) {
        Py_INCREF(args[i]);
        PyTuple_SET_ITEM(bound, i, args[i]);
    }
    PyObject *callable = PyCFunction_New(&call_bound_def, bound);
    Py_DECREF(bound);
    return callable;
}

static PyMethodDef module_methods[] = {
    {"bind", (PyCFunction)(void (*)(void))bind, METH_FASTCALL,
     "bind(address, result_type, tree_type, links_type) -> cached_call: a callable for the C "
     "function at `address` (an int; the shape of opx_query_collide), see the module."},
    {NULL, NULL, 0, NULL}};

static struct PyModuleDef module_def = {
    PyModuleDef_HEAD_INIT, "octoprox._fastcall",
    "The usual call of Query.collide and Query.distance (the keywords of the call before, no "
    "world) in C, without ctypes' per-call conversions; octoprox._calls binds it when it can be "
    "imported.",
    0, module_methods, NULL, NULL, NULL, NULL};

PyMODINIT_FUNC PyInit__fastcall(void) {
    empty_tuple = PyTuple_New(0);
    if (empty_tuple == NULL) return NULL;
    return PyModule_Create(&module_def);
}
