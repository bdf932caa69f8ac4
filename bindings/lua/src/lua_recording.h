/* lua_recording.h - recordings of demonstrated steps (docs/teaching.md, "Recordings") in Lua:
 * verve.recording(agent), verve.load_recording(path), verve.load_recording_string(s) and
 * agent:replay(recording). */
#ifndef VERVE_LUA_RECORDING_H
#define VERVE_LUA_RECORDING_H

#include <lua.h>

/* Registers the recording type; luaopen_verve calls it. */
void lv_register_recordings(lua_State* L);
int lv_new_recording(lua_State* L);
int lv_load_recording(lua_State* L);
int lv_load_recording_string(lua_State* L);
/* agent:replay(recording) */
int lv_replay(lua_State* L);

#endif
