/* lua_warnings.h - verve.warnings(): libverve's log warnings, read from Lua. */
#ifndef VERVE_LUA_WARNINGS_H
#define VERVE_LUA_WARNINGS_H

#include <lua.h>

/* Installs the log hook that collects warnings (bindings/shared/warning_queue.h); luaopen_verve
 * calls it, before any agent exists. Returns 1 if installed. */
int lv_install_warnings(void);

/* verve.warnings() -> list of messages since the previous call (oldest first, possibly empty);
 * nil and a message when libverve's log hook could not be installed. */
int lv_warnings(lua_State* L);

#endif
