/* lua_shared.h - what the module's source files share (verve_lua.c defines these): the agent
 * userdata, observations read from tables, errors and the type registry. */
#ifndef VERVE_LUA_SHARED_H
#define VERVE_LUA_SHARED_H

#include <stdint.h>

#include <lauxlib.h>
#include <lua.h>
#include <verve_c.h>

#define LV_AGENT_MT "verve.agent"

typedef struct lv_agent {
    verve_agent* handle; /* NULL once closed */
} lv_agent;

typedef struct lv_obs {
    int32_t discrete[VERVE_MAX_SENSORS]; /* 0-based, as the C ABI wants them */
    float continuous[VERVE_MAX_SENSORS];
    uint32_t n_discrete;
    uint32_t n_continuous;
} lv_obs;

/* "verve: <fn>: <verve_last_error()> [<result name>]" (and, indexed, a note on 1-based indices). */
int lv_fail(lua_State* L, const char* fn, verve_result r);
int lv_fail_indexed(lua_State* L, const char* fn, verve_result r);
float lv_to_float(lua_Number n);
/* The non-negative integer at idx that fits 32 bits, else 0. */
int lv_get_u32(lua_State* L, int idx, uint32_t* out);
/* The native handle of the agent at index 1 (an error if closed): fetch it last, after every Lua
 * input is read (a metamethod or a finalizer may close the agent). */
verve_agent* lv_open_agent(lua_State* L);
/* {discrete = {...}, continuous = {...}} at idx (nil: no sensors), values shifted to 0-based. */
void lv_read_obs(lua_State* L, int idx, const char* fn, int raw, lv_obs* o);
/* Refuses keys other than `allowed` (a NULL-terminated list) in the table at idx: a typo must not
 * pass silently. */
void lv_check_keys(lua_State* L, int idx, const char* const* allowed, const char* fn, const char* what);
/* A metatable `name` with methods as __index and the metamethods in `meta`. */
void lv_register_type(lua_State* L, const char* name, const luaL_Reg* meta, const luaL_Reg* methods);

#endif
