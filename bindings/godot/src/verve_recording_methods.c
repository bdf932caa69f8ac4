/* verve_recording_methods.c - what each VerveRecording method does, as verve_agent_methods.c does
 * for VerveAgent: a failure prints a Godot error, returns false, -1 or null and changes nothing
 * (a refused entry is not recorded). Also VerveAgent.replay(), which takes a VerveRecording. */
#include "verve_recording_methods.h"

#define VG_METHOD(name)                                                                                         \
    godot_variant vg_recording_##name(godot_object* object, void* method_data, void* user_data, int argc, \
                                      godot_variant** argv)
#define VG_UNUSED (void)object, (void)method_data

void vg_recording_destroy(void* instance) {
    verve_recording_destroy(((vg_recording*)instance)->handle);
}

static int vg_begin_recording(vg_call* c, void* user_data, const char* method, int argc, godot_variant** argv,
                              int min_args, int max_args) {
    vg_recording* self = user_data;
    return vg_begin_class(c, vg_recording_class, self ? self->last_error : NULL, method, argc, argv, min_args,
                          max_args);
}

/* The recording, or 0 with an error when there is none. */
static int vg_recording_handle(vg_call* c, void* user_data, verve_recording** out) {
    *out = ((vg_recording*)user_data)->handle;
    if (*out) return 1;
    return vg_fail(c, "this VerveRecording has no recording: call create(), load() or load_bytes() first "
                      "(or it was closed)");
}

/* Replaces the recording held by self with `fresh` (the old one, if any, is destroyed). */
static void vg_adopt(vg_recording* self, verve_recording* fresh) {
    verve_recording_destroy(self->handle);
    self->handle = fresh;
}

VG_METHOD(create) {
    vg_call c;
    vg_agent* agent;
    verve_recording* fresh = NULL;
    VG_UNUSED;
    if (!vg_begin_recording(&c, user_data, "create", argc, argv, 1, 1)) return vg_variant_bool(0);
    agent = vg_instance_of(argv[0], vg_agent_class);
    if (!agent) {
        vg_fail(&c, "agent must be a VerveAgent (got %s)", vg_describe(argv[0]));
        return vg_variant_bool(0);
    }
    if (!agent->handle) {
        vg_fail(&c, "agent is a VerveAgent without an agent (never created, or closed)");
        return vg_variant_bool(0);
    }
    if (!vg_check(&c, verve_recording_create(agent->handle, &fresh))) return vg_variant_bool(0);
    vg_adopt(user_data, fresh);
    return vg_variant_bool(1);
}

VG_METHOD(add_step) {
    vg_call c;
    verve_recording* r;
    float reward = 0.0f, dt = 0.0f;
    int32_t discrete[VERVE_MAX_SENSORS];
    float continuous[VERVE_MAX_SENSORS];
    uint32_t n_discrete = 0, n_continuous = 0;
    int64_t action;
    VG_UNUSED;
    if (!vg_begin_recording(&c, user_data, "add_step", argc, argv, 5, 5) || !vg_recording_handle(&c, user_data, &r) ||
        !vg_arg_float(&c, 0, "reward", &reward) ||
        !vg_read_ints(&c, argv[1], "discrete", discrete, VERVE_MAX_SENSORS, &n_discrete) ||
        !vg_read_floats(&c, argv[2], "continuous", continuous, VERVE_MAX_SENSORS, &n_continuous) ||
        !vg_arg_float(&c, 3, "dt", &dt) || !vg_arg_type(&c, 4, "action", GODOT_VARIANT_TYPE_INT))
        return vg_variant_bool(0);
    action = vg_core->godot_variant_as_int(argv[4]);
    if (action < 0 || action > (int64_t)UINT32_MAX) {
        vg_fail(&c, "action must be 0 .. actions-1 (got %lld)", (long long)action);
        return vg_variant_bool(0);
    }
    return vg_variant_bool(vg_check(&c, verve_recording_add_step(r, reward, discrete, n_discrete, continuous,
                                                                 n_continuous, dt, (uint32_t)action)));
}

VG_METHOD(add_step_continuous) {
    vg_call c;
    verve_recording* r;
    float reward = 0.0f, dt = 0.0f;
    int32_t discrete[VERVE_MAX_DISCRETE_SENSORS];
    float continuous[VERVE_MAX_CONTINUOUS_SENSORS], values[VERVE_MAX_CONTINUOUS_ACTIONS];
    uint32_t n_discrete = 0, n_continuous = 0, n_values = 0;
    int64_t action;
    VG_UNUSED;
    if (!vg_begin_recording(&c, user_data, "add_step_continuous", argc, argv, 6, 6) ||
        !vg_recording_handle(&c, user_data, &r) || !vg_arg_float(&c, 0, "reward", &reward) ||
        !vg_read_ints(&c, argv[1], "discrete", discrete, VERVE_MAX_DISCRETE_SENSORS, &n_discrete) ||
        !vg_read_floats(&c, argv[2], "continuous", continuous, VERVE_MAX_CONTINUOUS_SENSORS, &n_continuous) ||
        !vg_arg_float(&c, 3, "dt", &dt) || !vg_arg_type(&c, 4, "action", GODOT_VARIANT_TYPE_INT) ||
        !vg_read_floats(&c, argv[5], "continuous_action", values, VERVE_MAX_CONTINUOUS_ACTIONS, &n_values))
        return vg_variant_bool(0);
    action = vg_core->godot_variant_as_int(argv[4]);
    if (action < 0 || action > (int64_t)UINT32_MAX) {
        vg_fail(&c, "action must be 0 .. actions-1 (got %lld)", (long long)action);
        return vg_variant_bool(0);
    }
    return vg_variant_bool(vg_check(&c, verve_recording_add_step_continuous(r, reward, discrete, n_discrete, continuous,
                                                                            n_continuous, dt, (uint32_t)action, values,
                                                                            n_values)));
}

VG_METHOD(add_end_episode) {
    vg_call c;
    verve_recording* r;
    float reward = 0.0f;
    VG_UNUSED;
    return vg_variant_bool(vg_begin_recording(&c, user_data, "add_end_episode", argc, argv, 1, 1) &&
                           vg_recording_handle(&c, user_data, &r) && vg_arg_float(&c, 0, "final_reward", &reward) &&
                           vg_check(&c, verve_recording_add_end_episode(r, reward)));
}

VG_METHOD(add_truncation) {
    vg_call c;
    verve_recording* r;
    float reward = 0.0f;
    VG_UNUSED;
    return vg_variant_bool(vg_begin_recording(&c, user_data, "add_truncation", argc, argv, 1, 1) &&
                           vg_recording_handle(&c, user_data, &r) && vg_arg_float(&c, 0, "reward", &reward) &&
                           vg_check(&c, verve_recording_add_truncation(r, reward)));
}

VG_METHOD(get_size) {
    vg_call c;
    verve_recording* r;
    uint64_t n = 0;
    VG_UNUSED;
    if (!vg_begin_recording(&c, user_data, "get_size", argc, argv, 0, 0) || !vg_recording_handle(&c, user_data, &r) ||
        !vg_check(&c, verve_recording_get_size(r, &n)))
        return vg_variant_int(-1);
    return vg_variant_int((int64_t)n);
}

/* The library's loads and save in vg_with_path's and vg_with_bytes's form. */
static verve_result vg_load_file(const char* path, void* out) { return verve_recording_load(path, out); }
static verve_result vg_load_memory(const void* data, size_t size, void* out) {
    return verve_recording_load_memory(data, size, out);
}
static verve_result vg_save_file(const char* path, void* recording) { return verve_recording_save(recording, path); }
static verve_result vg_save_memory(const void* recording, void* buffer, size_t* size) {
    return verve_recording_save_memory((const verve_recording*)recording, buffer, size);
}

VG_METHOD(save) {
    vg_call c;
    verve_recording* r;
    VG_UNUSED;
    return vg_variant_bool(vg_begin_recording(&c, user_data, "save", argc, argv, 1, 1) &&
                           vg_recording_handle(&c, user_data, &r) && vg_with_path(&c, 0, vg_save_file, r));
}

VG_METHOD(save_bytes) {
    vg_call c;
    verve_recording* r;
    VG_UNUSED;
    if (!vg_begin_recording(&c, user_data, "save_bytes", argc, argv, 0, 0) || !vg_recording_handle(&c, user_data, &r))
        return vg_variant_nil();
    /* vg_save_to_bytes never takes a PoolByteArray that could not grow for a size query (issue 32). */
    return vg_save_to_bytes(&c, vg_save_memory, r);
}

VG_METHOD(load) {
    vg_call c;
    verve_recording* fresh = NULL;
    int ok;
    VG_UNUSED;
    ok = vg_begin_recording(&c, user_data, "load", argc, argv, 1, 1) && vg_with_path(&c, 0, vg_load_file, &fresh);
    if (ok) vg_adopt(user_data, fresh);
    return vg_variant_bool(ok);
}

VG_METHOD(load_bytes) {
    vg_call c;
    verve_recording* fresh = NULL;
    int ok;
    VG_UNUSED;
    ok = vg_begin_recording(&c, user_data, "load_bytes", argc, argv, 1, 1) &&
         vg_with_bytes(&c, 0, vg_load_memory, &fresh);
    if (ok) vg_adopt(user_data, fresh);
    return vg_variant_bool(ok);
}

VG_METHOD(has_recording) {
    vg_call c;
    VG_UNUSED;
    return vg_variant_bool(vg_begin_recording(&c, user_data, "has_recording", argc, argv, 0, 0) &&
                           ((vg_recording*)user_data)->handle != NULL);
}

VG_METHOD(close) {
    vg_call c;
    VG_UNUSED;
    if (vg_begin_recording(&c, user_data, "close", argc, argv, 0, 0)) vg_adopt(user_data, NULL);
    return vg_variant_nil();
}

VG_METHOD(get_last_error) {
    VG_UNUSED, (void)argc, (void)argv;
    return vg_variant_string(user_data ? ((vg_recording*)user_data)->last_error : "");
}

godot_variant vg_replay(godot_object* object, void* method_data, void* user_data, int argc, godot_variant** argv) {
    vg_call c;
    verve_agent* a;
    vg_recording* recording;
    VG_UNUSED;
    if (!vg_begin(&c, user_data, "replay", argc, argv, 1, 1) || !vg_agent_handle(&c, &a)) return vg_variant_bool(0);
    recording = vg_instance_of(argv[0], vg_recording_class);
    if (!recording) {
        vg_fail(&c, "recording must be a VerveRecording (got %s)", vg_describe(argv[0]));
        return vg_variant_bool(0);
    }
    if (!recording->handle) {
        vg_fail(&c, "recording is a VerveRecording without a recording (never created or loaded, or closed)");
        return vg_variant_bool(0);
    }
    return vg_variant_bool(vg_check(&c, verve_agent_replay(a, recording->handle)));
}
