#include "gd_call.h"

#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

const char vg_agent_class[] = "VerveAgent";
const char vg_brain_class[] = "VerveBrain";
const char vg_batch_class[] = "VerveBatch";
const char vg_recording_class[] = "VerveRecording";

int vg_begin_class(vg_call* c, const char* class_name, char* last_error, const char* method, int argc,
                   godot_variant** argv, int min_args, int max_args) {
    c->class_name = class_name;
    c->last_error = last_error;
    c->self = NULL;
    c->method = method;
    c->argc = argc;
    c->argv = argv;
    if (last_error) last_error[0] = '\0';
    if (!last_error) return vg_fail(c, "no %s instance (was the script attached to another object?)", class_name);
    if (argc < min_args || argc > max_args) {
        if (min_args == max_args) return vg_fail(c, "takes %d arguments (got %d)", min_args, argc);
        return vg_fail(c, "takes %d to %d arguments (got %d)", min_args, max_args, argc);
    }
    return 1;
}

int vg_begin(vg_call* c, vg_agent* self, const char* method, int argc, godot_variant** argv, int min_args,
             int max_args) {
    int ok = vg_begin_class(c, vg_agent_class, self ? self->last_error : NULL, method, argc, argv, min_args, max_args);
    c->self = self;
    return ok;
}

int vg_fail(vg_call* c, const char* format, ...) {
    char full[VG_ERROR_SIZE];
    char function[64];
    int prefix = snprintf(full, sizeof full, "%s.%s: ", c->class_name, c->method);
    va_list args;
    if (prefix < 0 || (size_t)prefix >= sizeof full) prefix = 0;
    va_start(args, format);
    vsnprintf(full + prefix, sizeof full - (size_t)prefix, format, args);
    va_end(args);
    if (c->last_error) memcpy(c->last_error, full, sizeof full);
    snprintf(function, sizeof function, "%s.%s", c->class_name, c->method);
    vg_print_error(function, full + prefix); /* Godot prints "ERROR: <function>: <message>" */
    return 0;
}

int vg_check(vg_call* c, verve_result r) {
    if (r == VERVE_OK) return 1;
    return vg_fail(c, "%s [%s]", verve_last_error(), verve_result_name(r));
}

int vg_agent_handle(vg_call* c, verve_agent** out) {
    *out = c->self->handle;
    if (*out) return 1;
    return vg_fail(c, "this VerveAgent has no agent: call create(), load() or load_bytes() first "
                      "(or it was closed)");
}

const godot_variant* vg_arg(const vg_call* c, int i) {
    return i < c->argc ? c->argv[i] : NULL;
}

float vg_to_float(double d) {
    if (d > FLT_MAX) return (float)HUGE_VAL;
    if (d < -FLT_MAX) return (float)-HUGE_VAL;
    return (float)d;
}

/* int or float variant into *out; 0 for any other type. */
static int vg_number(const godot_variant* v, double* out) {
    switch (vg_core->godot_variant_get_type(v)) {
    case GODOT_VARIANT_TYPE_INT: *out = (double)vg_core->godot_variant_as_int(v); return 1;
    case GODOT_VARIANT_TYPE_REAL: *out = vg_core->godot_variant_as_real(v); return 1;
    default: return 0;
    }
}

int vg_arg_float(vg_call* c, int i, const char* name, float* out) {
    double d = 0.0;
    if (!vg_number(c->argv[i], &d)) return vg_fail(c, "%s must be a number (got %s)", name, vg_type_name(c->argv[i]));
    *out = vg_to_float(d);
    return 1;
}

int vg_arg_bool(vg_call* c, int i, const char* name, int* out) {
    if (!vg_arg_type(c, i, name, GODOT_VARIANT_TYPE_BOOL)) return 0;
    *out = vg_core->godot_variant_as_bool(c->argv[i]) ? 1 : 0;
    return 1;
}

int vg_arg_type(vg_call* c, int i, const char* name, godot_variant_type type) {
    const char* expected;
    if (vg_core->godot_variant_get_type(c->argv[i]) == type) return 1;
    expected = type == GODOT_VARIANT_TYPE_STRING ? "a String"
             : type == GODOT_VARIANT_TYPE_DICTIONARY ? "a Dictionary"
             : type == GODOT_VARIANT_TYPE_ARRAY ? "an Array"
             : type == GODOT_VARIANT_TYPE_POOL_BYTE_ARRAY ? "a PoolByteArray"
             : type == GODOT_VARIANT_TYPE_BOOL ? "a bool"
             : type == GODOT_VARIANT_TYPE_INT ? "an int" : "of another type";
    return vg_fail(c, "%s must be %s (got %s)", name, expected, vg_type_name(c->argv[i]));
}

/* Reads element i of a list into out; 0 after reporting a wrong element. */
typedef int (*vg_element_fn)(vg_call* c, const godot_variant* element, const char* name, uint32_t i, void* out);

static int vg_read_list(vg_call* c, const godot_variant* v, const char* name, godot_variant_type pool_type,
                        uint32_t max, uint32_t* n, vg_element_fn read, void* out) {
    godot_variant_type t = vg_core->godot_variant_get_type(v);
    godot_array array;
    godot_int size, i;
    int ok = 1;
    *n = 0;
    if (t == GODOT_VARIANT_TYPE_NIL) return 1;
    if (t != pool_type && t != GODOT_VARIANT_TYPE_ARRAY)
        return vg_fail(c, "%s must be a %s or an Array (got %s)", name,
                       pool_type == GODOT_VARIANT_TYPE_POOL_INT_ARRAY ? "PoolIntArray" : "PoolRealArray",
                       vg_type_name(v));
    /* Pool arrays convert to an Array of variants: one path for both kinds of list. */
    array = vg_core->godot_variant_as_array(v);
    size = vg_core->godot_array_size(&array);
    if ((uint64_t)size > max) ok = vg_fail(c, "%s has %d values; an agent has at most %u", name, (int)size, max);
    for (i = 0; ok && i < size; ++i)
        ok = read(c, vg_core->godot_array_operator_index_const(&array, i), name, (uint32_t)i, out);
    vg_core->godot_array_destroy(&array);
    if (ok) *n = (uint32_t)size;
    return ok;
}

static int vg_int_element(vg_call* c, const godot_variant* e, const char* name, uint32_t i, void* out) {
    int64_t v;
    if (vg_core->godot_variant_get_type(e) != GODOT_VARIANT_TYPE_INT)
        return vg_fail(c, "%s[%u] must be an int (got %s)", name, i, vg_type_name(e));
    v = vg_core->godot_variant_as_int(e);
    if (v < INT32_MIN || v > INT32_MAX) return vg_fail(c, "%s[%u] is out of range", name, i);
    ((int32_t*)out)[i] = (int32_t)v;
    return 1;
}

static int vg_float_element(vg_call* c, const godot_variant* e, const char* name, uint32_t i, void* out) {
    double d = 0.0;
    if (!vg_number(e, &d)) return vg_fail(c, "%s[%u] must be a number (got %s)", name, i, vg_type_name(e));
    ((float*)out)[i] = vg_to_float(d);
    return 1;
}

int vg_read_ints(vg_call* c, const godot_variant* v, const char* name, int32_t* out, uint32_t max, uint32_t* n) {
    return vg_read_list(c, v, name, GODOT_VARIANT_TYPE_POOL_INT_ARRAY, max, n, vg_int_element, out);
}

int vg_read_floats(vg_call* c, const godot_variant* v, const char* name, float* out, uint32_t max, uint32_t* n) {
    return vg_read_list(c, v, name, GODOT_VARIANT_TYPE_POOL_REAL_ARRAY, max, n, vg_float_element, out);
}

/* v's object when it is a live one, else NULL. */
static godot_object* vg_live_object(const godot_variant* v) {
    godot_object* object;
    if (!vg_core11 || vg_core->godot_variant_get_type(v) != GODOT_VARIANT_TYPE_OBJECT) return NULL;
    object = vg_core->godot_variant_as_object(v);
    /* A variant may still point at a freed Node: the object database is asked before it is touched. */
    return object && vg_core11->godot_is_instance_valid(object) ? object : NULL;
}

void* vg_instance_of(const godot_variant* v, const char* class_tag) {
    godot_object* object = vg_live_object(v);
    if (!object || !vg_ns11 || vg_ns11->godot_nativescript_get_type_tag(object) != (const void*)class_tag) return NULL;
    return vg_ns->godot_nativescript_get_userdata(object);
}

const char* vg_describe(const godot_variant* v) {
    godot_object* object = vg_live_object(v);
    const void* tag;
    if (vg_core->godot_variant_get_type(v) != GODOT_VARIANT_TYPE_OBJECT) return vg_type_name(v);
    if (!object) return vg_core->godot_variant_as_object(v) ? "a freed object" : "null";
    tag = vg_ns11 ? vg_ns11->godot_nativescript_get_type_tag(object) : NULL;
    if (tag == (const void*)vg_agent_class) return "a VerveAgent"; /* not asked for: it would have matched */
    if (tag == (const void*)vg_brain_class) return "a VerveBrain";
    if (tag == (const void*)vg_batch_class) return "a VerveBatch";
    if (tag == (const void*)vg_recording_class) return "a VerveRecording";
    return "an object of another class or library";
}

int vg_with_path(vg_call* c, int i, vg_path_fn use, void* context) {
    godot_char_string path;
    int ok;
    if (!vg_arg_type(c, i, "path", GODOT_VARIANT_TYPE_STRING)) return 0;
    path = vg_utf8(c->argv[i], 1);
    ok = vg_check(c, use(vg_core->godot_char_string_get_data(&path), context));
    vg_core->godot_char_string_destroy(&path);
    return ok;
}

int vg_with_bytes(vg_call* c, int i, vg_bytes_fn use, void* context) {
    godot_pool_byte_array bytes;
    godot_pool_byte_array_read_access* read;
    int ok;
    if (!vg_arg_type(c, i, "data", GODOT_VARIANT_TYPE_POOL_BYTE_ARRAY)) return 0;
    bytes = vg_core->godot_variant_as_pool_byte_array(c->argv[i]);
    read = vg_core->godot_pool_byte_array_read(&bytes);
    ok = vg_check(c, use(vg_core->godot_pool_byte_array_read_access_ptr(read),
                         (size_t)vg_core->godot_pool_byte_array_size(&bytes), context));
    vg_core->godot_pool_byte_array_read_access_destroy(read);
    vg_core->godot_pool_byte_array_destroy(&bytes);
    return ok;
}

godot_variant vg_save_to_bytes(vg_call* c, vg_save_memory_fn save, const void* object) {
    size_t size = 0;
    godot_pool_byte_array bytes;
    godot_pool_byte_array_write_access* write;
    uint8_t* buffer;
    godot_variant out;
    int ok;
    if (!vg_check(c, save(object, NULL, &size))) return vg_variant_nil();
    if (size > (size_t)INT32_MAX) {
        vg_fail(c, "the save needs %lu bytes, more than a PoolByteArray holds", (unsigned long)size);
        return vg_variant_nil();
    }
    vg_core->godot_pool_byte_array_new(&bytes);
    vg_core->godot_pool_byte_array_resize(&bytes, (godot_int)size);
    write = vg_core->godot_pool_byte_array_write(&bytes);
    buffer = vg_core->godot_pool_byte_array_write_access_ptr(write);
    /* A PoolByteArray that could not grow keeps its size (and an empty one has no buffer): the
     * second call must not run, since a NULL buffer would make it a size query (issue 32). */
    if (vg_core->godot_pool_byte_array_size(&bytes) != (godot_int)size || buffer == NULL) {
        ok = vg_fail(c, "out of memory: a PoolByteArray of %lu bytes could not be made [%s]", (unsigned long)size,
                     verve_result_name(VERVE_ERROR_OUT_OF_MEMORY));
    } else {
        ok = vg_check(c, save(object, buffer, &size));
    }
    vg_core->godot_pool_byte_array_write_access_destroy(write);
    if (ok) vg_core->godot_pool_byte_array_resize(&bytes, (godot_int)size);
    if (ok) vg_core->godot_variant_new_pool_byte_array(&out, &bytes);
    else out = vg_variant_nil();
    vg_core->godot_pool_byte_array_destroy(&bytes);
    return out;
}

float* vg_reals_open(godot_pool_real_array* values, godot_pool_real_array_write_access** write, uint32_t n) {
    vg_core->godot_pool_real_array_new(values);
    vg_core->godot_pool_real_array_resize(values, (godot_int)n);
    *write = vg_core->godot_pool_real_array_write(values);
    return vg_core->godot_pool_real_array_write_access_ptr(*write);
}

godot_variant vg_reals_close(godot_pool_real_array* values, godot_pool_real_array_write_access* write, int ok) {
    godot_variant out;
    vg_core->godot_pool_real_array_write_access_destroy(write);
    if (ok) vg_core->godot_variant_new_pool_real_array(&out, values);
    else out = vg_variant_nil();
    vg_core->godot_pool_real_array_destroy(values);
    return out;
}

int vg_string_is(const godot_variant* v, const char* text) {
    godot_char_string s;
    int same;
    if (!v || vg_core->godot_variant_get_type(v) != GODOT_VARIANT_TYPE_STRING) return 0;
    s = vg_utf8(v, 0);
    same = strcmp(vg_core->godot_char_string_get_data(&s), text) == 0;
    vg_core->godot_char_string_destroy(&s);
    return same;
}

int vg_dict_fields(vg_call* c, const godot_dictionary* dict, const char* what, const void* table, size_t stride,
                   int count, const godot_variant** values) {
    godot_array keys = vg_core->godot_dictionary_keys(dict);
    godot_int k, n = vg_core->godot_array_size(&keys);
    int ok = 1, j;
    for (j = 0; j < count; ++j) values[j] = NULL;
    for (k = 0; ok && k < n; ++k) {
        const godot_variant* key = vg_core->godot_array_operator_index_const(&keys, k);
        for (j = 0; j < count; ++j)
            if (vg_string_is(key, *(const char* const*)((const char*)table + (size_t)j * stride))) break;
        if (j < count) {
            values[j] = vg_core->godot_dictionary_operator_index_const(dict, key);
        } else {
            godot_char_string name = vg_utf8(key, 0);
            ok = vg_fail(c, "unknown %s '%s'", what, vg_core->godot_char_string_get_data(&name));
            vg_core->godot_char_string_destroy(&name);
        }
    }
    vg_core->godot_array_destroy(&keys);
    return ok;
}
