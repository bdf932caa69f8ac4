/* action_choices.h - how many flags an action mask holds and how many values the policy's
 * probabilities have: one per action with one action set, one per choice of each branch with
 * action branches (verve_c.h, verve_agent_desc V6). Shared by the C bindings (Lua, Godot). */
#ifndef VERVE_BINDINGS_ACTION_CHOICES_H
#define VERVE_BINDINGS_ACTION_CHOICES_H

#include <stdint.h>

#include <verve_c.h>

static inline uint32_t vb_action_choices(const verve_agent_desc* d) {
    uint32_t i, sum = 0;
    if (d->num_action_branches == 0) return d->num_actions;
    for (i = 0; i < d->num_action_branches && i < VERVE_MAX_ACTION_BRANCHES; ++i) sum += d->action_branches[i];
    return sum;
}

#endif
