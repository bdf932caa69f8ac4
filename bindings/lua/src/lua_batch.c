/* lua_batch.c - many agents in one call (docs/crowds.md): verve.batch and batch:update, packing
 * the Lua tables into the arrays verve_batch_update reads (grown as crowds grow, reused after). */
#include <stdlib.h>
#include <string.h>

#include <verve_c.h>

#include "lua_actions.h"
#include "lua_batch.h"
#include "lua_compat.h"
#include "lua_shared.h"

#define LV_BATCH_MT "verve.batch"

/* A batch and the packed arrays its update reads and writes. */
typedef struct lv_batch {
    verve_batch* handle; /* NULL once closed */
    uint32_t capacity;   /* agents the arrays hold */
    verve_agent** agents;
    float* rewards;
    int32_t* discrete;   /* VERVE_MAX_SENSORS per agent */
    float* continuous;   /* VERVE_MAX_SENSORS per agent */
    uint32_t* actions;
    uint32_t* demonstrated; /* the optional demonstrated actions (0-based, VERVE_AGENT_CHOOSES) */
    float* shown;           /* ... their continuous actions, VERVE_MAX_CONTINUOUS_ACTIONS per agent */
    uint32_t* shown_offsets;
} lv_batch;

static lv_batch* lv_check_batch(lua_State* L) {
    lv_batch* ud = (lv_batch*)luaL_checkudata(L, 1, LV_BATCH_MT);
    if (!ud->handle) luaL_error(L, "verve: the batch is closed");
    return ud;
}

static void lv_batch_free_arrays(lv_batch* b) {
    free(b->agents);
    free(b->rewards);
    free(b->discrete);
    free(b->continuous);
    free(b->actions);
    free(b->demonstrated);
    free(b->shown);
    free(b->shown_offsets);
    b->demonstrated = NULL;
    b->shown = NULL;
    b->shown_offsets = NULL;
    b->agents = NULL;
    b->rewards = NULL;
    b->discrete = NULL;
    b->continuous = NULL;
    b->actions = NULL;
    b->capacity = 0;
}

/* verve.batch{workers = n}: n threads (the caller included); 0 or absent: one per core. */
int lv_new_batch(lua_State* L) {
    static const char* const keys[] = {"workers", NULL};
    verve_batch_desc d;
    lv_batch* ud;
    verve_result r;
    verve_batch_desc_default(&d);
    if (!lua_isnoneornil(L, 1)) {
        luaL_checktype(L, 1, LUA_TTABLE);
        lv_check_keys(L, 1, keys, "batch", "batch");
        lua_getfield(L, 1, "workers");
        if (!lua_isnil(L, -1) && !lv_get_u32(L, -1, &d.worker_count))
            luaL_error(L, "verve: batch: workers must be a non-negative integer");
        lua_pop(L, 1);
    }
    ud = (lv_batch*)lua_newuserdata(L, sizeof *ud);
    memset(ud, 0, sizeof *ud);
    luaL_setmetatable(L, LV_BATCH_MT);
    r = verve_batch_create(&d, &ud->handle);
    if (r != VERVE_OK) return lv_fail(L, "batch", r);
    return 1;
}

static void lv_batch_reserve(lua_State* L, lv_batch* b, uint32_t n) {
    if (n <= b->capacity) return;
    lv_batch_free_arrays(b);
    b->agents = (verve_agent**)malloc(n * sizeof *b->agents);
    b->rewards = (float*)malloc(n * sizeof *b->rewards);
    b->discrete = (int32_t*)malloc((size_t)n * VERVE_MAX_SENSORS * sizeof *b->discrete);
    b->continuous = (float*)malloc((size_t)n * VERVE_MAX_SENSORS * sizeof *b->continuous);
    b->actions = (uint32_t*)malloc(n * sizeof *b->actions);
    b->demonstrated = (uint32_t*)malloc(n * sizeof *b->demonstrated);
    b->shown = (float*)malloc((size_t)n * VERVE_MAX_CONTINUOUS_ACTIONS * sizeof *b->shown);
    b->shown_offsets = (uint32_t*)malloc(n * sizeof *b->shown_offsets);
    if (!b->agents || !b->rewards || !b->discrete || !b->continuous || !b->actions || !b->demonstrated || !b->shown ||
        !b->shown_offsets) {
        lv_batch_free_arrays(b);
        luaL_error(L, "verve: update: out of memory for %d agents", (int)n);
    }
    b->capacity = n;
}

/* continuous_actions (argument 8) into b->shown at b->shown_offsets: each shown agent's list,
 * which must hold its num_continuous_actions values (the library reads that many at the offset, so
 * a shorter list would read the next agent's). Returns the values' total. */
static uint32_t lv_read_shown_values(lua_State* L, lv_batch* b, uint32_t n) {
    uint32_t i, total = 0;
    luaL_checktype(L, 8, LUA_TTABLE);
    for (i = 0; i < n; ++i) {
        b->shown_offsets[i] = total;
        if (b->demonstrated[i] == VERVE_AGENT_CHOOSES) continue;
        lua_rawgeti(L, 8, (int)i + 1);
        if (lua_isnil(L, -1)) {
            luaL_error(L, "verve: update: agents[%d] is shown an action: continuous_actions[%d] must list its "
                       "continuous actions ({} for none)", (int)i + 1, (int)i + 1);
        } else {
            verve_agent_desc d;
            const uint32_t count = lv_read_continuous_values(L, lua_gettop(L), "update", b->shown + total);
            verve_agent_desc_init(&d, sizeof d);
            if (verve_agent_get_desc(b->agents[i], &d) != VERVE_OK || d.num_continuous_actions != count)
                luaL_error(L, "verve: update: continuous_actions[%d] has %d values, agents[%d] has %d continuous actions",
                           (int)i + 1, (int)count, (int)i + 1, (int)d.num_continuous_actions);
            total += count;
        }
        lua_pop(L, 1);
    }
    return total;
}

/* batch:update(agents, rewards, observations, dt [, actions [, demonstrated [, continuous_actions]]]):
 * agents[i] gets rewards[i] and observations[i] (as agent:update takes them); returns the actions
 * (written into `actions` when given, so a game loop allocates nothing). `demonstrated[i]`, when
 * given, is the action (from 1) the host took for agents[i] (agent:update_demonstrated), or false
 * for the agent's own choice; `continuous_actions[i]` the continuous actions it played, {v1, ...}
 * (agent:update_demonstrated_continuous), read for the agents shown an action only. Any bad input
 * refuses the whole call. */
static int lv_batch_update(lua_State* L) {
    lv_batch* b = lv_check_batch(L);
    float dt = lv_to_float(luaL_checknumber(L, 5));
    uint32_t n, i, nd = 0, nc = 0;
    verve_result r;
    luaL_checktype(L, 2, LUA_TTABLE);
    luaL_checktype(L, 3, LUA_TTABLE);
    luaL_checktype(L, 4, LUA_TTABLE);
    n = (uint32_t)lua_rawlen(L, 2);
    if (lua_rawlen(L, 3) != n || lua_rawlen(L, 4) != n)
        luaL_error(L, "verve: update: %d agents, %d rewards and %d observations: the counts must match", (int)n,
                   (int)lua_rawlen(L, 3), (int)lua_rawlen(L, 4));
    lv_batch_reserve(L, b, n);
    for (i = 0; i < n; ++i) {
        lv_agent* a;
        lv_obs o;
        lua_rawgeti(L, 2, (int)i + 1);
        a = (lv_agent*)luaL_testudata(L, -1, LV_AGENT_MT);
        if (!a || !a->handle) luaL_error(L, "verve: update: agents[%d] is not an open agent", (int)i + 1);
        b->agents[i] = a->handle;
        lua_pop(L, 1);
        lua_rawgeti(L, 3, (int)i + 1);
        if (lua_type(L, -1) != LUA_TNUMBER) luaL_error(L, "verve: update: rewards[%d] must be a number", (int)i + 1);
        b->rewards[i] = lv_to_float(lua_tonumber(L, -1));
        lua_pop(L, 1);
        lua_rawgeti(L, 4, (int)i + 1);
        /* Raw: a metamethod could close an agent already listed, or the batch and its arrays. */
        lv_read_obs(L, lua_gettop(L), "update", 1, &o);
        lua_pop(L, 1);
        memcpy(b->discrete + nd, o.discrete, o.n_discrete * sizeof *o.discrete);
        memcpy(b->continuous + nc, o.continuous, o.n_continuous * sizeof *o.continuous);
        nd += o.n_discrete;
        nc += o.n_continuous;
    }
    if (!lua_isnoneornil(L, 7)) {
        luaL_checktype(L, 7, LUA_TTABLE);
        for (i = 0; i < n; ++i) {
            uint32_t action = 0;
            lua_rawgeti(L, 7, (int)i + 1);
            if (lua_isnil(L, -1) || (lua_isboolean(L, -1) && !lua_toboolean(L, -1))) {
                b->demonstrated[i] = VERVE_AGENT_CHOOSES;
            } else if (lv_get_u32(L, -1, &action) && action > 0) {
                b->demonstrated[i] = action - 1;
            } else {
                luaL_error(L, "verve: update: demonstrated[%d] must be an action from 1, or false (got %s)", (int)i + 1,
                           luaL_typename(L, -1));
            }
            lua_pop(L, 1);
        }
        if (lua_isnoneornil(L, 8)) {
            r = verve_batch_update_demonstrated(b->handle, b->agents, n, b->rewards, b->discrete, NULL, nd,
                                                b->continuous, NULL, nc, dt, b->demonstrated, b->actions, NULL);
        } else {
            const uint32_t total = lv_read_shown_values(L, b, n);
            r = verve_batch_update_demonstrated_continuous(b->handle, b->agents, n, b->rewards, b->discrete, NULL, nd,
                                                           b->continuous, NULL, nc, dt, b->demonstrated, b->shown,
                                                           b->shown_offsets, total, b->actions, NULL);
        }
    } else {
        r = verve_batch_update(b->handle, b->agents, n, b->rewards, b->discrete, NULL, nd, b->continuous, NULL, nc, dt,
                               b->actions, NULL);
    }
    if (r != VERVE_OK) return lv_fail_indexed(L, "update", r);
    if (lua_istable(L, 6)) {
        lua_pushvalue(L, 6);
    } else {
        lua_createtable(L, (int)n, 0);
    }
    for (i = 0; i < n; ++i) {
        lua_pushinteger(L, (lua_Integer)b->actions[i] + 1);
        lua_rawseti(L, -2, (int)i + 1);
    }
    return 1;
}

static int lv_batch_workers(lua_State* L) {
    uint32_t n = 0;
    verve_result r = verve_batch_get_worker_count(lv_check_batch(L)->handle, &n);
    if (r != VERVE_OK) return lv_fail(L, "workers", r);
    lua_pushinteger(L, (lua_Integer)n);
    return 1;
}

static int lv_batch_close(lua_State* L) {
    lv_batch* ud = (lv_batch*)luaL_checkudata(L, 1, LV_BATCH_MT);
    verve_batch_destroy(ud->handle);
    ud->handle = NULL;
    lv_batch_free_arrays(ud);
    return 0;
}

static const luaL_Reg lv_batch_methods[] = {
    {"update", lv_batch_update},
    {"workers", lv_batch_workers},
    {"close", lv_batch_close},
    {NULL, NULL},
};

static const luaL_Reg lv_batch_meta[] = {
    {"__gc", lv_batch_close},
    {"__close", lv_batch_close},
    {NULL, NULL},
};

void lv_register_batches(lua_State* L) { lv_register_type(L, LV_BATCH_MT, lv_batch_meta, lv_batch_methods); }
