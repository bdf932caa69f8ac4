/* gd_call.h - one call from GDScript into a VerveAgent method: its arguments, read and checked,
 * and its error, printed as a Godot error and kept for VerveAgent.get_last_error(). Every reader
 * returns 0 after reporting what was wrong, so a method can stop at the first failure. */
#ifndef VERVE_GD_CALL_H
#define VERVE_GD_CALL_H

#include <stddef.h>
#include <stdint.h>

#include <verve_c.h>

#include "gd_api.h"

#define VG_ERROR_SIZE 512

typedef struct vg_agent {
    verve_agent* handle;            /* NULL before create()/load() and after close() */
    char last_error[VG_ERROR_SIZE]; /* "" after a call that succeeded */
} vg_agent;

typedef struct vg_call {
    vg_agent* self;
    const char* method;
    int argc;
    godot_variant** argv;
} vg_call;

/* Starts a call: clears the last error and checks the argument count. */
int vg_begin(vg_call* c, vg_agent* self, const char* method, int argc, godot_variant** argv, int min_args,
             int max_args);
/* Reports "VerveAgent.<method>: <message>". Returns 0. */
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
