/* lua_descriptor.h - agent descriptors as Lua tables (lua_descriptor.c). */
#ifndef VERVE_LUA_DESCRIPTOR_H
#define VERVE_LUA_DESCRIPTOR_H

#include <lua.h>
#include <verve_c.h>

/* The table at idx into d, over the library's defaults; a Lua error naming the first wrong field. */
void lv_read_desc(lua_State* L, int idx, verve_agent_desc* d);
/* The value count of discrete sensor i (0-based, below d->num_discrete_sensors). */
uint32_t lv_discrete_count(const verve_agent_desc* d, uint32_t i);
/* Pushes d as a table that lv_read_desc reads back to the same descriptor. */
void lv_push_desc(lua_State* L, const verve_agent_desc* d);

#endif
