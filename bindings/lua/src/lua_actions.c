/* lua_actions.c - actions beyond one discrete set: action branches (the descriptor field and
 * split/join of combined actions) and continuous actions (the descriptor field and their values).
 * Actions and choices are 1-based here, as every action in this module; 0-based at the C ABI. */
#include <stdint.h>

#include <lauxlib.h>

#include "lua_actions.h"
#include "lua_compat.h"
#include "lua_shared.h"

void lv_read_action_branches(lua_State* L, verve_agent_desc* d) {
    uint32_t n, b;
    if (!lua_istable(L, -1))
        luaL_error(L, "verve: agent: descriptor field 'action_branches' must be a list of choice counts like {3, 3, 2} (got %s)",
                   luaL_typename(L, -1));
    n = (uint32_t)lua_rawlen(L, -1);
    if (n > VERVE_MAX_ACTION_BRANCHES)
        luaL_error(L, "verve: agent: %d action_branches; at most %d", (int)n, VERVE_MAX_ACTION_BRANCHES);
    for (b = 0; b < n; ++b) {
        lua_rawgeti(L, -1, (int)b + 1);
        if (!lv_get_u32(L, -1, &d->action_branches[b]) || d->action_branches[b] == 0)
            luaL_error(L, "verve: agent: action_branches[%d] must be a number of choices, at least 1 (got %s)",
                       (int)b + 1, lua_type(L, -1) == LUA_TNUMBER ? lua_tostring(L, -1) : luaL_typename(L, -1));
        lua_pop(L, 1);
    }
    d->num_action_branches = n;
}

void lv_read_continuous_actions(lua_State* L, verve_agent_desc* d) {
    uint32_t n = 0;
    if (!lv_get_u32(L, -1, &n))
        luaL_error(L, "verve: agent: descriptor field 'continuous_actions' must be a count of values like 2, 0 to %d (got %s)",
                   VERVE_MAX_CONTINUOUS_ACTIONS,
                   lua_type(L, -1) == LUA_TNUMBER ? lua_tostring(L, -1) : luaL_typename(L, -1));
    if (n > VERVE_MAX_CONTINUOUS_ACTIONS)
        luaL_error(L, "verve: agent: %d continuous_actions; at most %d", (int)n, VERVE_MAX_CONTINUOUS_ACTIONS);
    d->num_continuous_actions = n;
}

void lv_finish_actions(verve_agent_desc* d, int actions_given) {
    /* The library's 0: the branches' product, or with continuous actions alone the one discrete
     * action they keep (the default 2 would make a steering agent also pick between two). */
    if ((d->num_action_branches > 0 || d->num_continuous_actions > 0) && !actions_given) d->num_actions = 0;
}

void lv_push_action_branches(lua_State* L, const verve_agent_desc* d) {
    uint32_t b;
    lua_createtable(L, (int)d->num_action_branches, 0);
    for (b = 0; b < d->num_action_branches && b < VERVE_MAX_ACTION_BRANCHES; ++b) {
        lua_pushinteger(L, (lua_Integer)d->action_branches[b]);
        lua_rawseti(L, -2, (int)b + 1);
    }
}

static uint32_t lv_branch_count(lua_State* L, const char* fn) {
    verve_agent_desc d;
    verve_result r;
    verve_agent_desc_init(&d, (uint32_t)sizeof d);
    r = verve_agent_get_desc(lv_open_agent(L), &d);
    if (r != VERVE_OK) lv_fail(L, fn, r);
    return d.num_action_branches == 0 ? 1 : d.num_action_branches;
}

int lv_split_action(lua_State* L) {
    uint32_t action = 0, choices[VERVE_MAX_ACTION_BRANCHES], n, b;
    verve_result r;
    luaL_checkudata(L, 1, LV_AGENT_MT);
    if (!lv_get_u32(L, 2, &action) || action == 0)
        return luaL_error(L, "verve: split_action: the action must be an integer from 1 to the number of actions");
    n = lv_branch_count(L, "split_action");
    r = verve_agent_split_action(lv_open_agent(L), action - 1, choices, n);
    if (r != VERVE_OK) return lv_fail_indexed(L, "split_action", r);
    lua_createtable(L, (int)n, 0);
    for (b = 0; b < n; ++b) {
        lua_pushinteger(L, (lua_Integer)choices[b] + 1);
        lua_rawseti(L, -2, (int)b + 1);
    }
    return 1;
}

int lv_join_action(lua_State* L) {
    uint32_t choices[VERVE_MAX_ACTION_BRANCHES], n, b, action = 0;
    verve_result r;
    luaL_checkudata(L, 1, LV_AGENT_MT);
    luaL_checktype(L, 2, LUA_TTABLE);
    n = (uint32_t)lua_rawlen(L, 2);
    if (n == 0 || n > VERVE_MAX_ACTION_BRANCHES)
        return luaL_error(L, "verve: join_action: give one choice per branch, 1 to %d of them (got %d)",
                          VERVE_MAX_ACTION_BRANCHES, (int)n);
    for (b = 0; b < n; ++b) {
        lua_rawgeti(L, 2, (int)b + 1);
        if (!lv_get_u32(L, -1, &choices[b]) || choices[b] == 0)
            return luaL_error(L, "verve: join_action: choice %d must be an integer from 1 (got %s)", (int)b + 1,
                              lua_type(L, -1) == LUA_TNUMBER ? lua_tostring(L, -1) : luaL_typename(L, -1));
        --choices[b];
        lua_pop(L, 1);
    }
    r = verve_agent_join_action(lv_open_agent(L), choices, n, &action);
    if (r != VERVE_OK) return lv_fail_indexed(L, "join_action", r);
    lua_pushinteger(L, (lua_Integer)action + 1);
    return 1;
}

int lv_continuous_action(lua_State* L) {
    float values[VERVE_MAX_CONTINUOUS_ACTIONS];
    verve_agent_desc d;
    verve_agent* a;
    uint32_t n = 0, i;
    verve_result r;
    luaL_checkudata(L, 1, LV_AGENT_MT);
    if (!lua_isnoneornil(L, 2)) luaL_checktype(L, 2, LUA_TTABLE);
    a = lv_open_agent(L);
    verve_agent_desc_init(&d, (uint32_t)sizeof d);
    r = verve_agent_get_desc(a, &d); /* the count the library wants: num_continuous_actions */
    if (r == VERVE_OK) {
        n = d.num_continuous_actions > VERVE_MAX_CONTINUOUS_ACTIONS ? VERVE_MAX_CONTINUOUS_ACTIONS
                                                                    : (uint32_t)d.num_continuous_actions;
        r = verve_agent_get_continuous_action(a, values, n);
    }
    if (r != VERVE_OK) return lv_fail(L, "continuous_action", r);
    /* The caller's table when given: a game loop reading every frame allocates nothing. Raw sets,
     * so no metamethod (no Lua code) runs. */
    if (lua_istable(L, 2)) lua_settop(L, 2);
    else lua_createtable(L, (int)n, 0);
    for (i = 0; i < n; ++i) {
        lua_pushnumber(L, (lua_Number)values[i]);
        lua_rawseti(L, -2, (int)i + 1);
    }
    return 1;
}

uint32_t lv_read_continuous_values(lua_State* L, int idx, const char* fn, float* out) {
    size_t n, i;
    if (lua_type(L, idx) != LUA_TTABLE)
        return (uint32_t)luaL_error(L, "verve: %s: continuous values must be a list of numbers like {0.5, -1}", fn);
    n = lua_rawlen(L, idx);
    if (n > VERVE_MAX_CONTINUOUS_ACTIONS)
        return (uint32_t)luaL_error(L, "verve: %s: %d continuous values; an agent has at most %d", fn, (int)n,
                                    VERVE_MAX_CONTINUOUS_ACTIONS);
    for (i = 0; i < n; ++i) {
        lua_rawgeti(L, idx, (int)i + 1);
        if (lua_type(L, -1) != LUA_TNUMBER)
            return (uint32_t)luaL_error(L, "verve: %s: continuous value %d must be a number", fn, (int)i + 1);
        out[i] = lv_to_float(lua_tonumber(L, -1));
        lua_pop(L, 1);
    }
    return (uint32_t)n;
}
