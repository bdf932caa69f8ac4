/* verve_action_methods.c - action branches and continuous actions on a VerveAgent:
 * split_action(action) -> Array of one choice per branch, join_action(choices) -> the combined
 * action, get_continuous_action() -> the latest update's continuous values. Actions and choices count
 * from 0, as every action of this plugin; branch 0 varies fastest. A failure prints a Godot error
 * and returns null or -1. */
#include "verve_agent_methods.h"

#define VG_METHOD(name) \
    godot_variant vg_##name(godot_object* object, void* method_data, void* user_data, int argc, godot_variant** argv)
#define VG_UNUSED (void)object, (void)method_data

/* How many choices an action of this agent has: its branches, or 1 with one action set. */
static int vg_branch_count(vg_call* c, verve_agent* a, uint32_t* out) {
    verve_agent_desc d;
    verve_agent_desc_default(&d);
    if (!vg_check(c, verve_agent_get_desc(a, &d))) return 0;
    *out = d.num_action_branches == 0 ? 1 : d.num_action_branches;
    return 1;
}

VG_METHOD(split_action) {
    vg_call c;
    verve_agent* a;
    uint32_t choices[VERVE_MAX_ACTION_BRANCHES], n = 0, b;
    int64_t action;
    godot_array list;
    godot_variant out;
    VG_UNUSED;
    if (!vg_begin(&c, user_data, "split_action", argc, argv, 1, 1) || !vg_agent_handle(&c, &a) ||
        !vg_arg_type(&c, 0, "action", GODOT_VARIANT_TYPE_INT))
        return vg_variant_nil();
    action = vg_core->godot_variant_as_int(argv[0]);
    if (action < 0 || action > (int64_t)UINT32_MAX) {
        vg_fail(&c, "action must be 0 .. actions-1 (got %lld)", (long long)action);
        return vg_variant_nil();
    }
    if (!vg_branch_count(&c, a, &n) || !vg_check(&c, verve_agent_split_action(a, (uint32_t)action, choices, n)))
        return vg_variant_nil();
    vg_core->godot_array_new(&list);
    for (b = 0; b < n; ++b) {
        godot_variant e = vg_variant_int(choices[b]);
        vg_core->godot_array_append(&list, &e);
        vg_core->godot_variant_destroy(&e);
    }
    vg_core->godot_variant_new_array(&out, &list);
    vg_core->godot_array_destroy(&list);
    return out;
}

VG_METHOD(join_action) {
    vg_call c;
    verve_agent* a;
    int32_t given[VERVE_MAX_ACTION_BRANCHES];
    uint32_t choices[VERVE_MAX_ACTION_BRANCHES], n = 0, b, action = 0;
    VG_UNUSED;
    if (!vg_begin(&c, user_data, "join_action", argc, argv, 1, 1) || !vg_agent_handle(&c, &a) ||
        !vg_read_ints(&c, argv[0], "choices", given, VERVE_MAX_ACTION_BRANCHES, &n))
        return vg_variant_int(-1);
    for (b = 0; b < n; ++b) {
        if (given[b] < 0) {
            vg_fail(&c, "choices[%u] must be a choice from 0 (got %d)", b, (int)given[b]);
            return vg_variant_int(-1);
        }
        choices[b] = (uint32_t)given[b];
    }
    if (!vg_check(&c, verve_agent_join_action(a, choices, n, &action))) return vg_variant_int(-1);
    return vg_variant_int(action);
}

VG_METHOD(get_continuous_action) {
    vg_call c;
    verve_agent* a;
    verve_agent_desc d;
    godot_pool_real_array values;
    godot_pool_real_array_write_access* write;
    float* out;
    float none = 0.0f;
    uint32_t n;
    VG_UNUSED;
    verve_agent_desc_default(&d);
    if (!vg_begin(&c, user_data, "get_continuous_action", argc, argv, 0, 0) || !vg_agent_handle(&c, &a) ||
        !vg_check(&c, verve_agent_get_desc(a, &d)))
        return vg_variant_nil();
    n = d.num_continuous_actions <= VERVE_MAX_CONTINUOUS_ACTIONS ? (uint32_t)d.num_continuous_actions : 0;
    out = vg_reals_open(&values, &write, n);
    /* An empty PoolRealArray has no buffer; the library wants a pointer even for 0 values. */
    return vg_reals_close(&values, write, vg_check(&c, verve_agent_get_continuous_action(a, n ? out : &none, n)));
}
