/* lua_recording.c - recordings of demonstrated steps in Lua (lua_recording.h). Actions are 1-based
 * here, as everywhere in the module. */
#include <stdlib.h>

#include <lauxlib.h>

#include "lua_actions.h"
#include "lua_recording.h"
#include "lua_shared.h"

#define LV_RECORDING_MT "verve.recording"

typedef struct lv_recording {
    verve_recording* handle; /* NULL once closed */
} lv_recording;

static lv_recording* lv_push_recording(lua_State* L) {
    lv_recording* ud = (lv_recording*)lua_newuserdata(L, sizeof *ud);
    ud->handle = NULL; /* set only after the C call succeeds */
    luaL_setmetatable(L, LV_RECORDING_MT);
    return ud;
}

/* The native handle of the recording at idx (an error if closed); fetched after every Lua input. */
static verve_recording* lv_open_recording(lua_State* L, int idx) {
    lv_recording* ud = (lv_recording*)luaL_checkudata(L, idx, LV_RECORDING_MT);
    if (!ud->handle) luaL_error(L, "verve: the recording is closed");
    return ud->handle;
}

int lv_new_recording(lua_State* L) {
    lv_recording* ud;
    verve_result r;
    luaL_checkudata(L, 1, LV_AGENT_MT);
    ud = lv_push_recording(L);
    r = verve_recording_create(lv_open_agent(L), &ud->handle);
    if (r != VERVE_OK) return lv_fail(L, "recording", r);
    return 1;
}

int lv_load_recording(lua_State* L) {
    const char* path = luaL_checkstring(L, 1);
    lv_recording* ud = lv_push_recording(L);
    verve_result r = verve_recording_load(path, &ud->handle);
    if (r != VERVE_OK) return lv_fail(L, "load_recording", r);
    return 1;
}

int lv_load_recording_string(lua_State* L) {
    size_t size = 0;
    const char* data = luaL_checklstring(L, 1, &size);
    lv_recording* ud = lv_push_recording(L);
    verve_result r = verve_recording_load_memory(data, size, &ud->handle);
    if (r != VERVE_OK) return lv_fail(L, "load_recording_string", r);
    return 1;
}

/* rec:add_step(reward, obs, dt, action) */
static int lv_add_step(lua_State* L) {
    float reward, dt;
    uint32_t action = 0;
    lv_obs o;
    verve_result r;
    luaL_checkudata(L, 1, LV_RECORDING_MT);
    reward = lv_to_float(luaL_checknumber(L, 2));
    dt = lv_to_float(luaL_checknumber(L, 4));
    if (!lv_get_u32(L, 5, &action) || action == 0)
        return luaL_error(L, "verve: add_step: action must be an integer from 1 to the number of actions");
    lv_read_obs(L, 3, "add_step", 0, &o);
    r = verve_recording_add_step(lv_open_recording(L, 1), reward, o.discrete, o.n_discrete, o.continuous,
                                 o.n_continuous, dt, action - 1);
    if (r != VERVE_OK) return lv_fail_indexed(L, "add_step", r);
    return 0;
}

/* rec:add_step_continuous(reward, obs, dt, action, values) */
static int lv_add_step_continuous(lua_State* L) {
    float reward, dt, values[VERVE_MAX_CONTINUOUS_ACTIONS];
    uint32_t action = 0, count;
    lv_obs o;
    verve_result r;
    luaL_checkudata(L, 1, LV_RECORDING_MT);
    reward = lv_to_float(luaL_checknumber(L, 2));
    dt = lv_to_float(luaL_checknumber(L, 4));
    if (!lv_get_u32(L, 5, &action) || action == 0)
        return luaL_error(L, "verve: add_step_continuous: action must be an integer from 1 to the number of actions");
    count = lv_read_continuous_values(L, 6, "add_step_continuous", values);
    lv_read_obs(L, 3, "add_step_continuous", 0, &o);
    r = verve_recording_add_step_continuous(lv_open_recording(L, 1), reward, o.discrete, o.n_discrete, o.continuous,
                                            o.n_continuous, dt, action - 1, values, count);
    if (r != VERVE_OK) return lv_fail_indexed(L, "add_step_continuous", r);
    return 0;
}

static int lv_add_end_episode(lua_State* L) {
    float reward = lv_to_float(luaL_checknumber(L, 2));
    verve_result r = verve_recording_add_end_episode(lv_open_recording(L, 1), reward);
    if (r != VERVE_OK) return lv_fail(L, "add_end_episode", r);
    return 0;
}

static int lv_add_truncation(lua_State* L) {
    float reward = lv_to_float(luaL_checknumber(L, 2));
    verve_result r = verve_recording_add_truncation(lv_open_recording(L, 1), reward);
    if (r != VERVE_OK) return lv_fail(L, "add_truncation", r);
    return 0;
}

static int lv_recording_size(lua_State* L) {
    uint64_t entries = 0;
    verve_result r = verve_recording_get_size(lv_open_recording(L, 1), &entries);
    if (r != VERVE_OK) return lv_fail(L, "size", r);
    lua_pushinteger(L, (lua_Integer)entries);
    return 1;
}

static int lv_recording_save(lua_State* L) {
    const char* path = luaL_checkstring(L, 2);
    verve_result r = verve_recording_save(lv_open_recording(L, 1), path);
    if (r != VERVE_OK) return lv_fail(L, "save", r);
    return 0;
}

/* The recording's file as a Lua string (for love.filesystem.write and the like). */
static int lv_recording_save_string(lua_State* L) {
    size_t size = 0;
    char* bytes;
    verve_result r = verve_recording_save_memory(lv_open_recording(L, 1), NULL, &size);
    if (r != VERVE_OK) return lv_fail(L, "save_string", r);
    bytes = (char*)malloc(size ? size : 1);
    if (!bytes) return luaL_error(L, "verve: save_string: out of memory");
    r = verve_recording_save_memory(lv_open_recording(L, 1), bytes, &size);
    if (r != VERVE_OK) {
        free(bytes);
        return lv_fail(L, "save_string", r);
    }
    lua_pushlstring(L, bytes, size); /* may raise: free first */
    free(bytes);
    return 1;
}

static int lv_recording_close(lua_State* L) {
    lv_recording* ud = (lv_recording*)luaL_checkudata(L, 1, LV_RECORDING_MT);
    verve_recording_destroy(ud->handle);
    ud->handle = NULL;
    return 0;
}

int lv_replay(lua_State* L) {
    verve_recording* rec;
    verve_result r;
    luaL_checkudata(L, 1, LV_AGENT_MT);
    rec = lv_open_recording(L, 2);
    r = verve_agent_replay(lv_open_agent(L), rec);
    if (r != VERVE_OK) return lv_fail(L, "replay", r);
    return 0;
}

static const luaL_Reg lv_recording_methods[] = {
    {"add_step", lv_add_step},
    {"add_step_continuous", lv_add_step_continuous},
    {"add_end_episode", lv_add_end_episode},
    {"add_truncation", lv_add_truncation},
    {"size", lv_recording_size},
    {"save", lv_recording_save},
    {"save_string", lv_recording_save_string},
    {"close", lv_recording_close},
    {NULL, NULL},
};

static const luaL_Reg lv_recording_meta[] = {
    {"__gc", lv_recording_close},
    {"__close", lv_recording_close},
    {NULL, NULL},
};

void lv_register_recordings(lua_State* L) { lv_register_type(L, LV_RECORDING_MT, lv_recording_meta, lv_recording_methods); }
