/* verve_lua.c - the Lua module `verve` (require "verve"), a thin layer over the C ABI.
 *
 * One source, built twice: against Lua 5.4 and against LuaJIT 2.1 (the Lua 5.1 API).
 * Indexing follows Lua: actions, discrete sensor values and sensor indices are 1-based here and
 * shifted by one at the C boundary. Continuous values stay in [-1, 1].
 * Nothing the binding does per update allocates: observations are read into stack buffers. */
#include <float.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <verve_c.h>

#include "action_choices.h"
#include "lua_actions.h"
#include "lua_batch.h"
#include "lua_compat.h"
#include "lua_descriptor.h"
#include "lua_recording.h"
#include "lua_shared.h"
#include "lua_warnings.h"

#if defined(_WIN32)
#  define LV_EXPORT __declspec(dllexport)
#else
#  define LV_EXPORT __attribute__((visibility("default")))
#endif

#define LV_BRAIN_MT "verve.brain"
/* sample_values refuses more points than this instead of allocating without bound. */
#define LV_MAX_SAMPLES (1u << 24)

static const char* const lv_selection_names[] = {"sample", "greedy", NULL};

typedef struct lv_brain {
    verve_brain* handle; /* NULL once closed */
} lv_brain;

/* ---- errors and conversions ------------------------------------------------------------- */

int lv_fail(lua_State* L, const char* fn, verve_result r) {
    return luaL_error(L, "verve: %s: %s [%s]", fn, verve_last_error(), verve_result_name(r));
}

/* For calls taking 1-based sensors or values: the library's message speaks 0-based. */
int lv_fail_indexed(lua_State* L, const char* fn, verve_result r) {
    return luaL_error(L, "verve: %s: %s [%s] (the library counts sensors and values from 0, Lua from 1)", fn,
                      verve_last_error(), verve_result_name(r));
}

/* Lua numbers are doubles; a finite double beyond float range becomes an infinity (which the
 * library refuses) instead of an undefined conversion. */
float lv_to_float(lua_Number n) {
    if (n > FLT_MAX) return (float)HUGE_VAL;
    if (n < -FLT_MAX) return (float)-HUGE_VAL;
    return (float)n;
}

/* The non-negative integer at idx that fits 32 bits, else 0. */
int lv_get_u32(lua_State* L, int idx, uint32_t* out) {
    lua_Integer v = 0;
    if (!lv_tointeger(L, idx, &v) || v < 0 || v > (lua_Integer)UINT32_MAX) return 0;
    *out = (uint32_t)v;
    return 1;
}

void lv_check_keys(lua_State* L, int idx, const char* const* allowed, const char* fn, const char* what) {
    idx = lua_absindex(L, idx);
    lua_pushnil(L);
    while (lua_next(L, idx)) {
        const char* const* a = allowed;
        if (lua_type(L, -2) != LUA_TSTRING)
            luaL_error(L, "verve: %s: %s fields are names (got a %s key)", fn, what, luaL_typename(L, -2));
        while (*a && strcmp(*a, lua_tostring(L, -2)) != 0) ++a;
        if (!*a) luaL_error(L, "verve: %s: unknown %s field '%s'", fn, what, lua_tostring(L, -2));
        lua_pop(L, 1);
    }
}

/* ---- agent userdata --------------------------------------------------------------------- */

static lv_agent* lv_push_agent(lua_State* L) {
    lv_agent* ud = (lv_agent*)lua_newuserdata(L, sizeof *ud);
    ud->handle = NULL; /* set only after the C call succeeds, so a failure leaks nothing */
    luaL_setmetatable(L, LV_AGENT_MT);
    return ud;
}

/* The native handle of the agent at index 1. Fetch it only after every Lua input is read and every
 * Lua allocation is done, right before the C call: reading a table may run an __index metamethod,
 * and allocating may run a finalizer, and either may close this very agent. */
verve_agent* lv_open_agent(lua_State* L) {
    lv_agent* ud = (lv_agent*)luaL_checkudata(L, 1, LV_AGENT_MT);
    if (!ud->handle) luaL_error(L, "verve: the agent is closed");
    return ud->handle;
}

/* ---- observations ----------------------------------------------------------------------- */

/* obs.<key> (a list of at most max numbers) into the stack; returns the count. Integers are
 * shifted to 0-based when `discrete` is set. */
static uint32_t lv_read_obs_list(lua_State* L, int obs, const char* fn, const char* key, int discrete, int raw,
                                 lv_obs* o) {
    uint32_t n, i, max = VERVE_MAX_SENSORS;
    if (raw) {
        lua_pushstring(L, key);
        lua_rawget(L, obs);
    } else {
        lua_getfield(L, obs, key);
    }
    if (lua_isnil(L, -1)) {
        lua_pop(L, 1);
        return 0;
    }
    if (!lua_istable(L, -1)) luaL_error(L, "verve: %s: obs.%s must be a list (got %s)", fn, key, luaL_typename(L, -1));
    n = (uint32_t)lua_rawlen(L, -1);
    if (n > max) luaL_error(L, "verve: %s: obs.%s has %d values; an agent has at most %d", fn, key, (int)n,
                          (int)max);
    for (i = 0; i < n; ++i) {
        lua_rawgeti(L, -1, (int)i + 1);
        if (discrete) {
            lua_Integer v = 0;
            if (!lv_tointeger(L, -1, &v) || v <= INT32_MIN || v > INT32_MAX)
                luaL_error(L, "verve: %s: obs.discrete[%d] must be an integer value from 1 (got %s)", fn,
                           (int)i + 1, luaL_typename(L, -1));
            o->discrete[i] = (int32_t)(v - 1);
        } else {
            if (lua_type(L, -1) != LUA_TNUMBER)
                luaL_error(L, "verve: %s: obs.continuous[%d] must be a number (got %s)", fn, (int)i + 1,
                           luaL_typename(L, -1));
            o->continuous[i] = lv_to_float(lua_tonumber(L, -1));
        }
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
    return n;
}

/* {discrete = {...}, continuous = {...}} at idx; nil means no sensors. Sizes and ranges are
 * the library's to check, so its message reaches the script. Raw: without metamethods, so that no
 * Lua code runs while it reads (the lists' elements are always read raw). */
void lv_read_obs(lua_State* L, int idx, const char* fn, int raw, lv_obs* o) {
    o->n_discrete = o->n_continuous = 0;
    if (lua_isnoneornil(L, idx)) return;
    if (!lua_istable(L, idx))
        luaL_error(L, "verve: %s: the observation must be a table {discrete = {...}, continuous = {...}} (got %s)",
                   fn, luaL_typename(L, idx));
    o->n_discrete = lv_read_obs_list(L, idx, fn, "discrete", 1, raw, o);
    o->n_continuous = lv_read_obs_list(L, idx, fn, "continuous", 0, raw, o);
}

/* ---- module functions ------------------------------------------------------------------- */

static int lv_new_agent(lua_State* L) {
    verve_agent_desc d;
    lv_agent* ud;
    verve_result r;
    lv_read_desc(L, 1, &d);
    ud = lv_push_agent(L);
    r = verve_agent_create(&d, &ud->handle);
    if (r != VERVE_OK) return lv_fail(L, "agent", r);
    return 1;
}

static int lv_load(lua_State* L) {
    const char* path = luaL_checkstring(L, 1);
    lv_agent* ud = lv_push_agent(L);
    verve_result r = verve_agent_load(path, &ud->handle);
    if (r != VERVE_OK) return lv_fail(L, "load", r);
    return 1;
}

static int lv_load_string(lua_State* L) {
    size_t size = 0;
    const char* data = luaL_checklstring(L, 1, &size);
    lv_agent* ud = lv_push_agent(L);
    verve_result r = verve_agent_load_memory(data, size, &ud->handle);
    if (r != VERVE_OK) return lv_fail(L, "load_string", r);
    return 1;
}

static int lv_defaults(lua_State* L) {
    verve_agent_desc d;
    verve_agent_desc_init(&d, (uint32_t)sizeof d);
    lv_push_desc(L, &d);
    return 1;
}

static int lv_version(lua_State* L) {
    uint32_t v = verve_version();
    lua_pushfstring(L, "%d.%d.%d", (int)(v >> 16), (int)((v >> 8) & 0xff), (int)(v & 0xff));
    lua_pushinteger(L, (lua_Integer)v);
    return 2;
}

/* ---- agent methods ---------------------------------------------------------------------- */

/* An optional list of booleans, one per action (true: allowed this step), or with action branches
 * one per choice of each branch, branch after branch; returns its length. */
static uint32_t lv_read_mask(lua_State* L, int idx, uint8_t* mask) {
    uint32_t n, i;
    luaL_checktype(L, idx, LUA_TTABLE);
    n = (uint32_t)lua_rawlen(L, idx);
    if (n > LV_MAX_CHOICES) luaL_error(L, "verve: update: the action mask has %d entries, at most %d", (int)n, LV_MAX_CHOICES);
    for (i = 0; i < n; ++i) {
        lua_rawgeti(L, idx, (int)i + 1);
        if (!lua_isboolean(L, -1))
            luaL_error(L, "verve: update: mask[%d] must be true or false (got %s)", (int)i + 1, luaL_typename(L, -1));
        mask[i] = lua_toboolean(L, -1) ? 1 : 0;
        lua_pop(L, 1);
    }
    return n;
}

static int lv_update(lua_State* L) {
    float reward, dt;
    uint32_t action = 0;
    lv_obs o;
    verve_result r;
    luaL_checkudata(L, 1, LV_AGENT_MT);
    reward = lv_to_float(luaL_checknumber(L, 2));
    dt = lv_to_float(luaL_checknumber(L, 4));
    lv_read_obs(L, 3, "update", 0, &o);
    /* Every Lua input is read before the handle is taken: a metamethod may close the agent. */
    if (lua_isnoneornil(L, 5)) {
        r = verve_agent_update(lv_open_agent(L), reward, o.discrete, o.n_discrete, o.continuous, o.n_continuous, dt,
                               &action);
    } else {
        uint8_t mask[LV_MAX_CHOICES];
        uint32_t n = lv_read_mask(L, 5, mask);
        r = verve_agent_update_masked(lv_open_agent(L), reward, o.discrete, o.n_discrete, o.continuous, o.n_continuous,
                                      dt, mask, n, &action);
    }
    if (r != VERVE_OK) return lv_fail_indexed(L, "update", r);
    lua_pushinteger(L, (lua_Integer)action + 1);
    return 1;
}

/* agent:update_demonstrated(reward, obs, dt, action [, mask]): the host took `action` (1-based). */
static int lv_update_demonstrated(lua_State* L) {
    float reward, dt;
    uint32_t action = 0, n = 0;
    uint8_t mask[LV_MAX_CHOICES];
    lv_obs o;
    verve_result r;
    luaL_checkudata(L, 1, LV_AGENT_MT);
    reward = lv_to_float(luaL_checknumber(L, 2));
    dt = lv_to_float(luaL_checknumber(L, 4));
    if (!lv_get_u32(L, 5, &action) || action == 0)
        return luaL_error(L, "verve: update_demonstrated: action must be an integer from 1 to the number of actions");
    lv_read_obs(L, 3, "update_demonstrated", 0, &o);
    if (!lua_isnoneornil(L, 6)) n = lv_read_mask(L, 6, mask);
    /* Every Lua input is read before the handle is taken: a metamethod may close the agent. */
    r = verve_agent_update_demonstrated(lv_open_agent(L), reward, o.discrete, o.n_discrete, o.continuous,
                                        o.n_continuous, dt, lua_isnoneornil(L, 6) ? NULL : mask, n, action - 1);
    if (r != VERVE_OK) return lv_fail_indexed(L, "update_demonstrated", r);
    return 0;
}

/* agent:update_demonstrated_continuous(reward, obs, dt, action, values [, mask]): the host took
 * `action` (1-based) and played the continuous actions `values` ({v1, ...}, each in [-1, 1]). */
static int lv_update_demonstrated_continuous(lua_State* L) {
    float reward, dt, values[VERVE_MAX_CONTINUOUS_ACTIONS];
    uint32_t action = 0, n = 0, count;
    uint8_t mask[LV_MAX_CHOICES];
    lv_obs o;
    verve_result r;
    luaL_checkudata(L, 1, LV_AGENT_MT);
    reward = lv_to_float(luaL_checknumber(L, 2));
    dt = lv_to_float(luaL_checknumber(L, 4));
    if (!lv_get_u32(L, 5, &action) || action == 0)
        return luaL_error(L, "verve: update_demonstrated_continuous: action must be an integer from 1 to the number of actions");
    count = lv_read_continuous_values(L, 6, "update_demonstrated_continuous", values);
    lv_read_obs(L, 3, "update_demonstrated_continuous", 0, &o);
    if (!lua_isnoneornil(L, 7)) n = lv_read_mask(L, 7, mask);
    /* Every Lua input is read before the handle is taken: a metamethod may close the agent. */
    r = verve_agent_update_demonstrated_continuous(lv_open_agent(L), reward, o.discrete, o.n_discrete, o.continuous,
                                                   o.n_continuous, dt, lua_isnoneornil(L, 7) ? NULL : mask, n, action - 1,
                                                   values, count);
    if (r != VERVE_OK) return lv_fail_indexed(L, "update_demonstrated_continuous", r);
    return 0;
}

static int lv_teach(lua_State* L) {
    float praise = lv_to_float(luaL_checknumber(L, 2));
    verve_result r = verve_agent_teach(lv_open_agent(L), praise);
    if (r != VERVE_OK) return lv_fail(L, "teach", r);
    return 0;
}

static int lv_end_episode(lua_State* L) {
    float reward = lv_to_float(luaL_checknumber(L, 2));
    verve_result r = verve_agent_end_episode(lv_open_agent(L), reward);
    if (r != VERVE_OK) return lv_fail(L, "end_episode", r);
    return 0;
}

static int lv_truncate_episode(lua_State* L) {
    verve_agent* a = lv_open_agent(L);
    verve_result r = verve_agent_truncate_episode(a, lv_to_float(luaL_checknumber(L, 2)));
    if (r != VERVE_OK) return lv_fail(L, "truncate_episode", r);
    return 0;
}

static int lv_set_action_selection(lua_State* L) {
    verve_agent* a = lv_open_agent(L);
    verve_result r = verve_agent_set_action_selection(a, (uint32_t)luaL_checkoption(L, 2, NULL, lv_selection_names));
    if (r != VERVE_OK) return lv_fail(L, "set_action_selection", r);
    return 0;
}

static int lv_action_selection(lua_State* L) {
    uint32_t mode = 0;
    verve_result r = verve_agent_get_action_selection(lv_open_agent(L), &mode);
    if (r != VERVE_OK) return lv_fail(L, "action_selection", r);
    lua_pushstring(L, lv_selection_names[mode]);
    return 1;
}

static int lv_action_probabilities(lua_State* L) {
    verve_agent* a = lv_open_agent(L);
    verve_agent_desc d;
    float p[LV_MAX_CHOICES];
    uint32_t i, n = 0;
    verve_result r;
    verve_agent_desc_init(&d, (uint32_t)sizeof d);
    r = verve_agent_get_desc(a, &d);
    /* One per action, or with action branches one per choice of each branch (each branch sums to 1). */
    if (r == VERVE_OK) n = vb_action_choices(&d);
    if (r == VERVE_OK && n > LV_MAX_CHOICES) return luaL_error(L, "verve: action_probabilities: %d values", (int)n);
    if (r == VERVE_OK) r = verve_agent_get_action_probabilities(a, p, n);
    if (r != VERVE_OK) return lv_fail(L, "action_probabilities", r);
    lua_createtable(L, (int)n, 0);
    for (i = 0; i < n; ++i) {
        lua_pushnumber(L, (lua_Number)p[i]);
        lua_rawseti(L, -2, (int)i + 1);
    }
    return 1;
}

static int lv_reset_short_term_memory(lua_State* L) {
    verve_result r = verve_agent_reset_short_term_memory(lv_open_agent(L));
    if (r != VERVE_OK) return lv_fail(L, "reset_short_term_memory", r);
    return 0;
}

static int lv_set_learning(lua_State* L) {
    verve_result r;
    luaL_checktype(L, 2, LUA_TBOOLEAN);
    r = verve_agent_set_learning(lv_open_agent(L), lua_toboolean(L, 2));
    if (r != VERVE_OK) return lv_fail(L, "set_learning", r);
    return 0;
}

static int lv_learning(lua_State* L) {
    int enabled = 0;
    verve_result r = verve_agent_get_learning(lv_open_agent(L), &enabled);
    if (r != VERVE_OK) return lv_fail(L, "learning", r);
    lua_pushboolean(L, enabled);
    return 1;
}

static int lv_descriptor(lua_State* L) {
    verve_agent_desc d;
    verve_result r;
    verve_agent_desc_init(&d, (uint32_t)sizeof d); /* sets struct_size */
    r = verve_agent_get_desc(lv_open_agent(L), &d);
    if (r != VERVE_OK) return lv_fail(L, "descriptor", r);
    lv_push_desc(L, &d);
    return 1;
}

static int lv_value(lua_State* L) {
    float v = 0.0f;
    verve_result r = verve_agent_get_value(lv_open_agent(L), &v);
    if (r != VERVE_OK) return lv_fail(L, "value", r);
    lua_pushnumber(L, (lua_Number)v);
    return 1;
}

static int lv_td_error(lua_State* L) {
    float v = 0.0f;
    verve_result r = verve_agent_get_td_error(lv_open_agent(L), &v);
    if (r != VERVE_OK) return lv_fail(L, "td_error", r);
    lua_pushnumber(L, (lua_Number)v);
    return 1;
}

static int lv_rbf_count(lua_State* L) {
    uint32_t n = 0;
    verve_result r = verve_agent_get_rbf_count(lv_open_agent(L), &n);
    if (r != VERVE_OK) return lv_fail(L, "rbf_count", r);
    lua_pushinteger(L, (lua_Integer)n);
    return 1;
}

/* agent:stats([t]) fills t (or a new table): pass the same table each frame to avoid garbage. */
static int lv_stats(lua_State* L) {
    verve_agent_stats s;
    verve_result r;
    memset(&s, 0, sizeof s);
    s.struct_size = (uint32_t)sizeof s;
    if (!lua_isnoneornil(L, 2)) luaL_checktype(L, 2, LUA_TTABLE);
    r = verve_agent_get_stats(lv_open_agent(L), &s);
    if (r != VERVE_OK) return lv_fail(L, "stats", r);
    if (lua_istable(L, 2)) lua_settop(L, 2);
    else lua_createtable(L, 0, 11);
    lua_pushinteger(L, (lua_Integer)s.steps);
    lua_setfield(L, -2, "steps");
    lua_pushinteger(L, (lua_Integer)s.rbf_count);
    lua_setfield(L, -2, "rbf_count");
    lua_pushinteger(L, (lua_Integer)s.live_traces);
    lua_setfield(L, -2, "live_traces");
    lua_pushnumber(L, (lua_Number)s.value);
    lua_setfield(L, -2, "value");
    lua_pushnumber(L, (lua_Number)s.td_error);
    lua_setfield(L, -2, "td_error");
    lua_pushnumber(L, (lua_Number)s.model_error);
    lua_setfield(L, -2, "model_error");
    lua_pushnumber(L, (lua_Number)s.predicted_uncertainty);
    lua_setfield(L, -2, "predicted_uncertainty");
    lua_pushinteger(L, (lua_Integer)s.planning_steps);
    lua_setfield(L, -2, "planning_steps");
    lua_pushnumber(L, (lua_Number)s.curiosity_reward);
    lua_setfield(L, -2, "curiosity_reward");
    lua_pushinteger(L, (lua_Integer)s.rbf_budget_hits);
    lua_setfield(L, -2, "rbf_budget_hits");
    lua_pushinteger(L, (lua_Integer)s.clamped_rewards);
    lua_setfield(L, -2, "clamped_rewards");
    return 1;
}

static const char* const lv_axis_keys[] = {"kind", "index", "samples", NULL};

/* {kind = "continuous"|"discrete", index = 1.., samples = n} on top of the stack. A discrete
 * axis's samples default to the sensor's value count. */
static void lv_read_axis(lua_State* L, const verve_agent_desc* d, verve_value_axis* axis) {
    const char* kind;
    if (!lua_istable(L, -1)) luaL_error(L, "verve: sample_values: each axis must be a table {kind=, index=, samples=}");
    lv_check_keys(L, -1, lv_axis_keys, "sample_values", "axis");
    lua_getfield(L, -1, "kind");
    kind = lua_type(L, -1) == LUA_TSTRING ? lua_tostring(L, -1) : "";
    if (strcmp(kind, "continuous") == 0) axis->kind = VERVE_SENSOR_CONTINUOUS;
    else if (strcmp(kind, "discrete") == 0) axis->kind = VERVE_SENSOR_DISCRETE;
    else luaL_error(L, "verve: sample_values: axis kind must be \"continuous\" or \"discrete\"");
    lua_pop(L, 1);
    lua_getfield(L, -1, "index");
    if (!lv_get_u32(L, -1, &axis->index) || axis->index == 0)
        luaL_error(L, "verve: sample_values: axis index must be an integer from 1 (got %s)", luaL_typename(L, -1));
    axis->index -= 1;
    lua_pop(L, 1);
    lua_getfield(L, -1, "samples");
    if (lua_isnil(L, -1) && axis->kind == VERVE_SENSOR_DISCRETE) /* no such sensor: the library says so */
        axis->samples = axis->index < d->num_discrete_sensors && axis->index < VERVE_MAX_SENSORS ? lv_discrete_count(d, axis->index) : 0;
    else if (!lv_get_u32(L, -1, &axis->samples))
        luaL_error(L, "verve: sample_values: axis samples must be a non-negative integer (got %s)",
                   luaL_typename(L, -1));
    lua_pop(L, 1);
}

/* agent:sample_values(axes, [base]) -> V over 1 or 2 swept sensors, the others held at base
 * (default: every discrete sensor at 1, every continuous at 0). One axis gives a list;
 * two give t[i][j], i along the first axis and j along the second. */
static int lv_sample_values(lua_State* L) {
    verve_agent_desc d;
    verve_value_axis axes[2];
    uint32_t n_axes, i, j, n0, n1;
    uint64_t total;
    lv_obs base;
    float* out;
    verve_result r;
    verve_agent_desc_init(&d, (uint32_t)sizeof d);
    r = verve_agent_get_desc(lv_open_agent(L), &d); /* the axes' defaults; the handle is fetched again below */
    if (r != VERVE_OK) return lv_fail(L, "sample_values", r);
    luaL_checktype(L, 2, LUA_TTABLE);
    n_axes = (uint32_t)lua_rawlen(L, 2);
    if (n_axes < 1 || n_axes > 2) luaL_error(L, "verve: sample_values: give 1 or 2 axes (got %d)", (int)n_axes);
    for (i = 0; i < n_axes; ++i) {
        lua_rawgeti(L, 2, (int)i + 1);
        lv_read_axis(L, &d, &axes[i]);
        lua_pop(L, 1);
    }
    if (lua_isnoneornil(L, 3)) {
        memset(&base, 0, sizeof base);
        base.n_discrete = d.num_discrete_sensors;
        base.n_continuous = d.num_continuous_sensors;
    } else {
        lv_read_obs(L, 3, "sample_values", 0, &base);
    }
    n0 = axes[0].samples;
    n1 = n_axes == 2 ? axes[1].samples : 1;
    total = (uint64_t)n0 * n1;
    if (total > LV_MAX_SAMPLES) luaL_error(L, "verve: sample_values: more than %d samples", (int)LV_MAX_SAMPLES);
    out = (float*)lua_newuserdata(L, (size_t)(total ? total : 1) * sizeof(float)); /* collected by Lua */
    r = verve_agent_sample_values(lv_open_agent(L), axes, n_axes, base.discrete, base.n_discrete, base.continuous,
                                  base.n_continuous, out, (uint32_t)total);
    if (r != VERVE_OK) return lv_fail_indexed(L, "sample_values", r);
    lua_createtable(L, (int)n0, 0);
    for (i = 0; i < n0; ++i) {
        if (n_axes == 1) {
            lua_pushnumber(L, (lua_Number)out[i]);
        } else {
            lua_createtable(L, (int)n1, 0);
            for (j = 0; j < n1; ++j) {
                lua_pushnumber(L, (lua_Number)out[(size_t)j * n0 + i]); /* axis 0 fastest in C */
                lua_rawseti(L, -2, (int)j + 1);
            }
        }
        lua_rawseti(L, -2, (int)i + 1);
    }
    return 1;
}

/* A save of the agent or of the brain at index 1: the agent's function, or NULL and the brain's. */
typedef verve_result (VERVE_CALL* lv_file_save)(const verve_agent*, const char*);
typedef verve_result (VERVE_CALL* lv_memory_save)(const verve_agent*, void*, size_t*);
typedef verve_result (VERVE_CALL* lv_brain_file_save)(const verve_brain*, const char*);
typedef verve_result (VERVE_CALL* lv_brain_memory_save)(const verve_brain*, void*, size_t*);

static verve_brain* lv_open_brain(lua_State* L);

static int lv_save_file(lua_State* L, lv_file_save agent_save, lv_brain_file_save brain_save, const char* name) {
    const char* path = luaL_checkstring(L, 2);
    verve_result r = agent_save ? agent_save(lv_open_agent(L), path) : brain_save(lv_open_brain(L), path);
    if (r != VERVE_OK) return lv_fail(L, name, r);
    return 0;
}

/* The memory save as a Lua string. */
static int lv_push_save(lua_State* L, lv_memory_save agent_save, lv_brain_memory_save brain_save, const char* name) {
    size_t size = 0;
    void* buffer;
    verve_result r = agent_save ? agent_save(lv_open_agent(L), NULL, &size) : brain_save(lv_open_brain(L), NULL, &size);
    if (r != VERVE_OK && r != VERVE_ERROR_BUFFER_TOO_SMALL) return lv_fail(L, name, r);
    buffer = lua_newuserdata(L, size ? size : 1); /* collected by Lua, even if a later call errors */
    /* Opened again: a finalizer run by that allocation may have closed it. */
    r = agent_save ? agent_save(lv_open_agent(L), buffer, &size) : brain_save(lv_open_brain(L), buffer, &size);
    if (r != VERVE_OK) return lv_fail(L, name, r);
    lua_pushlstring(L, (const char*)buffer, size);
    return 1;
}

static int lv_save(lua_State* L) { return lv_save_file(L, verve_agent_save, NULL, "save"); }
static int lv_save_string(lua_State* L) { return lv_push_save(L, verve_agent_save_memory, NULL, "save_string"); }
static int lv_save_binary(lua_State* L) { return lv_save_file(L, verve_agent_save_binary, NULL, "save_binary"); }
static int lv_save_binary_string(lua_State* L) {
    return lv_push_save(L, verve_agent_save_memory_binary, NULL, "save_binary_string");
}

/* close, __gc and __close: idempotent. */
static int lv_close(lua_State* L) {
    lv_agent* ud = (lv_agent*)luaL_checkudata(L, 1, LV_AGENT_MT);
    verve_agent_destroy(ud->handle);
    ud->handle = NULL;
    return 0;
}

static int lv_tostring(lua_State* L) {
    lv_agent* ud = (lv_agent*)luaL_checkudata(L, 1, LV_AGENT_MT);
    verve_agent_desc d;
    verve_agent_desc_init(&d, (uint32_t)sizeof d);
    if (!ud->handle) {
        lua_pushfstring(L, "verve.agent (closed): %p", (void*)ud);
    } else if (verve_agent_get_desc(ud->handle, &d) == VERVE_OK) {
        lua_pushfstring(L, "verve.agent (%d discrete, %d continuous sensors, %d actions",
                        (int)d.num_discrete_sensors, (int)d.num_continuous_sensors, (int)d.num_actions);
        if (d.num_continuous_actions > 0) lua_pushfstring(L, ", %d continuous actions", (int)d.num_continuous_actions);
        else lua_pushliteral(L, "");
        lua_pushfstring(L, "): %p", (void*)ud);
        lua_concat(L, 3);
    } else {
        lua_pushfstring(L, "verve.agent: %p", (void*)ud);
    }
    return 1;
}

/* ---- one brain, many bodies ------------------------------------------------------------ */

static lv_brain* lv_push_brain(lua_State* L) {
    lv_brain* ud = (lv_brain*)lua_newuserdata(L, sizeof *ud);
    ud->handle = NULL;
    luaL_setmetatable(L, LV_BRAIN_MT);
    return ud;
}

static verve_brain* lv_open_brain(lua_State* L) {
    lv_brain* ud = (lv_brain*)luaL_checkudata(L, 1, LV_BRAIN_MT);
    if (!ud->handle) luaL_error(L, "verve: the brain is closed");
    return ud->handle;
}

static int lv_new_brain(lua_State* L) {
    verve_agent_desc d;
    lv_brain* ud;
    verve_result r;
    lv_read_desc(L, 1, &d);
    ud = lv_push_brain(L);
    r = verve_brain_create(&d, &ud->handle);
    if (r != VERVE_OK) return lv_fail(L, "brain", r);
    return 1;
}

static int lv_load_brain(lua_State* L) {
    const char* path = luaL_checkstring(L, 1);
    lv_brain* ud = lv_push_brain(L);
    verve_result r = verve_brain_load(path, &ud->handle);
    if (r != VERVE_OK) return lv_fail(L, "load_brain", r);
    return 1;
}

static int lv_load_brain_string(lua_State* L) {
    size_t size = 0;
    const char* data = luaL_checklstring(L, 1, &size);
    lv_brain* ud = lv_push_brain(L);
    verve_result r = verve_brain_load_memory(data, size, &ud->handle);
    if (r != VERVE_OK) return lv_fail(L, "load_brain_string", r);
    return 1;
}

static int lv_brain_body(lua_State* L) {
    verve_brain* b = lv_open_brain(L);
    lv_agent* ud = lv_push_agent(L);
    verve_result r = verve_brain_create_body(b, &ud->handle);
    if (r != VERVE_OK) return lv_fail(L, "body", r);
    return 1;
}

static int lv_brain_rbf_count(lua_State* L) {
    uint32_t n = 0;
    verve_result r = verve_brain_get_rbf_count(lv_open_brain(L), &n);
    if (r != VERVE_OK) return lv_fail(L, "rbf_count", r);
    lua_pushinteger(L, (lua_Integer)n);
    return 1;
}

static int lv_brain_save(lua_State* L) { return lv_save_file(L, NULL, verve_brain_save, "save"); }
static int lv_brain_save_string(lua_State* L) { return lv_push_save(L, NULL, verve_brain_save_memory, "save_string"); }
static int lv_brain_save_binary(lua_State* L) { return lv_save_file(L, NULL, verve_brain_save_binary, "save_binary"); }
static int lv_brain_save_binary_string(lua_State* L) {
    return lv_push_save(L, NULL, verve_brain_save_memory_binary, "save_binary_string");
}

static int lv_brain_close(lua_State* L) {
    lv_brain* ud = (lv_brain*)luaL_checkudata(L, 1, LV_BRAIN_MT);
    verve_brain_destroy(ud->handle);
    ud->handle = NULL;
    return 0;
}

static const luaL_Reg lv_brain_methods[] = {
    {"body", lv_brain_body},
    {"rbf_count", lv_brain_rbf_count},
    {"save", lv_brain_save},
    {"save_string", lv_brain_save_string},
    {"save_binary", lv_brain_save_binary},
    {"save_binary_string", lv_brain_save_binary_string},
    {"close", lv_brain_close},
    {NULL, NULL},
};

static const luaL_Reg lv_brain_meta[] = {
    {"__gc", lv_brain_close},
    {"__close", lv_brain_close},
    {NULL, NULL},
};

static const luaL_Reg lv_agent_methods[] = {
    {"update", lv_update},
    {"update_demonstrated", lv_update_demonstrated},
    {"update_demonstrated_continuous", lv_update_demonstrated_continuous},
    {"teach", lv_teach},
    {"end_episode", lv_end_episode},
    {"truncate_episode", lv_truncate_episode},
    {"set_action_selection", lv_set_action_selection},
    {"action_selection", lv_action_selection},
    {"action_probabilities", lv_action_probabilities},
    {"split_action", lv_split_action},
    {"join_action", lv_join_action},
    {"continuous_action", lv_continuous_action},
    {"reset_short_term_memory", lv_reset_short_term_memory},
    {"set_learning", lv_set_learning},
    {"learning", lv_learning},
    {"descriptor", lv_descriptor},
    {"value", lv_value},
    {"td_error", lv_td_error},
    {"rbf_count", lv_rbf_count},
    {"stats", lv_stats},
    {"sample_values", lv_sample_values},
    {"save", lv_save},
    {"save_string", lv_save_string},
    {"save_binary", lv_save_binary},
    {"save_binary_string", lv_save_binary_string},
    {"replay", lv_replay},
    {"close", lv_close},
    {NULL, NULL},
};

static const luaL_Reg lv_agent_meta[] = {
    {"__gc", lv_close},
    {"__close", lv_close}, /* Lua 5.4 to-be-closed variables; ignored by LuaJIT */
    {"__tostring", lv_tostring},
    {NULL, NULL},
};

static const luaL_Reg lv_module[] = {
    {"agent", lv_new_agent},
    {"load", lv_load},
    {"load_string", lv_load_string},
    {"defaults", lv_defaults},
    {"version", lv_version},
    {"brain", lv_new_brain},
    {"load_brain", lv_load_brain},
    {"load_brain_string", lv_load_brain_string},
    {"batch", lv_new_batch},
    {"warnings", lv_warnings},
    {"recording", lv_new_recording},
    {"load_recording", lv_load_recording},
    {"load_recording_string", lv_load_recording_string},
    {NULL, NULL},
};

/* A metatable `name` with methods as __index and the metamethods in `meta`. */
void lv_register_type(lua_State* L, const char* name, const luaL_Reg* meta, const luaL_Reg* methods) {
    luaL_newmetatable(L, name);
    luaL_setfuncs(L, meta, 0);
    lua_newtable(L);
    luaL_setfuncs(L, methods, 0);
    lua_setfield(L, -2, "__index");
    lua_pushstring(L, name);
    lua_setfield(L, -2, "__name"); /* Lua 5.4 sets it too; LuaJIT's error messages use it */
    lua_pop(L, 1);
}

LV_EXPORT int luaopen_verve(lua_State* L) {
    uint32_t v = verve_version();
    /* A library with another major version, or older than this header, may lack what we call. */
    if ((v >> 16) != VERVE_VERSION_MAJOR || v < VERVE_VERSION_NUMBER)
        return luaL_error(L, "verve: the module needs libverve %d.%d.x (>= %d.%d.%d) but found %d.%d.%d",
                          VERVE_VERSION_MAJOR, VERVE_VERSION_MINOR, VERVE_VERSION_MAJOR, VERVE_VERSION_MINOR,
                          VERVE_VERSION_PATCH, (int)(v >> 16), (int)((v >> 8) & 0xff), (int)(v & 0xff));
    /* Before any agent exists: the log hook can only be installed while libverve holds no memory. */
    lv_install_warnings();
    lv_register_type(L, LV_AGENT_MT, lv_agent_meta, lv_agent_methods);
    lv_register_type(L, LV_BRAIN_MT, lv_brain_meta, lv_brain_methods);
    lv_register_batches(L);
    lv_register_recordings(L);
    luaL_newlib(L, lv_module);
    return 1;
}
