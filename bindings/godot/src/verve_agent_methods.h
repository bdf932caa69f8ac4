/* verve_agent_methods.h - the methods of the VerveAgent class, in NativeScript's calling form. */
#ifndef VERVE_AGENT_METHODS_H
#define VERVE_AGENT_METHODS_H

#include "gd_call.h"

/* Frees the agent a VerveAgent instance holds (its destructor). */
void vg_agent_destroy(void* instance);

#define VG_DECLARE(name) \
    godot_variant vg_##name(godot_object* object, void* method_data, void* user_data, int argc, godot_variant** argv);
VG_DECLARE(create)
VG_DECLARE(load)
VG_DECLARE(load_bytes)
VG_DECLARE(save)
VG_DECLARE(save_bytes)
VG_DECLARE(update)
VG_DECLARE(update_masked)
VG_DECLARE(update_demonstrated)
VG_DECLARE(update_demonstrated_continuous)
VG_DECLARE(teach)
VG_DECLARE(end_episode)
VG_DECLARE(truncate_episode)
VG_DECLARE(reset_short_term_memory)
VG_DECLARE(get_options)
VG_DECLARE(get_default_options)
VG_DECLARE(get_value)
VG_DECLARE(get_td_error)
VG_DECLARE(get_rbf_count)
VG_DECLARE(get_action_probabilities)
VG_DECLARE(split_action) /* verve_action_methods.c */
VG_DECLARE(join_action)
VG_DECLARE(get_continuous_action)
VG_DECLARE(get_stats)
VG_DECLARE(sample_values)
VG_DECLARE(has_agent)
VG_DECLARE(close)
VG_DECLARE(get_last_error)
#undef VG_DECLARE

/* The `learning` property. */
void vg_set_learning(godot_object* object, void* method_data, void* user_data, godot_variant* value);
godot_variant vg_get_learning(godot_object* object, void* method_data, void* user_data);
/* The `greedy` property: false samples each action with its probability (learning explores),
 * true always plays the most probable one (a shipped, frozen NPC). Per agent, not saved. */
void vg_set_greedy(godot_object* object, void* method_data, void* user_data, godot_variant* value);
godot_variant vg_get_greedy(godot_object* object, void* method_data, void* user_data);

#endif
