#include "gd_options.h"

#include <stddef.h>
#include <stdio.h>
#include <string.h>

typedef enum vg_kind {
    VG_UINT, VG_FLOAT, VG_UINT64, VG_BOOL, VG_ENUM, VG_DISCRETE_SENSORS, VG_CIRCULAR, VG_SENSOR_GROUPS,
    VG_ACTION_BRANCHES, VG_CONTINUOUS_ACTIONS
} vg_kind;

typedef struct vg_option {
    const char* name;
    size_t offset;
    vg_kind kind;
    const char* const* names; /* VG_ENUM: value i is names[i] */
} vg_option;

static const char* const vg_allocation_names[] = {"dynamic", "full", NULL};
static const char* const vg_curiosity_names[] = {"none", "novelty", "progress", NULL};
static const char* const vg_prediction_names[] = {"categorical", "ordinal", NULL};
static const char* const vg_grouping_names[] = {"auto", "joint", "custom", NULL};

#define VG_OPTION(name, member, kind, names) {name, offsetof(verve_agent_desc, member), kind, names}
static const vg_option vg_options[] = {
    VG_OPTION("discrete_sensors", discrete_sensor_values, VG_DISCRETE_SENSORS, NULL),
    VG_OPTION("continuous_sensor_circular", continuous_sensor_circular, VG_CIRCULAR, NULL),
    VG_OPTION("actions", num_actions, VG_UINT, NULL),
    VG_OPTION("resolution", resolution, VG_UINT, NULL),
    VG_OPTION("rbf_allocation", rbf_allocation, VG_ENUM, vg_allocation_names),
    VG_OPTION("tau_value", tau_value, VG_FLOAT, NULL),
    VG_OPTION("tau_discount", tau_discount, VG_FLOAT, NULL),
    VG_OPTION("tau_eligibility", tau_eligibility, VG_FLOAT, NULL),
    VG_OPTION("policy_multiplier", policy_multiplier, VG_FLOAT, NULL),
    VG_OPTION("trace_threshold", trace_threshold, VG_FLOAT, NULL),
    VG_OPTION("seed", seed, VG_UINT64, NULL),
    VG_OPTION("planning", planning, VG_BOOL, NULL),
    VG_OPTION("tau_model", tau_model, VG_FLOAT, NULL),
    VG_OPTION("max_planning_steps", max_planning_steps, VG_UINT, NULL),
    VG_OPTION("planning_uncertainty_threshold", planning_uncertainty_threshold, VG_FLOAT, NULL),
    VG_OPTION("curiosity", curiosity, VG_ENUM, vg_curiosity_names),
    VG_OPTION("curiosity_factor", curiosity_factor, VG_FLOAT, NULL),
    VG_OPTION("planning_accumulates_uncertainty", planning_accumulates_uncertainty, VG_BOOL, NULL),
    VG_OPTION("learn_from_real_steps", learn_from_real_steps, VG_BOOL, NULL),
    VG_OPTION("discrete_prediction", discrete_prediction, VG_ENUM, vg_prediction_names),
    VG_OPTION("max_rbfs", max_rbfs, VG_UINT64, NULL),
    VG_OPTION("policy_weight_bound", policy_weight_bound, VG_FLOAT, NULL),
    VG_OPTION("adaptation", adaptation, VG_UINT64, NULL),
    VG_OPTION("grouping", sensor_grouping, VG_ENUM, vg_grouping_names),
    VG_OPTION("sensor_groups", sensor_groups, VG_SENSOR_GROUPS, NULL),
    VG_OPTION("action_branches", action_branches, VG_ACTION_BRANCHES, NULL),
    VG_OPTION("continuous_actions", num_continuous_actions, VG_CONTINUOUS_ACTIONS, NULL),
};

#define VG_OPTION_COUNT (sizeof vg_options / sizeof vg_options[0])

static int vg_option_error(vg_call* c, const vg_option* o, const char* expected, const godot_variant* v) {
    return vg_fail(c, "option '%s' must be %s (got %s)", o->name, expected, vg_type_name(v));
}

/* Sensor i's entry in the desc: the first 16 in the V1-V7 arrays, sensors 16..63 in V8's. */
static uint32_t* vg_discrete_values(verve_agent_desc* d, uint32_t i) {
    return i < VERVE_MAX_DISCRETE_SENSORS ? &d->discrete_sensor_values[i]
                                          : &d->more_discrete_sensor_values[i - VERVE_MAX_DISCRETE_SENSORS];
}
static uint8_t* vg_circular(verve_agent_desc* d, uint32_t i) {
    return i < VERVE_MAX_CONTINUOUS_SENSORS ? &d->continuous_sensor_circular[i]
                                            : &d->more_continuous_sensor_circular[i - VERVE_MAX_CONTINUOUS_SENSORS];
}

static int vg_read_discrete_sensors(vg_call* c, const vg_option* o, const godot_variant* v, verve_agent_desc* d) {
    int32_t values[VERVE_MAX_SENSORS];
    uint32_t n = 0, i;
    if (!vg_read_ints(c, v, o->name, values, VERVE_MAX_SENSORS, &n)) return 0;
    for (i = 0; i < n; ++i) {
        if (values[i] < 0) return vg_fail(c, "option '%s': value counts are not negative (got %d)", o->name, values[i]);
        *vg_discrete_values(d, i) = (uint32_t)values[i];
    }
    d->num_discrete_sensors = n;
    return 1;
}

static int vg_read_circular(vg_call* c, const vg_option* o, const godot_variant* v, verve_agent_desc* d) {
    godot_array array;
    godot_int n, i;
    int ok = 1;
    if (vg_core->godot_variant_get_type(v) != GODOT_VARIANT_TYPE_ARRAY)
        return vg_option_error(c, o, "an Array of bools, one per continuous sensor", v);
    array = vg_core->godot_variant_as_array(v);
    n = vg_core->godot_array_size(&array);
    if (n > VERVE_MAX_SENSORS)
        ok = vg_fail(c, "option '%s' has %d sensors; an agent has at most %d", o->name, (int)n, VERVE_MAX_SENSORS);
    for (i = 0; ok && i < n; ++i) {
        const godot_variant* e = vg_core->godot_array_operator_index_const(&array, i);
        if (vg_core->godot_variant_get_type(e) != GODOT_VARIANT_TYPE_BOOL)
            ok = vg_fail(c, "option '%s'[%d] must be a bool (true: the sensor wraps around) (got %s)", o->name,
                         (int)i, vg_type_name(e));
        else
            *vg_circular(d, (uint32_t)i) = vg_core->godot_variant_as_bool(e) ? 1 : 0;
    }
    vg_core->godot_array_destroy(&array);
    if (ok) d->num_continuous_sensors = (uint32_t)n;
    return ok;
}

/* sensor_groups: an Array of groups, each an Array (or PoolIntArray) of continuous sensor indices
 * from 0, into bit masks (bit i: sensor i). Whether they fit the sensors: vg_check_sensor_groups. */
static int vg_read_sensor_groups(vg_call* c, const vg_option* o, const godot_variant* v, verve_agent_desc* d) {
    godot_array array;
    godot_int n, g;
    int ok = 1;
    if (vg_core->godot_variant_get_type(v) != GODOT_VARIANT_TYPE_ARRAY)
        return vg_option_error(c, o, "an Array of groups of continuous sensor indices, like [[0, 1], [2]]", v);
    array = vg_core->godot_variant_as_array(v);
    n = vg_core->godot_array_size(&array);
    if (n > VERVE_MAX_SENSOR_GROUPS)
        ok = vg_fail(c, "option '%s' has %d groups; at most %d", o->name, (int)n, VERVE_MAX_SENSOR_GROUPS);
    for (g = 0; ok && g < n; ++g) {
        const godot_variant* e = vg_core->godot_array_operator_index_const(&array, g);
        godot_variant_type t = vg_core->godot_variant_get_type(e);
        int32_t sensors[VERVE_MAX_SENSORS];
        uint32_t m = 0, k;
        uint64_t mask = 0;
        char name[64];
        snprintf(name, sizeof name, "option '%s'[%d]", o->name, (int)g);
        if (t != GODOT_VARIANT_TYPE_ARRAY && t != GODOT_VARIANT_TYPE_POOL_INT_ARRAY) {
            ok = vg_fail(c, "%s must be an Array of continuous sensor indices (got %s)", name, vg_type_name(e));
            break;
        }
        ok = vg_read_ints(c, e, name, sensors, VERVE_MAX_SENSORS, &m);
        if (ok && m == 0) ok = vg_fail(c, "%s is empty", name);
        for (k = 0; ok && k < m; ++k) {
            if (sensors[k] < 0 || sensors[k] >= VERVE_MAX_SENSORS)
                ok = vg_fail(c, "%s[%u] must be a continuous sensor index from 0 to %d (got %d)", name, k,
                             VERVE_MAX_SENSORS - 1, (int)sensors[k]);
            else if (mask & ((uint64_t)1 << sensors[k]))
                ok = vg_fail(c, "%s lists continuous sensor %d twice", name, (int)sensors[k]);
            else
                mask |= (uint64_t)1 << sensors[k];
        }
        if (ok) d->sensor_groups[g] = mask;
    }
    vg_core->godot_array_destroy(&array);
    if (ok) d->num_sensor_groups = (uint32_t)n;
    return ok;
}

/* Groups against sensors, in this API's terms (the library checks the same and speaks of C fields
 * and bits). Groups given without 'grouping' mean "custom". */
static int vg_check_sensor_groups(vg_call* c, verve_agent_desc* d, int grouping_given) {
    uint32_t n = d->num_continuous_sensors, g, s;
    uint64_t covered = 0;
    if (!grouping_given && d->num_sensor_groups > 0) d->sensor_grouping = VERVE_GROUPING_CUSTOM;
    if (d->sensor_grouping != VERVE_GROUPING_CUSTOM) {
        if (d->num_sensor_groups > 0)
            return vg_fail(c, "option 'sensor_groups' is only used with 'grouping' \"custom\" (got \"%s\")",
                           vg_grouping_names[d->sensor_grouping]);
        return 1;
    }
    if (d->num_sensor_groups == 0 && n > 0)
        return vg_fail(c, "option 'grouping' \"custom\" needs 'sensor_groups' covering every continuous sensor");
    for (g = 0; g < d->num_sensor_groups; ++g) {
        for (s = n; s < VERVE_MAX_SENSORS; ++s)
            if (d->sensor_groups[g] & ((uint64_t)1 << s))
                return vg_fail(c, "option 'sensor_groups'[%u] lists continuous sensor %u, but the agent has %u", g, s, n);
        covered |= d->sensor_groups[g];
    }
    for (s = 0; s < n; ++s)
        if (!(covered & ((uint64_t)1 << s)))
            return vg_fail(c, "continuous sensor %u is in none of option 'sensor_groups': its readings would be ignored",
                           s);
    return 1;
}

/* action_branches: an Array (or PoolIntArray) of choice counts, one per branch, like [3, 3, 2]. */
static int vg_read_action_branches(vg_call* c, const vg_option* o, const godot_variant* v, verve_agent_desc* d) {
    int32_t sizes[VERVE_MAX_ACTION_BRANCHES];
    uint32_t n = 0, b;
    char name[64];
    godot_variant_type t = vg_core->godot_variant_get_type(v);
    if (t != GODOT_VARIANT_TYPE_ARRAY && t != GODOT_VARIANT_TYPE_POOL_INT_ARRAY)
        return vg_option_error(c, o, "an Array of choice counts, one per branch, like [3, 3, 2]", v);
    snprintf(name, sizeof name, "option '%s'", o->name);
    if (!vg_read_ints(c, v, name, sizes, VERVE_MAX_ACTION_BRANCHES, &n)) return 0;
    for (b = 0; b < n; ++b) {
        if (sizes[b] < 1)
            return vg_fail(c, "%s[%u] must be a number of choices, at least 1 (got %d)", name, b, (int)sizes[b]);
        d->action_branches[b] = (uint32_t)sizes[b];
    }
    d->num_action_branches = n;
    return 1;
}

/* continuous_actions: how many values in [-1, 1] the agent chooses beside its discrete action.
 * The range is checked here so that the error names this option, not the C field. */
static int vg_read_continuous_actions(vg_call* c, const vg_option* o, const godot_variant* v, verve_agent_desc* d) {
    char expected[32];
    int64_t n;
    snprintf(expected, sizeof expected, "an int from 0 to %d", VERVE_MAX_CONTINUOUS_ACTIONS);
    if (vg_core->godot_variant_get_type(v) != GODOT_VARIANT_TYPE_INT) return vg_option_error(c, o, expected, v);
    n = vg_core->godot_variant_as_int(v);
    if (n < 0 || n > VERVE_MAX_CONTINUOUS_ACTIONS)
        return vg_fail(c, "option '%s' must be %s (got %lld)", o->name, expected, (long long)n);
    d->num_continuous_actions = (uint64_t)n;
    return 1;
}

static int vg_read_enum(vg_call* c, const vg_option* o, const godot_variant* v, uint32_t* out) {
    char expected[128] = "one of";
    uint32_t i = 0;
    while (o->names[i] && !vg_string_is(v, o->names[i])) ++i;
    if (o->names[i]) {
        *out = i;
        return 1;
    }
    for (i = 0; o->names[i]; ++i) {
        strcat(expected, i ? ", \"" : " \"");
        strcat(expected, o->names[i]);
        strcat(expected, "\"");
    }
    return vg_option_error(c, o, expected, v);
}

static int vg_read_option(vg_call* c, const vg_option* o, const godot_variant* v, verve_agent_desc* d) {
    char* p = (char*)d + o->offset;
    godot_variant_type t = vg_core->godot_variant_get_type(v);
    int64_t i = t == GODOT_VARIANT_TYPE_INT ? vg_core->godot_variant_as_int(v) : -1;
    switch (o->kind) {
    case VG_UINT:
        if (t != GODOT_VARIANT_TYPE_INT || i < 0 || i > (int64_t)UINT32_MAX)
            return vg_option_error(c, o, "a non-negative int", v);
        *(uint32_t*)p = (uint32_t)i;
        return 1;
    case VG_UINT64:
        if (t != GODOT_VARIANT_TYPE_INT || i < 0) return vg_option_error(c, o, "a non-negative int", v);
        *(uint64_t*)p = (uint64_t)i;
        return 1;
    case VG_FLOAT:
        if (t == GODOT_VARIANT_TYPE_INT) *(float*)p = (float)i;
        else if (t == GODOT_VARIANT_TYPE_REAL) *(float*)p = vg_to_float(vg_core->godot_variant_as_real(v));
        else return vg_option_error(c, o, "a number", v);
        return 1;
    case VG_BOOL:
        if (t != GODOT_VARIANT_TYPE_BOOL) return vg_option_error(c, o, "a bool", v);
        *(uint32_t*)p = vg_core->godot_variant_as_bool(v) ? 1u : 0u;
        return 1;
    case VG_ENUM: return vg_read_enum(c, o, v, (uint32_t*)p);
    case VG_DISCRETE_SENSORS: return vg_read_discrete_sensors(c, o, v, d);
    case VG_CIRCULAR: return vg_read_circular(c, o, v, d);
    case VG_SENSOR_GROUPS: return vg_read_sensor_groups(c, o, v, d);
    case VG_ACTION_BRANCHES: return vg_read_action_branches(c, o, v, d);
    case VG_CONTINUOUS_ACTIONS: return vg_read_continuous_actions(c, o, v, d);
    }
    return 0;
}

int vg_options_read(vg_call* c, int i, verve_agent_desc* d) {
    const godot_variant* arg = vg_arg(c, i);
    const godot_variant* values[VG_OPTION_COUNT];
    godot_dictionary dict;
    size_t k;
    int ok;
    verve_agent_desc_default(d);
    if (!arg) return 1;
    if (!vg_arg_type(c, i, "options", GODOT_VARIANT_TYPE_DICTIONARY)) return 0;
    dict = vg_core->godot_variant_as_dictionary(arg);
    ok = vg_dict_fields(c, &dict, "option", vg_options, sizeof vg_options[0], (int)VG_OPTION_COUNT, values);
    for (k = 0; ok && k < VG_OPTION_COUNT; ++k)
        if (values[k]) ok = vg_read_option(c, &vg_options[k], values[k], d);
    for (k = 0; k < VG_OPTION_COUNT && vg_options[k].offset != offsetof(verve_agent_desc, sensor_grouping); ++k) {}
    if (ok) ok = vg_check_sensor_groups(c, d, k < VG_OPTION_COUNT && values[k] != NULL);
    /* Branches without 'actions': num_actions 0, which the library sets to their product. */
    for (k = 0; k < VG_OPTION_COUNT && vg_options[k].offset != offsetof(verve_agent_desc, num_actions); ++k) {}
    if (ok && d->num_action_branches > 0 && (k == VG_OPTION_COUNT || values[k] == NULL)) d->num_actions = 0;
    /* Continuous actions without branches or 'actions': num_actions 0, which the library makes the
     * one trivial discrete action of an agent that only steers (not the default 2). */
    if (ok && d->num_continuous_actions > 0 && d->num_action_branches == 0 &&
        (k == VG_OPTION_COUNT || values[k] == NULL))
        d->num_actions = 0;
    vg_core->godot_dictionary_destroy(&dict);
    return ok;
}

static godot_variant vg_option_variant(const vg_option* o, const verve_agent_desc* d) {
    const char* p = (const char*)d + o->offset;
    godot_array list;
    godot_variant v;
    uint32_t i, n;
    switch (o->kind) {
    case VG_UINT: return vg_variant_int(*(const uint32_t*)p);
    case VG_UINT64:
    case VG_CONTINUOUS_ACTIONS: return vg_variant_int((int64_t)*(const uint64_t*)p);
    case VG_FLOAT: return vg_variant_real(*(const float*)p);
    case VG_BOOL: return vg_variant_bool(*(const uint32_t*)p != 0);
    case VG_ENUM: {
        uint32_t u = *(const uint32_t*)p;
        for (i = 0; o->names[i] && i < u; ++i) {}
        return vg_variant_string(o->names[i] ? o->names[i] : "unknown");
    }
    case VG_DISCRETE_SENSORS:
    case VG_CIRCULAR:
    case VG_ACTION_BRANCHES:
        vg_core->godot_array_new(&list);
        n = o->kind == VG_CIRCULAR ? d->num_continuous_sensors
            : o->kind == VG_ACTION_BRANCHES ? d->num_action_branches : d->num_discrete_sensors;
        if (n > (o->kind == VG_ACTION_BRANCHES ? VERVE_MAX_ACTION_BRANCHES : VERVE_MAX_SENSORS)) n = 0;
        for (i = 0; i < n; ++i) {
            godot_variant e = o->kind == VG_CIRCULAR ? vg_variant_bool(*vg_circular((verve_agent_desc*)d, i))
                              : o->kind == VG_ACTION_BRANCHES ? vg_variant_int(d->action_branches[i])
                                                              : vg_variant_int(*vg_discrete_values((verve_agent_desc*)d, i));
            vg_core->godot_array_append(&list, &e);
            vg_core->godot_variant_destroy(&e);
        }
        vg_core->godot_variant_new_array(&v, &list);
        vg_core->godot_array_destroy(&list);
        return v;
    case VG_SENSOR_GROUPS:
        vg_core->godot_array_new(&list);
        n = d->num_sensor_groups <= VERVE_MAX_SENSOR_GROUPS ? d->num_sensor_groups : 0;
        for (i = 0; i < n; ++i) {
            godot_array group;
            godot_variant e;
            uint32_t s;
            vg_core->godot_array_new(&group);
            for (s = 0; s < 64; ++s) {
                if (!(d->sensor_groups[i] & ((uint64_t)1 << s))) continue;
                e = vg_variant_int(s);
                vg_core->godot_array_append(&group, &e);
                vg_core->godot_variant_destroy(&e);
            }
            vg_core->godot_variant_new_array(&e, &group);
            vg_core->godot_array_destroy(&group);
            vg_core->godot_array_append(&list, &e);
            vg_core->godot_variant_destroy(&e);
        }
        vg_core->godot_variant_new_array(&v, &list);
        vg_core->godot_array_destroy(&list);
        return v;
    }
    return vg_variant_nil();
}

godot_variant vg_options_variant(const verve_agent_desc* d) {
    godot_dictionary dict;
    godot_variant v;
    size_t i;
    vg_core->godot_dictionary_new(&dict);
    for (i = 0; i < VG_OPTION_COUNT; ++i) vg_dict_set(&dict, vg_options[i].name, vg_option_variant(&vg_options[i], d));
    vg_core->godot_variant_new_dictionary(&v, &dict);
    vg_core->godot_dictionary_destroy(&dict);
    return v;
}
