/*
 * octoprox._fastcall: Query.collide and Query.distance as methods written in
 * C for their usual call, so that a tiny query from Python costs little more
 * than its C call.
 *
 * The module does not link liboctoprox: octoprox._calls hands it the
 * address of a C function the package's ctypes library resolved, with the
 * shape of opx_query_collide and opx_query_distance:
 *     opx_status f(opx_query *, const opx_octree *, const opx_linkset *,
 *                  const request *, result *)
 * and the Python method the C method stands for (the fallback).  The call
 * `query.m(tree, links, **keywords)` runs here when query, tree and links
 * are of the bound types and every keyword is one of the request's (or
 * world=None), and
 *   - without keywords: with the default request bound here;
 *   - with keywords: with the request of the query's cache (the attribute
 *     named at binding, an octoprox._requests.RequestCache) when the
 *     keywords' values, defaults filled in, equal its `key`; the request at
 *     its `address` is then used.
 * It makes a new result of the bound ctypes struct type (struct_size set),
 * calls the function on the handles' `_address` ints (0 for a closed
 * handle, which the library refuses) with the GIL released, as ctypes does,
 * sets the query's result attribute (when one is bound) and returns the
 * result.  Every other call, and a failing status, is the fallback's: it
 * builds the request, fills the cache, and raises what it raises.
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <structmember.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

typedef int32_t (*query_function)(void *query, const void *tree, const void *links,
                                  const void *request, void *result);

enum { MAX_KEY = 16 }; /* keywords a request key may hold */

typedef struct {
    PyObject_HEAD
    vectorcallfunc vectorcall;
    PyObject *fallback;      /* the Python method */
    query_function function; /* opx_query_collide or opx_query_distance */
    void *request;           /* the default request; the Python side keeps it alive */
    PyObject *result_type, *query_type, *tree_type, *links_type;
    PyObject *result_name;   /* the query's attribute set to the result, or NULL */
    PyObject *cache_name;    /* the query's RequestCache attribute */
    PyObject *names;         /* the key's keywords, in order (interned str) */
    PyObject *defaults;      /* their default values */
    PyObject *doc;           /* fallback's, for readers that skip method_getattro (pydoc) */
} fast_method;

static PyObject *empty_tuple, *address_name, *key_name, *request_address_name, *world_name;

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

/* The attribute `name` of `object` as a pointer (an int): 1, or 0. */
static int attribute_pointer(PyObject *object, PyObject *name, void **out) {
    PyObject *value = PyObject_GetAttr(object, name);
    if (value == NULL) {
        PyErr_Clear();
        return 0;
    }
    const int ok = int_pointer(value, out);
    Py_DECREF(value);
    return ok;
}

/* 1 when `cached` is a tuple equal to the `count` values of `key`, as
 * Python's == compares tuples; 0 otherwise, also when a comparison raises
 * (an array among the values). */
static int key_matches(PyObject *cached, PyObject *const *key, Py_ssize_t count) {
    int same = PyTuple_Check(cached) && PyTuple_GET_SIZE(cached) == count;
    for (Py_ssize_t i = 0; same && i < count; ++i) {
        PyObject *item = PyTuple_GET_ITEM(cached, i);
        if (item == key[i]) continue;  /* the usual case: the same objects */
        same = PyObject_RichCompareBool(item, key[i], Py_EQ);
        if (same < 0) {
            PyErr_Clear();
            same = 0;
        }
    }
    return same;
}

/* The index of keyword `name` among `names`, -1 when it is none of them. */
static Py_ssize_t keyword_index(PyObject *names, PyObject *name) {
    const Py_ssize_t count = PyTuple_GET_SIZE(names);
    for (Py_ssize_t i = 0; i < count; ++i)  /* call sites pass interned names */
        if (PyTuple_GET_ITEM(names, i) == name) return i;
    for (Py_ssize_t i = 0; i < count; ++i)
        if (PyUnicode_Compare(PyTuple_GET_ITEM(names, i), name) == 0) return i;
    PyErr_Clear();
    return -1;
}

/* The request for the call's keywords: the default one without keywords,
 * else the cache's last when its key equals theirs; NULL when the
 * fallback must serve the call. */
static void *request_for(fast_method *method, PyObject *query, PyObject *const *values,
                         PyObject *kwnames) {
    const Py_ssize_t given = kwnames == NULL ? 0 : PyTuple_GET_SIZE(kwnames);
    if (given == 0) return method->request;
    const Py_ssize_t count = PyTuple_GET_SIZE(method->names);
    PyObject *key[MAX_KEY];
    for (Py_ssize_t i = 0; i < count; ++i) key[i] = PyTuple_GET_ITEM(method->defaults, i);
    for (Py_ssize_t i = 0; i < given; ++i) {
        PyObject *name = PyTuple_GET_ITEM(kwnames, i);
        const Py_ssize_t at = keyword_index(method->names, name);
        if (at >= 0)
            key[at] = values[i];
        else if (!(values[i] == Py_None && PyUnicode_Compare(name, world_name) == 0))
            return NULL;  /* a world, or no keyword of the method */
    }
    PyObject *cache = PyObject_GetAttr(query, method->cache_name);
    if (cache == NULL) {
        PyErr_Clear();
        return NULL;
    }
    void *request = NULL;
    PyObject *cached_key = PyObject_GetAttr(cache, key_name);
    if (cached_key == NULL)
        PyErr_Clear();
    else if (!key_matches(cached_key, key, count) || !attribute_pointer(cache, request_address_name, &request))
        request = NULL;
    Py_XDECREF(cached_key);
    Py_DECREF(cache);
    return request;
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

/* The call (query, tree, links, keyword values...): its result, NULL with
 * an exception, or None: the fallback serves it. */
static PyObject *method_fast_call(fast_method *method, PyObject *const *args, PyObject *kwnames) {
    void *query, *tree, *links, *request;
    if (!PyObject_TypeCheck(args[0], (PyTypeObject *)method->query_type) ||
        !PyObject_TypeCheck(args[1], (PyTypeObject *)method->tree_type) ||
        !PyObject_TypeCheck(args[2], (PyTypeObject *)method->links_type) ||
        !attribute_pointer(args[0], address_name, &query) ||
        !attribute_pointer(args[1], address_name, &tree) ||
        !attribute_pointer(args[2], address_name, &links) ||
        (request = request_for(method, args[0], args + 3, kwnames)) == NULL)
        Py_RETURN_NONE;
    Py_buffer view;
    PyObject *result = new_result(method->result_type, &view);
    if (result == NULL) return NULL;
    int32_t status;
    Py_BEGIN_ALLOW_THREADS
    status = method->function(query, tree, links, request, view.buf);
    Py_END_ALLOW_THREADS
    PyBuffer_Release(&view);
    if (status != 0) {
        Py_DECREF(result);
        Py_RETURN_NONE;
    }
    if (method->result_name != NULL && PyObject_SetAttr(args[0], method->result_name, result) != 0) {
        Py_DECREF(result);
        return NULL;
    }
    return result;
}

static PyObject *method_vectorcall(PyObject *callable, PyObject *const *args, size_t nargsf,
                                   PyObject *kwnames) {
    fast_method *method = (fast_method *)callable;
    if (PyVectorcall_NARGS(nargsf) == 3) {
        PyObject *result = method_fast_call(method, args, kwnames);
        if (result != Py_None) return result;  /* a result, or NULL: an exception */
        Py_DECREF(result);
    }
    return PyObject_Vectorcall(method->fallback, args, nargsf, kwnames);
}

/* Bound to an instance as a Python function is (the type has
 * Py_TPFLAGS_METHOD_DESCRIPTOR, so `query.m(...)` makes no bound method). */
static PyObject *method_get(PyObject *self, PyObject *instance, PyObject *owner) {
    (void)owner;
    if (instance == NULL || instance == Py_None) return Py_NewRef(self);
    return PyMethod_New(self, instance);
}

/* Every attribute but __class__ is the Python method's (__doc__, __name__,
 * __annotations__, __kwdefaults__); __wrapped__ is the method itself. */
static PyObject *method_getattro(PyObject *self, PyObject *name) {
    fast_method *method = (fast_method *)self;
    if (PyUnicode_Check(name) && PyUnicode_CompareWithASCIIString(name, "__wrapped__") == 0)
        return Py_NewRef(method->fallback);
    if (PyUnicode_Check(name) && PyUnicode_CompareWithASCIIString(name, "__class__") != 0) {
        PyObject *value = PyObject_GetAttr(method->fallback, name);
        if (value != NULL || !PyErr_ExceptionMatches(PyExc_AttributeError)) return value;
        PyErr_Clear();
    }
    return PyObject_GenericGetAttr(self, name);
}

static PyMemberDef method_members[] = {
    {"__doc__", T_OBJECT, offsetof(fast_method, doc), READONLY, NULL}, {NULL, 0, 0, 0, NULL}};

static PyObject *method_repr(PyObject *self) {
    return PyUnicode_FromFormat("<compiled %R>", ((fast_method *)self)->fallback);
}

static int method_traverse(PyObject *self, visitproc visit, void *arg) {
    fast_method *method = (fast_method *)self;
    Py_VISIT(method->fallback);
    Py_VISIT(method->result_type);
    Py_VISIT(method->query_type);
    Py_VISIT(method->tree_type);
    Py_VISIT(method->links_type);
    Py_VISIT(method->defaults);
    Py_VISIT(method->doc);
    return 0;
}

static void method_dealloc(PyObject *self) {
    fast_method *method = (fast_method *)self;
    PyObject_GC_UnTrack(self);
    Py_XDECREF(method->fallback);
    Py_XDECREF(method->result_type);
    Py_XDECREF(method->query_type);
    Py_XDECREF(method->tree_type);
    Py_XDECREF(method->links_type);
    Py_XDECREF(method->result_name);
    Py_XDECREF(method->cache_name);
    Py_XDECREF(method->names);
    Py_XDECREF(method->defaults);
    Py_XDECREF(method->doc);
    PyObject_GC_Del(self);
}

static PyTypeObject fast_method_type = {
    PyVarObject_HEAD_INIT(NULL, 0)
    .tp_name = "octoprox._fastcall.method",
    .tp_basicsize = sizeof(fast_method),
    .tp_flags = Py_TPFLAGS_DEFAULT | Py_TPFLAGS_HAVE_GC | Py_TPFLAGS_HAVE_VECTORCALL |
                Py_TPFLAGS_METHOD_DESCRIPTOR,
    .tp_vectorcall_offset = offsetof(fast_method, vectorcall),
    .tp_call = PyVectorcall_Call,
    .tp_descr_get = method_get,
    .tp_getattro = method_getattro,
    .tp_members = method_members,
    .tp_repr = method_repr,
    .tp_traverse = method_traverse,
    .tp_dealloc = method_dealloc};

enum { BIND_FALLBACK, BIND_ADDRESS, BIND_REQUEST, BIND_RESULT_TYPE, BIND_QUERY_TYPE,
       BIND_TREE_TYPE, BIND_LINKS_TYPE, BIND_RESULT_NAME, BIND_CACHE_NAME, BIND_NAMES,
       BIND_DEFAULTS, BIND_COUNT };

static const char method_usage[] =
    "method(fallback, address: int, request_address: int, result_type, query_type, tree_type, "
    "links_type, result_attribute: str | None, cache_attribute: str, names: tuple[str], "
    "defaults: tuple)";

/* 1 when names is a tuple of at most MAX_KEY str and defaults a tuple as long. */
static int key_shape(PyObject *names, PyObject *defaults) {
    if (!PyTuple_CheckExact(names) || !PyTuple_CheckExact(defaults) ||
        PyTuple_GET_SIZE(names) != PyTuple_GET_SIZE(defaults) ||
        PyTuple_GET_SIZE(names) > MAX_KEY || PyTuple_GET_SIZE(names) == 0)
        return 0;
    for (Py_ssize_t i = 0; i < PyTuple_GET_SIZE(names); ++i)
        if (!PyUnicode_CheckExact(PyTuple_GET_ITEM(names, i))) return 0;
    return 1;
}

/* `names` with each name interned, as call sites' keyword names are. */
static PyObject *interned_names(PyObject *names) {
    PyObject *out = PyTuple_New(PyTuple_GET_SIZE(names));
    for (Py_ssize_t i = 0; out != NULL && i < PyTuple_GET_SIZE(names); ++i) {
        PyObject *name = Py_NewRef(PyTuple_GET_ITEM(names, i));
        PyUnicode_InternInPlace(&name);
        PyTuple_SET_ITEM(out, i, name);
    }
    return out;
}

static PyObject *interned_or_null(PyObject *name) {
    if (name == Py_None) return NULL;
    PyObject *out = Py_NewRef(name);
    PyUnicode_InternInPlace(&out);
    return out;
}

static PyObject *method(PyObject *module, PyObject *const *args, Py_ssize_t nargs) {
    (void)module;
    const int shaped = nargs == BIND_COUNT && PyCallable_Check(args[BIND_FALLBACK]) &&
                       PyLong_Check(args[BIND_ADDRESS]) && PyLong_Check(args[BIND_REQUEST]) &&
                       PyType_Check(args[BIND_RESULT_TYPE]) && PyType_Check(args[BIND_QUERY_TYPE]) &&
                       PyType_Check(args[BIND_TREE_TYPE]) && PyType_Check(args[BIND_LINKS_TYPE]) &&
                       (args[BIND_RESULT_NAME] == Py_None || PyUnicode_Check(args[BIND_RESULT_NAME])) &&
                       PyUnicode_Check(args[BIND_CACHE_NAME]) &&
                       key_shape(args[BIND_NAMES], args[BIND_DEFAULTS]);
    if (!shaped) {
        PyErr_SetString(PyExc_TypeError, method_usage);
        return NULL;
    }
    void *function = PyLong_AsVoidPtr(args[BIND_ADDRESS]);
    void *request = function ? PyLong_AsVoidPtr(args[BIND_REQUEST]) : NULL;
    if (function == NULL || request == NULL) {
        if (!PyErr_Occurred()) PyErr_SetString(PyExc_ValueError, "octoprox._fastcall.method: address 0");
        return NULL;
    }
    PyObject *names = interned_names(args[BIND_NAMES]);
    if (names == NULL) return NULL;
    fast_method *out = PyObject_GC_New(fast_method, &fast_method_type);
    if (out == NULL) {
        Py_DECREF(names);
        return NULL;
    }
    out->vectorcall = method_vectorcall;
    out->function = (query_function)function;
    out->request = request;
    out->fallback = Py_NewRef(args[BIND_FALLBACK]);
    out->result_type = Py_NewRef(args[BIND_RESULT_TYPE]);
    out->query_type = Py_NewRef(args[BIND_QUERY_TYPE]);
    out->tree_type = Py_NewRef(args[BIND_TREE_TYPE]);
    out->links_type = Py_NewRef(args[BIND_LINKS_TYPE]);
    out->result_name = interned_or_null(args[BIND_RESULT_NAME]);
    out->cache_name = interned_or_null(args[BIND_CACHE_NAME]);
    out->names = names;
    out->defaults = Py_NewRef(args[BIND_DEFAULTS]);
    out->doc = PyObject_GetAttrString(args[BIND_FALLBACK], "__doc__");
    if (out->doc == NULL) {
        PyErr_Clear();
        out->doc = Py_NewRef(Py_None);
    }
    PyObject_GC_Track(out);
    return (PyObject *)out;
}

static PyMethodDef module_methods[] = {
    {"method", (PyCFunction)(void (*)(void))method, METH_FASTCALL,
     "method(fallback, address, request_address, result_type, query_type, tree_type, "
     "links_type, result_attribute, cache_attribute, names, defaults) -> a query method whose "
     "usual call runs the C function at `address` (see the module); every other call, and a "
     "failing status, is fallback's."},
    {NULL, NULL, 0, NULL}};

static struct PyModuleDef module_def = {
    PyModuleDef_HEAD_INIT, "octoprox._fastcall",
    "Query.collide and Query.distance in C for their usual call (no world, keywords whose "
    "request the query already holds), without ctypes' per-call conversions; octoprox._calls "
    "binds them when the module can be imported.",
    0, module_methods, NULL, NULL, NULL, NULL};

PyMODINIT_FUNC PyInit__fastcall(void) {
    empty_tuple = PyTuple_New(0);
    address_name = PyUnicode_InternFromString("_address");
    key_name = PyUnicode_InternFromString("key");
    request_address_name = PyUnicode_InternFromString("address");
    world_name = PyUnicode_InternFromString("world");
    if (empty_tuple == NULL || address_name == NULL || key_name == NULL ||
        request_address_name == NULL || world_name == NULL ||
        PyType_Ready(&fast_method_type) != 0)
        return NULL;
    return PyModule_Create(&module_def);
}
