/* lua_actions.h - actions beyond one discrete set in Lua.
 * Action branches (verve_c.h, verve_agent_desc V6): the descriptor's action_branches = {3, 3, 2},
 * and agent:split_action(a) / agent:join_action({c1, c2, c3}), which count actions and choices from
 * 1 like every action in this module.
 * Continuous actions (V7): the descriptor's continuous_actions = 2, and agent:continuous_action([t])
 * with the latest update's values in [-1, 1]. */
#ifndef VERVE_LUA_ACTIONS_H
#define VERVE_LUA_ACTIONS_H

#include <lua.h>
#include <verve_c.h>

/* The most flags in a mask / values in the probabilities: 4096 combined actions, plus one per
 * branch of a single choice (their sum can exceed the product by as much). */
#define LV_MAX_ACTIONS 4096 /* the library's limit on num_actions */
#define LV_MAX_CHOICES (LV_MAX_ACTIONS + VERVE_MAX_ACTION_BRANCHES)

/* action_branches = {...} on top of the stack into d. */
void lv_read_action_branches(lua_State* L, verve_agent_desc* d);
/* continuous_actions = n on top of the stack into d (0 to VERVE_MAX_CONTINUOUS_ACTIONS). */
void lv_read_continuous_actions(lua_State* L, verve_agent_desc* d);
/* After the whole descriptor is read: with branches or continuous actions and no `actions` given,
 * num_actions is 0 (the library sets it to the branches' product, or to 1). */
void lv_finish_actions(verve_agent_desc* d, int actions_given);
/* Pushes d's action_branches as a list (empty with one action set). */
void lv_push_action_branches(lua_State* L, const verve_agent_desc* d);
/* agent:split_action(a) -> {c1, c2, ...}; agent:join_action({c1, c2, ...}) -> a. */
int lv_split_action(lua_State* L);
int lv_join_action(lua_State* L);
/* agent:continuous_action([t]) -> t: the latest update's continuous actions as t[1..n], filled into
 * t when given (nothing allocated per frame), else a new list; {} without continuous actions. */
int lv_continuous_action(lua_State* L);
/* A teacher's continuous actions at idx, a list of numbers {v1, v2, ...} read raw (no metamethod
 * runs), into out (room for VERVE_MAX_CONTINUOUS_ACTIONS); returns the count. A non-list, a non-number
 * or more values than any agent has is a Lua error naming `fn`; the library checks count and range. */
uint32_t lv_read_continuous_values(lua_State* L, int idx, const char* fn, float* out);

#endif
