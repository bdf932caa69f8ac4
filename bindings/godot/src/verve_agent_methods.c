/* verve_agent_methods.c - what each VerveAgent method does: read its arguments, call the C ABI,
 * turn the answer into Godot values. A failure prints a Godot error with the library's message
 * and returns false, -1 or null; it never changes the agent. */
#include "verve_agent_methods.h"

#include <stdlib.h>
#include <string.h>

#include "action_choices.h"
#include "gd_options.h"

/* sample_values refuses more points than this instead of allocating without bound. */
#define VG_MAX_SAMPLES (1u << 24)

#define VG_METHOD(name) \
    godot_variant vg_##name(godot_object* object, void* method_data, void* user_data, int argc, godot_variant** argv)
#define VG_UNUSED (void)object, (void)method_data

void vg_agent_destroy(void* instance) {
    verve_agent_destroy(((vg_agent*)instance)->handle);
}

/* Replaces the agent held by self with `fresh` (the old one, if any, is destroyed). */
static void vg_adopt(vg_agent* self, verve_agent* fresh) {
    verve_agent_destroy(self->handle);
    self->handle = fresh;
}

VG_METHOD(create) {
    vg_call c;
    verve_agent_desc d;
    verve_agent* fresh = NULL;
    VG_UNUSED;
    if (!vg_begin(&c, user_data, "create", argc, argv, 0, 1) || !vg_options_read(&c, 0, &d) ||
        !vg_check(&c, verve_agent_create(&d, &fresh)))
        return vg_variant_bool(0);
    vg_adopt(c.self, fresh);
    return vg_variant_bool(1);
}

/* The library's loads and save in vg_with_path's and vg_with_bytes's form. */
static verve_result vg_load_file(const char* path, void* out) { return verve_agent_load(path, out); }
static verve_result vg_load_memory(const void* data, size_t size, void* out) {
    return verve_agent_load_memory(data, size, out);
}
static verve_result vg_save_file(const char* path, void* agent) { return verve_agent_save(agent, path); }

VG_METHOD(load) {
    vg_call c;
    verve_agent* fresh = NULL;
    int ok;
    VG_UNUSED;
    ok = vg_begin(&c, user_data, "load", argc, argv, 1, 1) && vg_with_path(&c, 0, vg_load_file, &fresh);
    if (ok) vg_adopt(c.self, fresh);
    return vg_variant_bool(ok);
}

VG_METHOD(load_bytes) {
    vg_call c;
    verve_agent* fresh = NULL;
    int ok;
    VG_UNUSED;
    ok = vg_begin(&c, user_data, "load_bytes", argc, argv, 1, 1) && vg_with_bytes(&c, 0, vg_load_memory, &fresh);
    if (ok) vg_adopt(c.self, fresh);
    return vg_variant_bool(ok);
}

VG_METHOD(save) {
    vg_call c;
    verve_agent* a;
    VG_UNUSED;
    return vg_variant_bool(vg_begin(&c, user_data, "save", argc, argv, 1, 1) && vg_agent_handle(&c, &a) &&
                           vg_with_path(&c, 0, vg_save_file, a));
}

static verve_result vg_agent_save_memory(const void* agent, void* buffer, size_t* size) {
    return verve_agent_save_memory((const verve_agent*)agent, buffer, size);
}

VG_METHOD(save_bytes) {
    vg_call c;
    verve_agent* a;
    VG_UNUSED;
    if (!vg_begin(&c, user_data, "save_bytes", argc, argv, 0, 0) || !vg_agent_handle(&c, &a)) return vg_variant_nil();
    return vg_save_to_bytes(&c, vg_agent_save_memory, a);
}

/* Most flags in a mask, read onto the stack: the library's limit of 4096 actions, or with action
 * branches one per choice of each branch (their sum exceeds the product by at most one per branch). */
#define VG_MAX_ACTIONS (4096 + VERVE_MAX_ACTION_BRANCHES)

/* update, update_masked and update_demonstrated: argv is (reward, discrete, continuous, dt), then
 * update_masked's mask, or update_demonstrated's action and optional mask. */
enum { VG_PLAIN, VG_MASKED, VG_DEMONSTRATED };
static godot_variant vg_step(void* user_data, const char* method, int argc, godot_variant** argv, int kind) {
    vg_call c;
    verve_agent* a;
    float reward = 0.0f, dt = 0.0f;
    int32_t discrete[VERVE_MAX_SENSORS];
    float continuous[VERVE_MAX_SENSORS];
    int32_t flags[VG_MAX_ACTIONS];
    uint8_t mask[VG_MAX_ACTIONS];
    uint32_t n_discrete = 0, n_continuous = 0, n_mask = 0, action = 0, i;
    int64_t shown = 0;
    const int extra = kind == VG_PLAIN ? 0 : 1;
    const int masked = kind == VG_MASKED || (kind == VG_DEMONSTRATED && argc == 6); /* the mask's argument */
    const int mask_arg = kind == VG_MASKED ? 4 : 5;
    if (!vg_begin(&c, user_data, method, argc, argv, 4 + extra, 4 + extra + (kind == VG_DEMONSTRATED)) ||
        !vg_agent_handle(&c, &a) ||
        !vg_arg_float(&c, 0, "reward", &reward) ||
        !vg_read_ints(&c, argv[1], "discrete", discrete, VERVE_MAX_SENSORS, &n_discrete) ||
        !vg_read_floats(&c, argv[2], "continuous", continuous, VERVE_MAX_SENSORS, &n_continuous) ||
        !vg_arg_float(&c, 3, "dt", &dt) ||
        (masked && !vg_read_ints(&c, argv[mask_arg], "mask", flags, VG_MAX_ACTIONS, &n_mask)) ||
        (kind == VG_DEMONSTRATED && !vg_arg_type(&c, 4, "action", GODOT_VARIANT_TYPE_INT)))
        return kind == VG_DEMONSTRATED ? vg_variant_bool(0) : vg_variant_int(-1);
    for (i = 0; i < n_mask; ++i) {
        if (flags[i] != 0 && flags[i] != 1) {
            vg_fail(&c, "mask[%u] must be 0 or 1 (got %d)", i, (int)flags[i]);
            return kind == VG_DEMONSTRATED ? vg_variant_bool(0) : vg_variant_int(-1);
        }
        mask[i] = (uint8_t)flags[i];
    }
    if (kind == VG_DEMONSTRATED) {
        shown = vg_core->godot_variant_as_int(argv[4]);
        if (shown < 0 || shown > (int64_t)UINT32_MAX) {
            vg_fail(&c, "action must be 0 .. actions-1 (got %lld)", (long long)shown);
            return vg_variant_bool(0);
        }
        return vg_variant_bool(vg_check(&c, verve_agent_update_demonstrated(a, reward, discrete, n_discrete, continuous,
                                                                            n_continuous, dt, masked ? mask : NULL,
                                                                            masked ? n_mask : 0, (uint32_t)shown)));
    }
    if (!vg_check(&c, kind == VG_MASKED ? verve_agent_update_masked(a, reward, discrete, n_discrete, continuous,
                                                                    n_continuous, dt, mask, n_mask, &action)
                                        : verve_agent_update(a, reward, discrete, n_discrete, continuous, n_continuous,
                                                             dt, &action)))
        return vg_variant_int(-1);
    return vg_variant_int(action);
}

VG_METHOD(update) {
    VG_UNUSED;
    return vg_step(user_data, "update", argc, argv, VG_PLAIN);
}

VG_METHOD(update_masked) {
    VG_UNUSED;
    return vg_step(user_data, "update_masked", argc, argv, VG_MASKED);
}

VG_METHOD(update_demonstrated) {
    VG_UNUSED;
    return vg_step(user_data, "update_demonstrated", argc, argv, VG_DEMONSTRATED);
}

/* update_demonstrated_continuous(reward, discrete, continuous, dt, action, values [, mask]): the
 * host's continuous actions too (docs/teaching.md). */
VG_METHOD(update_demonstrated_continuous) {
    vg_call c;
    verve_agent* a;
    float reward = 0.0f, dt = 0.0f;
    int32_t discrete[VERVE_MAX_DISCRETE_SENSORS];
    float continuous[VERVE_MAX_CONTINUOUS_SENSORS], values[VERVE_MAX_CONTINUOUS_ACTIONS];
    int32_t flags[VG_MAX_ACTIONS];
    uint8_t mask[VG_MAX_ACTIONS];
    uint32_t n_discrete = 0, n_continuous = 0, n_values = 0, n_mask = 0, i;
    int64_t shown = 0;
    VG_UNUSED;
    if (!vg_begin(&c, user_data, "update_demonstrated_continuous", argc, argv, 6, 7) || !vg_agent_handle(&c, &a) ||
        !vg_arg_float(&c, 0, "reward", &reward) ||
        !vg_read_ints(&c, argv[1], "discrete", discrete, VERVE_MAX_DISCRETE_SENSORS, &n_discrete) ||
        !vg_read_floats(&c, argv[2], "continuous", continuous, VERVE_MAX_CONTINUOUS_SENSORS, &n_continuous) ||
        !vg_arg_float(&c, 3, "dt", &dt) || !vg_arg_type(&c, 4, "action", GODOT_VARIANT_TYPE_INT) ||
        !vg_read_floats(&c, argv[5], "continuous_action", values, VERVE_MAX_CONTINUOUS_ACTIONS, &n_values) ||
        (argc == 7 && !vg_read_ints(&c, argv[6], "mask", flags, VG_MAX_ACTIONS, &n_mask)))
        return vg_variant_bool(0);
    for (i = 0; i < n_mask; ++i) {
        if (flags[i] != 0 && flags[i] != 1) {
            vg_fail(&c, "mask[%u] must be 0 or 1 (got %d)", i, (int)flags[i]);
            return vg_variant_bool(0);
        }
        mask[i] = (uint8_t)flags[i];
    }
    shown = vg_core->godot_variant_as_int(argv[4]);
    if (shown < 0 || shown > (int64_t)UINT32_MAX) {
        vg_fail(&c, "action must be 0 .. actions-1 (got %lld)", (long long)shown);
        return vg_variant_bool(0);
    }
    return vg_variant_bool(vg_check(&c, verve_agent_update_demonstrated_continuous(
                                            a, reward, discrete, n_discrete, continuous, n_continuous, dt,
                                            argc == 7 ? mask : NULL, argc == 7 ? n_mask : 0, (uint32_t)shown, values,
                                            n_values)));
}

VG_METHOD(teach) {
    vg_call c;
    verve_agent* a;
    float praise = 0.0f;
    VG_UNUSED;
    return vg_variant_bool(vg_begin(&c, user_data, "teach", argc, argv, 1, 1) && vg_agent_handle(&c, &a) &&
                           vg_arg_float(&c, 0, "praise", &praise) && vg_check(&c, verve_agent_teach(a, praise)));
}

VG_METHOD(end_episode) {
    vg_call c;
    verve_agent* a;
    float reward = 0.0f;
    VG_UNUSED;
    return vg_variant_bool(vg_begin(&c, user_data, "end_episode", argc, argv, 1, 1) && vg_agent_handle(&c, &a) &&
                           vg_arg_float(&c, 0, "final_reward", &reward) &&
                           vg_check(&c, verve_agent_end_episode(a, reward)));
}

VG_METHOD(truncate_episode) {
    vg_call c;
    verve_agent* a;
    float reward = 0.0f;
    VG_UNUSED;
    return vg_variant_bool(vg_begin(&c, user_data, "truncate_episode", argc, argv, 1, 1) && vg_agent_handle(&c, &a) &&
                           vg_arg_float(&c, 0, "reward", &reward) &&
                           vg_check(&c, verve_agent_truncate_episode(a, reward)));
}

VG_METHOD(reset_short_term_memory) {
    vg_call c;
    verve_agent* a;
    VG_UNUSED;
    return vg_variant_bool(vg_begin(&c, user_data, "reset_short_term_memory", argc, argv, 0, 0) &&
                           vg_agent_handle(&c, &a) && vg_check(&c, verve_agent_reset_short_term_memory(a)));
}

VG_METHOD(get_options) {
    vg_call c;
    verve_agent* a;
    verve_agent_desc d;
    VG_UNUSED;
    verve_agent_desc_default(&d); /* sets struct_size */
    if (!vg_begin(&c, user_data, "get_options", argc, argv, 0, 0) || !vg_agent_handle(&c, &a) ||
        !vg_check(&c, verve_agent_get_desc(a, &d)))
        return vg_variant_nil();
    return vg_options_variant(&d);
}

VG_METHOD(get_default_options) {
    vg_call c;
    verve_agent_desc d;
    VG_UNUSED;
    if (!vg_begin(&c, user_data, "get_default_options", argc, argv, 0, 0)) return vg_variant_nil();
    verve_agent_desc_default(&d);
    return vg_options_variant(&d);
}

VG_METHOD(get_value) {
    vg_call c;
    verve_agent* a;
    float v = 0.0f;
    VG_UNUSED;
    if (!vg_begin(&c, user_data, "get_value", argc, argv, 0, 0) || !vg_agent_handle(&c, &a) ||
        !vg_check(&c, verve_agent_get_value(a, &v)))
        return vg_variant_nil();
    return vg_variant_real(v);
}

VG_METHOD(get_td_error) {
    vg_call c;
    verve_agent* a;
    float v = 0.0f;
    VG_UNUSED;
    if (!vg_begin(&c, user_data, "get_td_error", argc, argv, 0, 0) || !vg_agent_handle(&c, &a) ||
        !vg_check(&c, verve_agent_get_td_error(a, &v)))
        return vg_variant_nil();
    return vg_variant_real(v);
}

VG_METHOD(get_rbf_count) {
    vg_call c;
    verve_agent* a;
    uint32_t n = 0;
    VG_UNUSED;
    if (!vg_begin(&c, user_data, "get_rbf_count", argc, argv, 0, 0) || !vg_agent_handle(&c, &a) ||
        !vg_check(&c, verve_agent_get_rbf_count(a, &n)))
        return vg_variant_nil();
    return vg_variant_int(n);
}

VG_METHOD(get_action_probabilities) {
    vg_call c;
    verve_agent* a;
    verve_agent_desc d;
    godot_pool_real_array values;
    godot_pool_real_array_write_access* write;
    float* out;
    VG_UNUSED;
    verve_agent_desc_default(&d);
    if (!vg_begin(&c, user_data, "get_action_probabilities", argc, argv, 0, 0) || !vg_agent_handle(&c, &a) ||
        !vg_check(&c, verve_agent_get_desc(a, &d)))
        return vg_variant_nil();
    /* One per action, or with action branches one per choice of each branch (each branch sums to 1). */
    out = vg_reals_open(&values, &write, vb_action_choices(&d));
    return vg_reals_close(&values, write,
                          vg_check(&c, verve_agent_get_action_probabilities(a, out, vb_action_choices(&d))));
}

VG_METHOD(get_stats) {
    vg_call c;
    verve_agent* a;
    verve_agent_stats s;
    godot_dictionary dict;
    godot_variant out;
    VG_UNUSED;
    memset(&s, 0, sizeof s);
    s.struct_size = (uint32_t)sizeof s;
    if (!vg_begin(&c, user_data, "get_stats", argc, argv, 0, 0) || !vg_agent_handle(&c, &a) ||
        !vg_check(&c, verve_agent_get_stats(a, &s)))
        return vg_variant_nil();
    vg_core->godot_dictionary_new(&dict);
    vg_dict_set(&dict, "steps", vg_variant_int((int64_t)s.steps));
    vg_dict_set(&dict, "rbf_count", vg_variant_int(s.rbf_count));
    vg_dict_set(&dict, "live_traces", vg_variant_int(s.live_traces));
    vg_dict_set(&dict, "value", vg_variant_real(s.value));
    vg_dict_set(&dict, "td_error", vg_variant_real(s.td_error));
    vg_dict_set(&dict, "model_error", vg_variant_real(s.model_error));
    vg_dict_set(&dict, "predicted_uncertainty", vg_variant_real(s.predicted_uncertainty));
    vg_dict_set(&dict, "planning_steps", vg_variant_int(s.planning_steps));
    vg_dict_set(&dict, "curiosity_reward", vg_variant_real(s.curiosity_reward));
    vg_dict_set(&dict, "rbf_budget_hits", vg_variant_int((int64_t)s.rbf_budget_hits));
    vg_dict_set(&dict, "clamped_rewards", vg_variant_int((int64_t)s.clamped_rewards));
    vg_core->godot_variant_new_dictionary(&out, &dict);
    vg_core->godot_dictionary_destroy(&dict);
    return out;
}

/* An int variant within [lo, hi] into *out. */
static int vg_int_in(const godot_variant* v, int64_t lo, int64_t hi, uint32_t* out) {
    int64_t i;
    if (!v || vg_core->godot_variant_get_type(v) != GODOT_VARIANT_TYPE_INT) return 0;
    i = vg_core->godot_variant_as_int(v);
    if (i < lo || i > hi) return 0;
    *out = (uint32_t)i;
    return 1;
}

/* One axis: {"kind": "continuous" or "discrete", "index": i, "samples": n}; a discrete axis's
 * samples default to that sensor's value count. */
static int vg_read_axis(vg_call* c, const godot_variant* v, uint32_t i, const verve_agent_desc* d,
                        verve_value_axis* axis) {
    static const char* const keys[] = {"kind", "index", "samples"};
    const godot_variant* values[3];
    godot_dictionary dict;
    int ok;
    if (vg_core->godot_variant_get_type(v) != GODOT_VARIANT_TYPE_DICTIONARY)
        return vg_fail(c, "axes[%u] must be a Dictionary {\"kind\": ..., \"index\": ..., \"samples\": ...} (got %s)",
                       i, vg_type_name(v));
    dict = vg_core->godot_variant_as_dictionary(v);
    ok = vg_dict_fields(c, &dict, "axis key", keys, sizeof keys[0], 3, values);
    if (ok && vg_string_is(values[0], "continuous")) axis->kind = VERVE_SENSOR_CONTINUOUS;
    else if (ok && vg_string_is(values[0], "discrete")) axis->kind = VERVE_SENSOR_DISCRETE;
    else if (ok) ok = vg_fail(c, "axes[%u].kind must be \"continuous\" or \"discrete\"", i);
    if (ok && !vg_int_in(values[1], 0, INT32_MAX, &axis->index))
        ok = vg_fail(c, "axes[%u].index must be a sensor index from 0", i);
    if (ok && !values[2] && axis->kind == VERVE_SENSOR_DISCRETE)
        axis->samples = axis->index >= d->num_discrete_sensors || axis->index >= VERVE_MAX_SENSORS ? 0
                        : axis->index < VERVE_MAX_DISCRETE_SENSORS
                            ? d->discrete_sensor_values[axis->index]
                            : d->more_discrete_sensor_values[axis->index - VERVE_MAX_DISCRETE_SENSORS];
    else if (ok && !vg_int_in(values[2], 1, VG_MAX_SAMPLES, &axis->samples))
        ok = vg_fail(c, "axes[%u].samples must be an int from 1 to %u", i, VG_MAX_SAMPLES);
    vg_core->godot_dictionary_destroy(&dict);
    return ok;
}

VG_METHOD(sample_values) {
    vg_call c;
    verve_agent* a;
    verve_agent_desc d;
    verve_value_axis axes[2];
    int32_t discrete[VERVE_MAX_SENSORS] = {0};
    float continuous[VERVE_MAX_SENSORS] = {0};
    uint32_t n_discrete, n_continuous, n_axes = 0, i;
    uint64_t total;
    godot_array list;
    godot_pool_real_array values;
    godot_pool_real_array_write_access* write;
    float* out;
    int ok = 1;
    VG_UNUSED;
    verve_agent_desc_default(&d);
    if (!vg_begin(&c, user_data, "sample_values", argc, argv, 1, 3) || !vg_agent_handle(&c, &a) ||
        !vg_check(&c, verve_agent_get_desc(a, &d)) || !vg_arg_type(&c, 0, "axes", GODOT_VARIANT_TYPE_ARRAY))
        return vg_variant_nil();
    /* Sensors not given are held at 0 (the first discrete value, the middle of a continuous range). */
    n_discrete = d.num_discrete_sensors;
    n_continuous = d.num_continuous_sensors;
    if ((argc > 1 && !vg_read_ints(&c, argv[1], "base_discrete", discrete, VERVE_MAX_SENSORS, &n_discrete)) ||
        (argc > 2 && !vg_read_floats(&c, argv[2], "base_continuous", continuous, VERVE_MAX_SENSORS,
                                     &n_continuous)))
        return vg_variant_nil();
    list = vg_core->godot_variant_as_array(argv[0]);
    n_axes = (uint32_t)vg_core->godot_array_size(&list);
    if (n_axes < 1 || n_axes > 2) ok = vg_fail(&c, "give 1 or 2 axes (got %u)", n_axes);
    for (i = 0; ok && i < n_axes; ++i)
        ok = vg_read_axis(&c, vg_core->godot_array_operator_index_const(&list, (godot_int)i), i, &d, &axes[i]);
    vg_core->godot_array_destroy(&list);
    if (!ok) return vg_variant_nil();
    total = (uint64_t)axes[0].samples * (n_axes == 2 ? axes[1].samples : 1);
    if (total > VG_MAX_SAMPLES) {
        vg_fail(&c, "%lu samples; at most %u", (unsigned long)total, VG_MAX_SAMPLES);
        return vg_variant_nil();
    }
    out = vg_reals_open(&values, &write, (uint32_t)total);
    return vg_reals_close(&values, write,
                          vg_check(&c, verve_agent_sample_values(a, axes, n_axes, discrete, n_discrete, continuous,
                                                                 n_continuous, out, (uint32_t)total)));
}

VG_METHOD(has_agent) {
    vg_call c;
    VG_UNUSED;
    return vg_variant_bool(vg_begin(&c, user_data, "has_agent", argc, argv, 0, 0) && c.self->handle != NULL);
}

VG_METHOD(close) {
    vg_call c;
    VG_UNUSED;
    if (vg_begin(&c, user_data, "close", argc, argv, 0, 0)) vg_adopt(c.self, NULL);
    return vg_variant_nil();
}

VG_METHOD(get_last_error) {
    VG_UNUSED, (void)argc, (void)argv;
    return vg_variant_string(user_data ? ((vg_agent*)user_data)->last_error : "");
}

void vg_set_learning(godot_object* object, void* method_data, void* user_data, godot_variant* value) {
    vg_call c;
    verve_agent* a;
    int enabled = 0;
    VG_UNUSED;
    if (vg_begin(&c, user_data, "learning", 1, &value, 1, 1) && vg_agent_handle(&c, &a) &&
        vg_arg_bool(&c, 0, "learning", &enabled))
        vg_check(&c, verve_agent_set_learning(a, enabled));
}

void vg_set_greedy(godot_object* object, void* method_data, void* user_data, godot_variant* value) {
    vg_call c;
    verve_agent* a;
    int greedy = 0;
    VG_UNUSED;
    if (vg_begin(&c, user_data, "greedy", 1, &value, 1, 1) && vg_agent_handle(&c, &a) &&
        vg_arg_bool(&c, 0, "greedy", &greedy))
        vg_check(&c, verve_agent_set_action_selection(a, greedy ? VERVE_ACTION_GREEDY : VERVE_ACTION_SAMPLE));
}

godot_variant vg_get_greedy(godot_object* object, void* method_data, void* user_data) {
    vg_call c;
    verve_agent* a;
    uint32_t mode = 0;
    VG_UNUSED;
    if (!vg_begin(&c, user_data, "greedy", 0, NULL, 0, 0) || !vg_agent_handle(&c, &a) ||
        !vg_check(&c, verve_agent_get_action_selection(a, &mode)))
        return vg_variant_nil();
    return vg_variant_bool(mode == VERVE_ACTION_GREEDY);
}

godot_variant vg_get_learning(godot_object* object, void* method_data, void* user_data) {
    vg_call c;
    verve_agent* a;
    int enabled = 0;
    VG_UNUSED;
    if (!vg_begin(&c, user_data, "learning", 0, NULL, 0, 0) || !vg_agent_handle(&c, &a) ||
        !vg_check(&c, verve_agent_get_learning(a, &enabled)))
        return vg_variant_nil();
    return vg_variant_bool(enabled);
}
