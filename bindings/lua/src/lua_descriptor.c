/* lua_descriptor.c - a Lua table <-> verve_agent_desc: every field by name, sensors, groups and
 * actions 1-based, each wrong field refused by name before any agent is made. */
#include <float.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <verve_c.h>

#include "lua_actions.h"
#include "lua_compat.h"
#include "lua_descriptor.h"
#include "lua_shared.h"

typedef enum lv_kind { LV_UINT, LV_FLOAT, LV_UINT64, LV_BOOL, LV_ENUM } lv_kind;

typedef struct lv_field {
    const char* name;
    size_t offset;
    lv_kind kind;
    const char* const* names; /* LV_ENUM: value i is names[i] */
} lv_field;

static const char* const lv_allocation_names[] = {"dynamic", "full", NULL};
static const char* const lv_curiosity_names[] = {"none", "novelty", "progress", NULL};
static const char* const lv_prediction_names[] = {"categorical", "ordinal", NULL};
static const char* const lv_grouping_names[] = {"auto", "joint", "custom", NULL};

#define LV_FIELD(name, member, kind, names) {name, offsetof(verve_agent_desc, member), kind, names}
static const lv_field lv_fields[] = {
    LV_FIELD("actions", num_actions, LV_UINT, NULL),
    LV_FIELD("resolution", resolution, LV_UINT, NULL),
    LV_FIELD("allocation", rbf_allocation, LV_ENUM, lv_allocation_names),
    LV_FIELD("tau_value", tau_value, LV_FLOAT, NULL),
    LV_FIELD("tau_discount", tau_discount, LV_FLOAT, NULL),
    LV_FIELD("tau_eligibility", tau_eligibility, LV_FLOAT, NULL),
    LV_FIELD("policy_multiplier", policy_multiplier, LV_FLOAT, NULL),
    LV_FIELD("trace_threshold", trace_threshold, LV_FLOAT, NULL),
    LV_FIELD("seed", seed, LV_UINT64, NULL),
    LV_FIELD("planning", planning, LV_BOOL, NULL),
    LV_FIELD("tau_model", tau_model, LV_FLOAT, NULL),
    LV_FIELD("max_planning_steps", max_planning_steps, LV_UINT, NULL),
    LV_FIELD("planning_uncertainty_threshold", planning_uncertainty_threshold, LV_FLOAT, NULL),
    LV_FIELD("curiosity", curiosity, LV_ENUM, lv_curiosity_names),
    LV_FIELD("curiosity_factor", curiosity_factor, LV_FLOAT, NULL),
    LV_FIELD("planning_accumulates_uncertainty", planning_accumulates_uncertainty, LV_BOOL, NULL),
    LV_FIELD("learn_from_real_steps", learn_from_real_steps, LV_BOOL, NULL),
    LV_FIELD("discrete_prediction", discrete_prediction, LV_ENUM, lv_prediction_names),
    LV_FIELD("max_rbfs", max_rbfs, LV_UINT64, NULL),
    LV_FIELD("policy_weight_bound", policy_weight_bound, LV_FLOAT, NULL),
    LV_FIELD("adaptation", adaptation, LV_UINT64, NULL),
    LV_FIELD("grouping", sensor_grouping, LV_ENUM, lv_grouping_names),
};
#define LV_FIELD_COUNT (sizeof lv_fields / sizeof lv_fields[0])

static const char* const lv_sensor_keys[] = {"circular", NULL};

static void lv_desc_error(lua_State* L, const char* field, const char* expected) {
    luaL_error(L, "verve: agent: descriptor field '%s' must be %s (got %s)", field, expected,
               luaL_typename(L, -1));
}

/* The value on top of the stack into one scalar descriptor field. */
static void lv_read_field(lua_State* L, const lv_field* f, verve_agent_desc* d) {
    char* p = (char*)d + f->offset;
    lua_Integer v = 0;
    switch (f->kind) {
    case LV_UINT:
        if (!lv_get_u32(L, -1, (uint32_t*)p)) lv_desc_error(L, f->name, "a non-negative integer");
        break;
    case LV_FLOAT:
        if (lua_type(L, -1) != LUA_TNUMBER) lv_desc_error(L, f->name, "a number");
        *(float*)p = lv_to_float(lua_tonumber(L, -1));
        break;
    case LV_UINT64:
        if (!lv_tointeger(L, -1, &v) || v < 0) lv_desc_error(L, f->name, "a non-negative integer");
        *(uint64_t*)p = (uint64_t)v;
        break;
    case LV_BOOL:
        if (!lua_isboolean(L, -1)) lv_desc_error(L, f->name, "a boolean");
        *(uint32_t*)p = lua_toboolean(L, -1) ? 1u : 0u;
        break;
    case LV_ENUM: {
        uint32_t i = 0;
        if (lua_type(L, -1) == LUA_TSTRING)
            while (f->names[i] && strcmp(f->names[i], lua_tostring(L, -1)) != 0) ++i;
        if (lua_type(L, -1) != LUA_TSTRING || !f->names[i]) {
            int n = 0;
            for (; f->names[n]; ++n) lua_pushfstring(L, "%s\"%s\"", n ? ", " : "", f->names[n]);
            lua_concat(L, n);
            luaL_error(L, "verve: agent: descriptor field '%s' must be one of %s", f->name, lua_tostring(L, -1));
        }
        *(uint32_t*)p = i;
        break;
    }
    }
}

/* names[u], or "unknown" past the end of the list. */
static const char* lv_enum_name(const char* const* names, uint32_t u) {
    uint32_t i = 0;
    while (names[i] && i < u) ++i;
    return names[i] ? names[i] : "unknown";
}

static void lv_push_field(lua_State* L, const lv_field* f, const verve_agent_desc* d) {
    const char* p = (const char*)d + f->offset;
    switch (f->kind) {
    case LV_UINT:
        lua_pushinteger(L, (lua_Integer)*(const uint32_t*)p);
        break;
    case LV_FLOAT:
        lua_pushnumber(L, (lua_Number)*(const float*)p);
        break;
    case LV_UINT64:
        lua_pushinteger(L, (lua_Integer)*(const uint64_t*)p);
        break;
    case LV_BOOL:
        lua_pushboolean(L, *(const uint32_t*)p != 0);
        break;
    case LV_ENUM:
        lua_pushstring(L, lv_enum_name(f->names, *(const uint32_t*)p));
        break;
    }
}

/* Sensor i's entry in the desc: the first 16 in the V1-V7 arrays, the rest in V8's. */
static uint32_t* lv_discrete_values(verve_agent_desc* d, uint32_t i) {
    return i < VERVE_MAX_DISCRETE_SENSORS ? &d->discrete_sensor_values[i]
                                          : &d->more_discrete_sensor_values[i - VERVE_MAX_DISCRETE_SENSORS];
}
static uint8_t* lv_circular(verve_agent_desc* d, uint32_t i) {
    return i < VERVE_MAX_CONTINUOUS_SENSORS ? &d->continuous_sensor_circular[i]
                                            : &d->more_continuous_sensor_circular[i - VERVE_MAX_CONTINUOUS_SENSORS];
}

uint32_t lv_discrete_count(const verve_agent_desc* d, uint32_t i) {
    return i < VERVE_MAX_DISCRETE_SENSORS ? d->discrete_sensor_values[i]
                                          : d->more_discrete_sensor_values[i - VERVE_MAX_DISCRETE_SENSORS];
}

/* discrete = {values of sensor 1, values of sensor 2, ...}, the value on top of the stack. */
static void lv_read_discrete_sensors(lua_State* L, verve_agent_desc* d) {
    uint32_t n, i;
    if (!lua_istable(L, -1)) lv_desc_error(L, "discrete", "a list of value counts");
    n = (uint32_t)lua_rawlen(L, -1);
    if (n > VERVE_MAX_SENSORS)
        luaL_error(L, "verve: agent: %d discrete sensors; at most %d", (int)n, VERVE_MAX_SENSORS);
    for (i = 0; i < n; ++i) {
        lua_rawgeti(L, -1, (int)i + 1);
        if (!lv_get_u32(L, -1, lv_discrete_values(d, i)))
            lv_desc_error(L, "discrete", "a list of non-negative integer value counts");
        lua_pop(L, 1);
    }
    d->num_discrete_sensors = n;
}

/* continuous = N (N plain sensors) or {{circular = true}, {}, ...}, on top of the stack. */
static void lv_read_continuous_sensors(lua_State* L, verve_agent_desc* d) {
    uint32_t n = 0, i;
    int listed = lua_istable(L, -1);
    if (listed) n = (uint32_t)lua_rawlen(L, -1);
    else if (!lv_get_u32(L, -1, &n)) lv_desc_error(L, "continuous", "a sensor count or a list of sensor tables");
    if (n > VERVE_MAX_SENSORS)
        luaL_error(L, "verve: agent: %d continuous sensors; at most %d", (int)n, VERVE_MAX_SENSORS);
    for (i = 0; i < n; ++i) {
        *lv_circular(d, i) = 0;
        if (!listed) continue;
        lua_rawgeti(L, -1, (int)i + 1);
        if (!lua_istable(L, -1)) lv_desc_error(L, "continuous", "a list of sensor tables like {circular = true}");
        lv_check_keys(L, -1, lv_sensor_keys, "agent", "continuous sensor");
        lua_getfield(L, -1, "circular");
        if (!lua_isnil(L, -1) && !lua_isboolean(L, -1)) lv_desc_error(L, "circular", "a boolean");
        *lv_circular(d, i) = (uint8_t)(lua_toboolean(L, -1) ? 1 : 0);
        lua_pop(L, 2);
    }
    d->num_continuous_sensors = n;
}

/* sensor_groups = {{1, 2}, {3}, ...}: each group a list of continuous sensors (from 1), on top of
 * the stack, into bit masks (bit i: sensor i + 1). Whether the groups fit the sensors is checked once
 * the whole descriptor is read (lv_check_sensor_groups). */
static void lv_read_sensor_groups(lua_State* L, verve_agent_desc* d) {
    uint32_t n, g, k, m;
    if (!lua_istable(L, -1)) lv_desc_error(L, "sensor_groups", "a list of groups like {{1, 2}, {3}}");
    n = (uint32_t)lua_rawlen(L, -1);
    if (n > VERVE_MAX_SENSOR_GROUPS)
        luaL_error(L, "verve: agent: %d sensor_groups; at most %d", (int)n, VERVE_MAX_SENSOR_GROUPS);
    for (g = 0; g < n; ++g) {
        uint64_t mask = 0;
        lua_rawgeti(L, -1, (int)g + 1);
        if (!lua_istable(L, -1))
            luaL_error(L, "verve: agent: sensor_groups[%d] must be a list of continuous sensors from 1 (got %s)",
                       (int)g + 1, luaL_typename(L, -1));
        m = (uint32_t)lua_rawlen(L, -1);
        if (m == 0) luaL_error(L, "verve: agent: sensor_groups[%d] is empty", (int)g + 1);
        for (k = 0; k < m; ++k) {
            lua_Integer s = 0;
            lua_rawgeti(L, -1, (int)k + 1);
            if (!lv_tointeger(L, -1, &s) || s < 1 || s > VERVE_MAX_SENSORS)
                luaL_error(L, "verve: agent: sensor_groups[%d][%d] must be a continuous sensor from 1 to %d (got %s)",
                           (int)g + 1, (int)k + 1, VERVE_MAX_SENSORS,
                           lua_type(L, -1) == LUA_TNUMBER ? lua_tostring(L, -1) : luaL_typename(L, -1));
            if (mask & ((uint64_t)1 << (s - 1)))
                luaL_error(L, "verve: agent: sensor_groups[%d] lists continuous sensor %d twice", (int)g + 1, (int)s);
            mask |= (uint64_t)1 << (s - 1);
            lua_pop(L, 1);
        }
        d->sensor_groups[g] = mask;
        lua_pop(L, 1);
    }
    d->num_sensor_groups = n;
}

/* Groups against sensors, in Lua's terms (sensors from 1); the library would check the same and
 * speak of bits and sensors from 0. Groups alone mean custom grouping. */
static void lv_check_sensor_groups(lua_State* L, verve_agent_desc* d, int grouping_given) {
    uint32_t n = d->num_continuous_sensors, g, s;
    uint64_t covered = 0;
    if (!grouping_given && d->num_sensor_groups > 0) d->sensor_grouping = VERVE_GROUPING_CUSTOM;
    if (d->sensor_grouping != VERVE_GROUPING_CUSTOM) {
        if (d->num_sensor_groups > 0)
            luaL_error(L, "verve: agent: sensor_groups are only used with grouping = \"custom\" (got \"%s\")",
                       lv_grouping_names[d->sensor_grouping]);
        return;
    }
    if (d->num_sensor_groups == 0 && n > 0)
        luaL_error(L, "verve: agent: grouping = \"custom\" needs sensor_groups covering every continuous sensor");
    for (g = 0; g < d->num_sensor_groups; ++g) {
        for (s = n; s < VERVE_MAX_SENSORS; ++s)
            if (d->sensor_groups[g] & ((uint64_t)1 << s))
                luaL_error(L, "verve: agent: sensor_groups[%d] lists continuous sensor %d, but the agent has %d",
                           (int)g + 1, (int)s + 1, (int)n);
        covered |= d->sensor_groups[g];
    }
    for (s = 0; s < n; ++s)
        if (!(covered & ((uint64_t)1 << s)))
            luaL_error(L, "verve: agent: continuous sensor %d is in none of sensor_groups: its readings would be "
                          "ignored",
                       (int)s + 1);
}

/* The table at idx over the library defaults; unknown fields and wrong types are errors. */
void lv_read_desc(lua_State* L, int idx, verve_agent_desc* d) {
    int grouping_given = 0, actions_given = 0;
    idx = lua_absindex(L, idx);
    luaL_checktype(L, idx, LUA_TTABLE);
    verve_agent_desc_init(d, (uint32_t)sizeof *d); /* writes only this header's struct */
    lua_pushnil(L);
    while (lua_next(L, idx)) {
        const char* key;
        size_t i = 0;
        if (lua_type(L, -2) != LUA_TSTRING)
            luaL_error(L, "verve: agent: descriptor fields are names (got a %s key)", luaL_typename(L, -2));
        key = lua_tostring(L, -2);
        if (strcmp(key, "discrete") == 0) {
            lv_read_discrete_sensors(L, d);
        } else if (strcmp(key, "continuous") == 0) {
            lv_read_continuous_sensors(L, d);
        } else if (strcmp(key, "sensor_groups") == 0) {
            lv_read_sensor_groups(L, d);
        } else if (strcmp(key, "action_branches") == 0) {
            lv_read_action_branches(L, d);
        } else if (strcmp(key, "continuous_actions") == 0) {
            lv_read_continuous_actions(L, d);
        } else {
            while (i < LV_FIELD_COUNT && strcmp(lv_fields[i].name, key) != 0) ++i;
            if (i == LV_FIELD_COUNT) luaL_error(L, "verve: agent: unknown descriptor field '%s'", key);
            lv_read_field(L, &lv_fields[i], d);
            if (lv_fields[i].offset == offsetof(verve_agent_desc, sensor_grouping)) grouping_given = 1;
            if (lv_fields[i].offset == offsetof(verve_agent_desc, num_actions)) actions_given = 1;
        }
        lua_pop(L, 1);
    }
    lv_check_sensor_groups(L, d, grouping_given);
    lv_finish_actions(d, actions_given);
}

void lv_push_desc(lua_State* L, const verve_agent_desc* d) {
    uint32_t i;
    size_t f;
    lua_createtable(L, 0, (int)LV_FIELD_COUNT + 5);
    lua_createtable(L, (int)d->num_discrete_sensors, 0);
    for (i = 0; i < d->num_discrete_sensors && i < VERVE_MAX_SENSORS; ++i) {
        lua_pushinteger(L, (lua_Integer)lv_discrete_count(d, i));
        lua_rawseti(L, -2, (int)i + 1);
    }
    lua_setfield(L, -2, "discrete");
    lua_createtable(L, (int)d->num_continuous_sensors, 0);
    for (i = 0; i < d->num_continuous_sensors && i < VERVE_MAX_SENSORS; ++i) {
        lua_createtable(L, 0, 1);
        lua_pushboolean(L, (i < VERVE_MAX_CONTINUOUS_SENSORS ? d->continuous_sensor_circular[i]
                                                             : d->more_continuous_sensor_circular[i - VERVE_MAX_CONTINUOUS_SENSORS]) != 0);
        lua_setfield(L, -2, "circular");
        lua_rawseti(L, -2, (int)i + 1);
    }
    lua_setfield(L, -2, "continuous");
    lua_createtable(L, (int)d->num_sensor_groups, 0);
    for (i = 0; i < d->num_sensor_groups && i < VERVE_MAX_SENSOR_GROUPS; ++i) {
        uint32_t s, k = 0;
        lua_newtable(L);
        for (s = 0; s < 64; ++s) {
            if (!(d->sensor_groups[i] & ((uint64_t)1 << s))) continue;
            lua_pushinteger(L, (lua_Integer)s + 1);
            lua_rawseti(L, -2, (int)++k);
        }
        lua_rawseti(L, -2, (int)i + 1);
    }
    lua_setfield(L, -2, "sensor_groups");
    lv_push_action_branches(L, d);
    lua_setfield(L, -2, "action_branches");
    lua_pushinteger(L, (lua_Integer)d->num_continuous_actions);
    lua_setfield(L, -2, "continuous_actions");
    for (f = 0; f < LV_FIELD_COUNT; ++f) {
        lv_push_field(L, &lv_fields[f], d);
        lua_setfield(L, -2, lv_fields[f].name);
    }
}
