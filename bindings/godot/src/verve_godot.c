/* verve_godot.c - the GDNative entry points: Godot calls godot_gdnative_init when it loads the
 * library and godot_nativescript_init to learn its classes. One class, VerveAgent (a Reference:
 * freed, with its agent, when the last reference goes), whose methods are in
 * verve_agent_methods.c. */
#include <stdlib.h>

#include "verve_agent_methods.h"

typedef godot_variant (*vg_method_fn)(godot_object*, void*, void*, int, godot_variant**);

typedef struct vg_arg_info {
    const char* name;
    godot_variant_type type;
} vg_arg_info;

#define VG_MAX_ARGS 5 /* the most any method takes (update_masked) */

typedef struct vg_method_info {
    const char* name;
    vg_method_fn fn;
    const char* doc;
    int argc;
    vg_arg_info args[VG_MAX_ARGS];
} vg_method_info;

#define VG_NIL GODOT_VARIANT_TYPE_NIL /* any type */
static const vg_method_info vg_methods[] = {
    {"create", vg_create, "Creates the agent from an options Dictionary (missing keys: defaults). -> bool", 1,
     {{"options", GODOT_VARIANT_TYPE_DICTIONARY}}},
    {"load", vg_load, "Replaces the agent with one loaded from a save file (res://, user:// or a path). -> bool", 1,
     {{"path", GODOT_VARIANT_TYPE_STRING}}},
    {"load_bytes", vg_load_bytes, "Replaces the agent with one loaded from save_bytes() data. -> bool", 1,
     {{"data", GODOT_VARIANT_TYPE_POOL_BYTE_ARRAY}}},
    {"save", vg_save, "Saves the agent to a file, atomically. -> bool", 1, {{"path", GODOT_VARIANT_TYPE_STRING}}},
    {"save_bytes", vg_save_bytes, "The agent's save as bytes (null on error). -> PoolByteArray", 0, {{0}}},
    {"update", vg_update,
     "One step: the reward the previous action earned, the sensors now, seconds since the last step. "
     "-> the action, 0 .. actions-1 (-1 on error)",
     4,
     {{"reward", GODOT_VARIANT_TYPE_REAL},
      {"discrete", GODOT_VARIANT_TYPE_POOL_INT_ARRAY},
      {"continuous", GODOT_VARIANT_TYPE_POOL_REAL_ARRAY},
      {"dt", GODOT_VARIANT_TYPE_REAL}}},
    {"update_masked", vg_update_masked,
     "update() choosing only among the actions the mask allows this step (one 0/1 per action, at least one 1); "
     "a masked action is never chosen and gets no credit. -> the action (-1 on error)",
     5,
     {{"reward", GODOT_VARIANT_TYPE_REAL},
      {"discrete", GODOT_VARIANT_TYPE_POOL_INT_ARRAY},
      {"continuous", GODOT_VARIANT_TYPE_POOL_REAL_ARRAY},
      {"dt", GODOT_VARIANT_TYPE_REAL},
      {"mask", GODOT_VARIANT_TYPE_POOL_INT_ARRAY}}},
    {"end_episode", vg_end_episode, "Ends a trial with its final reward. -> bool", 1,
     {{"final_reward", GODOT_VARIANT_TYPE_REAL}}},
    {"truncate_episode", vg_truncate_episode,
     "Cuts a trial off at a time limit: learns the last reward, the trial could have gone on. -> bool", 1,
     {{"reward", GODOT_VARIANT_TYPE_REAL}}},
    {"reset_short_term_memory", vg_reset_short_term_memory,
     "Forgets the previous step and the eligibility traces (a teleport, a new life), keeps what was learned. -> bool",
     0, {{0}}},
    {"get_options", vg_get_options, "The agent's options, as create() takes them. -> Dictionary", 0, {{0}}},
    {"get_default_options", vg_get_default_options, "libverve's default options. -> Dictionary", 0, {{0}}},
    {"get_value", vg_get_value, "V(s) of the latest observation. -> float", 0, {{0}}},
    {"get_td_error", vg_get_td_error, "TD error of the latest step. -> float", 0, {{0}}},
    {"get_rbf_count", vg_get_rbf_count, "Radial basis functions created so far. -> int", 0, {{0}}},
    {"get_action_probabilities", vg_get_action_probabilities,
     "The policy's probability of each action at the latest update (what sampling drew from). -> PoolRealArray",
     0, {{0}}},
    {"get_stats", vg_get_stats, "steps, rbf_count, live_traces, value, td_error and planning figures. -> Dictionary",
     0, {{0}}},
    {"sample_values", vg_sample_values,
     "V over 1 or 2 swept sensors ({\"kind\", \"index\", \"samples\"} each), the others held at the base "
     "observation; axis 0 varies fastest. -> PoolRealArray",
     3,
     {{"axes", GODOT_VARIANT_TYPE_ARRAY},
      {"base_discrete", GODOT_VARIANT_TYPE_POOL_INT_ARRAY},
      {"base_continuous", GODOT_VARIANT_TYPE_POOL_REAL_ARRAY}}},
    {"has_agent", vg_has_agent, "Whether an agent was created or loaded (and not closed). -> bool", 0, {{0}}},
    {"close", vg_close, "Frees the agent now instead of with the last reference.", 0, {{0}}},
    {"get_last_error", vg_get_last_error, "The error of the latest failed call, \"\" after a success. -> String", 0,
     {{0}}},
};
#define VG_METHOD_COUNT (sizeof vg_methods / sizeof vg_methods[0])
#define VG_CLASS "VerveAgent"

static void* vg_construct(godot_object* object, void* method_data) {
    (void)object, (void)method_data;
    return calloc(1, sizeof(vg_agent)); /* no agent until create() or load() */
}

static void vg_destruct(godot_object* object, void* method_data, void* user_data) {
    (void)object, (void)method_data;
    if (user_data) verve_agent_destroy(((vg_agent*)user_data)->handle);
    free(user_data);
}

static void vg_document(void* handle, const vg_method_info* m) {
    godot_method_arg args[VG_MAX_ARGS];
    godot_string doc;
    int i;
    if (!vg_ns11) return;
    for (i = 0; i < m->argc; ++i) {
        args[i].name = vg_string(m->args[i].name);
        args[i].type = m->args[i].type;
        args[i].hint = GODOT_PROPERTY_HINT_NONE;
        vg_core->godot_string_new(&args[i].hint_string);
    }
    vg_ns11->godot_nativescript_set_method_argument_information(handle, VG_CLASS, m->name, m->argc, args);
    for (i = 0; i < m->argc; ++i) {
        vg_core->godot_string_destroy(&args[i].name);
        vg_core->godot_string_destroy(&args[i].hint_string);
    }
    doc = vg_string(m->doc);
    vg_ns11->godot_nativescript_set_method_documentation(handle, VG_CLASS, m->name, doc);
    vg_core->godot_string_destroy(&doc);
}

VG_EXPORT void godot_gdnative_init(godot_gdnative_init_options* options) {
    if (!vg_api_init(options->api_struct))
        options->report_loading_error(options->gd_native_library, "verve: this Godot has no NativeScript");
}

VG_EXPORT void godot_gdnative_terminate(godot_gdnative_terminate_options* options) {
    (void)options;
}

VG_EXPORT void godot_nativescript_init(void* handle) {
    godot_instance_create_func create = {vg_construct, NULL, NULL};
    godot_instance_destroy_func destroy = {vg_destruct, NULL, NULL};
    godot_property_attributes learning;
    godot_property_set_func set_learning = {vg_set_learning, NULL, NULL};
    godot_property_get_func get_learning = {vg_get_learning, NULL, NULL};
    godot_property_set_func set_greedy = {vg_set_greedy, NULL, NULL};
    godot_property_get_func get_greedy = {vg_get_greedy, NULL, NULL};
    godot_method_attributes attributes = {GODOT_METHOD_RPC_MODE_DISABLED};
    size_t i;
    if (!vg_ns) return;
    vg_ns->godot_nativescript_register_class(handle, VG_CLASS, "Reference", create, destroy);
    for (i = 0; i < VG_METHOD_COUNT; ++i) {
        godot_instance_method method = {vg_methods[i].fn, NULL, NULL};
        vg_ns->godot_nativescript_register_method(handle, VG_CLASS, vg_methods[i].name, attributes, method);
        vg_document(handle, &vg_methods[i]);
    }
    learning.rset_type = GODOT_METHOD_RPC_MODE_DISABLED;
    learning.type = GODOT_VARIANT_TYPE_BOOL;
    learning.hint = GODOT_PROPERTY_HINT_NONE;
    vg_core->godot_string_new(&learning.hint_string);
    learning.usage = GODOT_PROPERTY_USAGE_NOEDITOR; /* a run-time switch: not in the inspector */
    learning.default_value = vg_variant_bool(1);
    vg_ns->godot_nativescript_register_property(handle, VG_CLASS, "learning", &learning, set_learning, get_learning);
    vg_core->godot_variant_destroy(&learning.default_value);
    learning.default_value = vg_variant_bool(0); /* `greedy`: the same kind of run-time switch */
    vg_ns->godot_nativescript_register_property(handle, VG_CLASS, "greedy", &learning, set_greedy, get_greedy);
    vg_core->godot_string_destroy(&learning.hint_string);
    vg_core->godot_variant_destroy(&learning.default_value);
}
