/* lua_warnings.c - verve.warnings(): see lua_warnings.h. */
#include "lua_warnings.h"

#include <lauxlib.h>

#include <verve_c.h>

#include "warning_queue.h"

typedef struct lv_list {
    lua_State* L;
    int table;
    int n;
} lv_list;

static void lv_append(void* user, const char* message) {
    lv_list* list = (lv_list*)user;
    lua_pushstring(list->L, message);
    lua_rawseti(list->L, list->table, ++list->n);
}

int lv_install_warnings(void) { return vw_install(); }

int lv_warnings(lua_State* L) {
    lv_list list;
    if (!vw_install()) {
        lua_pushnil(L);
        lua_pushfstring(L, "verve.warnings: libverve's log hook could not be installed: %s", verve_last_error());
        return 2;
    }
    lua_newtable(L);
    list.L = L;
    list.table = lua_gettop(L);
    list.n = 0;
    vw_take(lv_append, &list);
    return 1;
}
