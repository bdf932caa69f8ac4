/* gd_call.h - one call from GDScript into a method of VerveAgent, VerveBrain, VerveBatch or
 * VerveRecording: its arguments, read and checked, and its error, printed as a Godot error and kept
 * for the instance's get_last_error(). Every reader returns 0 after reporting what was wrong, so a
 * method can stop at the first failure. */
#ifndef VERVE_GD_CALL_H
#define VERVE_GD_CALL_H

#include <stddef.h>
#include <stdint.h>

#include <verve_c.h>

#include "gd_api.h"

#define VG_ERROR_SIZE 512

/* The class names. Their addresses are also the classes' NativeScript type tags: unique to this
 * library, so an object of a same-named class from another library is told apart. */
extern const char vg_agent_class[]; /* "VerveAgent" */
extern const char vg_brain_class[]; /* "VerveBrain" */
extern const char vg_batch_class[]; /* "VerveBatch" */
extern const char vg_recording_class[]; /* "VerveRecording" */

typedef struct vg_agent {
    verve_agent* handle;            /* NULL before create()/load() and after close() */
    char last_error[VG_ERROR_SIZE]; /* "" after a call that succeeded */
} vg_agent;

typedef struct vg_call {
    const char* class_name; /* the errors' prefix */
    char* last_error;       /* the instance's, NULL when there is no instance */
    vg_agent* self;         /* VerveAgent methods only */
    const char* method;
    int argc;
    godot_variant** argv;
} vg_call;

/* Starts a call on an instance of class_name whose last error is last_error (NULL: the script is
 * on an object without our instance data): clears the error and checks the argument count. */
int vg_begin_class(vg_call* c, const char* class_name, char* last_error, const char* method, int argc,
                   godot_variant** argv, int min_args, int max_args);
/* vg_begin_class for a VerveAgent method. */
int vg_begin(vg_call* c, vg_agent* self, const char* method, int argc, godot_variant** argv, int min_args,
             int max_args);
/* Reports "<class>.<method>: <message>". Returns 0. */
int vg_fail(vg_call* c, const char* format, ...);
/* Reports the library's message when r is not VERVE_OK; returns r == VERVE_OK. */
int vg_check(vg_call* c, verve_result r);
/* The agent, or 0 with an error when there is none (never created, closed or a failed load). */
int vg_agent_handle(vg_call* c, verve_agent** out);

/* Argument i, when present (i < argc), else NULL. */
const godot_variant* vg_arg(const vg_call* c, int i);
int vg_arg_float(vg_call* c, int i, const char* name, float* out);   /* int or float */
int vg_arg_bool(vg_call* c, int i, const char* name, int* out);
int vg_arg_type(vg_call* c, int i, const char* name, godot_variant_type type);

/* A PoolIntArray, an Array of ints or null (no values) into out[max]. */
int vg_read_ints(vg_call* c, const godot_variant* v, const char* name, int32_t* out, uint32_t max, uint32_t* n);
/* A PoolRealArray, an Array of numbers or null (no values) into out[max]. */
int vg_read_floats(vg_call* c, const godot_variant* v, const char* name, float* out, uint32_t max, uint32_t* n);

/* The instance data of v when v is an object of this library's class `class_tag` (one of the
 * vg_*_class names), else NULL: null, a non-object, a freed object, an object of another class or
 * of another library's class of the same name. Type-safe by NativeScript 1.1's type tags. */
void* vg_instance_of(const godot_variant* v, const char* class_tag);
/* What v is, for an error: vg_type_name, or for an object "a freed object" or our class's name. */
const char* vg_describe(const godot_variant* v);

/* Argument i, a path String (res:// and user:// made file-system paths), handed to use(path,
 * context); the library's answer checked (vg_check). For loads and saves to files. */
typedef verve_result (*vg_path_fn)(const char* path, void* context);
int vg_with_path(vg_call* c, int i, vg_path_fn use, void* context);
/* Argument i, a PoolByteArray, handed to use(data, size, context) and checked. For loads from memory. */
typedef verve_result (*vg_bytes_fn)(const void* data, size_t size, void* context);
int vg_with_bytes(vg_call* c, int i, vg_bytes_fn use, void* context);

/* A save to memory (verve_agent_save_memory and its kin, the object cast away) as a PoolByteArray
 * variant, by the two-call pattern; null after reporting an error. */
typedef verve_result (*vg_save_memory_fn)(const void* object, void* buffer, size_t* size);
godot_variant vg_save_to_bytes(vg_call* c, vg_save_memory_fn save, const void* object);
/* A PoolRealArray of n floats for a C call to fill: open it, let the call write through the
 * pointer, then close it into a variant (nil when the call failed). */
float* vg_reals_open(godot_pool_real_array* values, godot_pool_real_array_write_access** write, uint32_t n);
godot_variant vg_reals_close(godot_pool_real_array* values, godot_pool_real_array_write_access* write, int ok);

/* Finds each of `count` names in dict: values[i] is its value, NULL when absent (valid while dict
 * lives). The names are the first member (const char*) of `count` table entries `stride` bytes
 * apart. A key that is not one of them is an error: a typo must not pass silently. */
int vg_dict_fields(vg_call* c, const godot_dictionary* dict, const char* what, const void* table, size_t stride,
                   int count, const godot_variant** values);
/* Whether v is a String equal to text. */
int vg_string_is(const godot_variant* v, const char* text);

/* A finite double as a float: beyond float range it becomes an infinity, which the library refuses. */
float vg_to_float(double d);

#endif
