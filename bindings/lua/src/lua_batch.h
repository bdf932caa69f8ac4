/* lua_batch.h - many agents in one call (docs/crowds.md) in Lua: verve.batch{workers = n} and
 * batch:update(agents, rewards, observations, dt [, actions [, demonstrated [, continuous_actions]]]). */
#ifndef VERVE_LUA_BATCH_H
#define VERVE_LUA_BATCH_H

#include <lua.h>

/* Registers the batch type; luaopen_verve calls it. */
void lv_register_batches(lua_State* L);
int lv_new_batch(lua_State* L);

#endif
