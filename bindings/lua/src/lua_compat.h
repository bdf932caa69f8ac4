/* lua_compat.h - the few Lua 5.4 API calls LuaJIT 2.1 (Lua 5.1 API) lacks.
 * LuaJIT 2.1 already has luaL_setfuncs, luaL_testudata and luaL_setmetatable. */
#ifndef VERVE_LUA_COMPAT_H
#define VERVE_LUA_COMPAT_H

#include <lauxlib.h>
#include <lua.h>
#include <math.h>

#if LUA_VERSION_NUM < 502
#  define lua_rawlen(L, i) lua_objlen((L), (i))
static inline int lua_absindex(lua_State* L, int idx) {
    return (idx > 0 || idx <= LUA_REGISTRYINDEX) ? idx : lua_gettop(L) + idx + 1;
}
#endif

/* The integer at idx, if it is a number with an exact integer value (no strings, no 1.5).
 * LuaJIT numbers are doubles, so it checks the value itself; Lua 5.4 converts 3.0 but not 3.5. */
static inline int lv_tointeger(lua_State* L, int idx, lua_Integer* out) {
    if (lua_type(L, idx) != LUA_TNUMBER) return 0;
#if LUA_VERSION_NUM >= 503
    {
        int isnum = 0;
        lua_Integer v = lua_tointegerx(L, idx, &isnum);
        if (!isnum) return 0;
        *out = v;
        return 1;
    }
#else
    {
        lua_Number n = lua_tonumber(L, idx);
        /* 2^53: beyond it a double no longer holds every integer. */
        if (n != floor(n) || n < -9007199254740992.0 || n > 9007199254740992.0) return 0;
        *out = (lua_Integer)n;
        return 1;
    }
#endif
}

#endif /* VERVE_LUA_COMPAT_H */
