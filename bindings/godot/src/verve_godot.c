/* verve_godot.c - the GDNative entry points: Godot calls godot_gdnative_init when it loads the
 * library and godot_nativescript_init to learn its classes. Four classes, each a Reference (freed,
 * with what it holds, when the last reference goes): VerveAgent (verve_agent_methods.c),
 * VerveBrain (verve_brain_methods.c), VerveBatch (verve_batch_methods.c) and VerveRecording
 * (verve_recording_methods.c). */
#include <stdlib.h>

#include "verve_agent_methods.h"
#include "verve_batch_methods.h"
#include "verve_brain_methods.h"
#include "verve_recording_methods.h"
#include "verve_warnings.h"

typedef godot_variant (*vg_method_fn)(godot_object*, void*, void*, int, godot_variant**);

typedef struct vg_arg_info {
    const char* name;
    godot_variant_type type;
} vg_arg_info;

#define VG_MAX_ARGS 7 /* the most any method takes (update_demonstrated_continuous with its mask) */

typedef struct vg_method_info {
    const char* name;
    vg_method_fn fn;
    const char* doc;
    int argc;
    vg_arg_info args[VG_MAX_ARGS];
} vg_method_info;

#define VG_NIL GODOT_VARIANT_TYPE_NIL /* any type */
static const vg_method_info vg_agent_methods[] = {
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
     "update() choosing only among the actions the mask allows this step (one 0/1 per action, at least one 1; "
     "with action branches one per choice of each branch, branch after branch, at least one 1 in each); "
     "a masked action is never chosen and gets no credit. -> the action (-1 on error)",
     5,
     {{"reward", GODOT_VARIANT_TYPE_REAL},
      {"discrete", GODOT_VARIANT_TYPE_POOL_INT_ARRAY},
      {"continuous", GODOT_VARIANT_TYPE_POOL_REAL_ARRAY},
      {"dt", GODOT_VARIANT_TYPE_REAL},
      {"mask", GODOT_VARIANT_TYPE_POOL_INT_ARRAY}}},
    {"update_demonstrated", vg_update_demonstrated,
     "A demonstrated step (docs/teaching.md): as update(), but the player or a scripted AI took `action`; the agent "
     "learns from it and is pulled towards it. The optional mask (one 0/1 per action) must allow `action`. -> bool",
     6,
     {{"reward", GODOT_VARIANT_TYPE_REAL},
      {"discrete", GODOT_VARIANT_TYPE_POOL_INT_ARRAY},
      {"continuous", GODOT_VARIANT_TYPE_POOL_REAL_ARRAY},
      {"dt", GODOT_VARIANT_TYPE_REAL},
      {"action", GODOT_VARIANT_TYPE_INT},
      {"mask", GODOT_VARIANT_TYPE_POOL_INT_ARRAY}}},
    {"update_demonstrated_continuous", vg_update_demonstrated_continuous,
     "update_demonstrated() with the continuous actions the player or a scripted AI played too (one per "
     "continuous action, each in [-1, 1]; docs/teaching.md): the agent learns from them and is pulled towards them, "
     "and get_continuous_action() reads them back. -> bool",
     7,
     {{"reward", GODOT_VARIANT_TYPE_REAL},
      {"discrete", GODOT_VARIANT_TYPE_POOL_INT_ARRAY},
      {"continuous", GODOT_VARIANT_TYPE_POOL_REAL_ARRAY},
      {"dt", GODOT_VARIANT_TYPE_REAL},
      {"action", GODOT_VARIANT_TYPE_INT},
      {"continuous_action", GODOT_VARIANT_TYPE_POOL_REAL_ARRAY},
      {"mask", GODOT_VARIANT_TYPE_POOL_INT_ARRAY}}},
    {"replay", vg_replay,
     "Every entry of a VerveRecording into the agent, in order, as demonstrated steps and trial ends; the agent "
     "must have the recording's sensors and actions (else nothing is replayed). -> bool",
     1,
     {{"recording", GODOT_VARIANT_TYPE_OBJECT}}},
    {"teach", vg_teach,
     "A teacher's judgement in [-1, 1] (1 good, -1 bad) of what the agent did over the last 2.5 s; not a reward. "
     "The agent remembers its acts from its first judgement on (0 arms it). -> bool",
     1,
     {{"praise", GODOT_VARIANT_TYPE_REAL}}},
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
     "The policy's probability of each action at the latest update (what sampling drew from); with action "
     "branches one per choice of each branch, branch after branch, each branch summing to 1. -> PoolRealArray",
     0, {{0}}},
    {"split_action", vg_split_action,
     "The choice of each action branch (from 0) within a combined action; one value without branches. -> Array",
     1, {{"action", GODOT_VARIANT_TYPE_INT}}},
    {"join_action", vg_join_action,
     "The combined action of one choice per action branch (each from 0, branch 0 varying fastest); -1 on error. "
     "-> int",
     1, {{"choices", GODOT_VARIANT_TYPE_ARRAY}}},
    {"get_continuous_action", vg_get_continuous_action,
     "The continuous actions of the latest update (option \"continuous_actions\"), each in [-1, 1]: sampled "
     "around the policy's mean, or the mean itself when greedy; 0s before the first update. -> PoolRealArray",
     0, {{0}}},
    {"take_warnings", vg_take_warnings,
     "libverve's warnings since the previous call, oldest first (a reward clamped to [-1, 1], an RBF budget "
     "reached: once per agent each; also printed as they come). -> PoolStringArray",
     0, {{0}}},
    {"get_stats", vg_get_stats,
     "steps, rbf_count, live_traces, value, td_error, planning figures, rbf_budget_hits and clamped_rewards. "
     "-> Dictionary",
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

static const vg_method_info vg_brain_methods[] = {
    {"create", vg_brain_create,
     "Creates the brain from an options Dictionary, as VerveAgent.create() takes it. -> bool", 1,
     {{"options", GODOT_VARIANT_TYPE_DICTIONARY}}},
    {"load", vg_brain_load,
     "Replaces the brain with one loaded from a brain's or an agent's save file, XML or binary. -> bool", 1,
     {{"path", GODOT_VARIANT_TYPE_STRING}}},
    {"load_bytes", vg_brain_load_bytes, "Replaces the brain with one loaded from save bytes, XML or binary. -> bool",
     1, {{"data", GODOT_VARIANT_TYPE_POOL_BYTE_ARRAY}}},
    {"save", vg_brain_save, "Saves the brain (an agent save without short-term memory), atomically. -> bool", 1,
     {{"path", GODOT_VARIANT_TYPE_STRING}}},
    {"save_binary", vg_brain_save_binary, "save() in the compact binary format. -> bool", 1,
     {{"path", GODOT_VARIANT_TYPE_STRING}}},
    {"save_bytes", vg_brain_save_bytes, "The brain's save as bytes (null on error). -> PoolByteArray", 0, {{0}}},
    {"save_binary_bytes", vg_brain_save_binary_bytes, "save_bytes() in the compact binary format. -> PoolByteArray",
     0, {{0}}},
    {"create_body", vg_brain_create_body,
     "A new VerveAgent over this brain: its own short-term memory, learning into the brain's weights; it keeps "
     "the brain alive. -> VerveAgent (null on error)",
     0, {{0}}},
    {"get_rbf_count", vg_brain_get_rbf_count, "Radial basis functions the brain's bodies have created. -> int", 0,
     {{0}}},
    {"has_brain", vg_brain_has_brain, "Whether a brain was created or loaded (and not closed). -> bool", 0, {{0}}},
    {"close", vg_brain_close, "Lets go of the brain now (its bodies keep it alive) instead of with the last reference.",
     0, {{0}}},
    {"get_last_error", vg_brain_get_last_error, "The error of the latest failed call, \"\" after a success. -> String",
     0, {{0}}},
};

static const vg_method_info vg_batch_methods[] = {
    {"create", vg_batch_create,
     "Creates the batch with worker_count threads, the calling one included (0: one per hardware thread). -> bool",
     1, {{"worker_count", GODOT_VARIANT_TYPE_INT}}},
    {"update", vg_batch_update,
     "One step of every agent, exactly as agents[i].update() in array order: rewards[i], the sensors packed agent "
     "after agent (discrete may be null), dt; optionally demonstrated: per agent the action the host took "
     "(update_demonstrated), -1 for its own choice; and continuous_actions: the continuous actions played, every "
     "agent's packed after the previous one's, read for the agents shown an action only "
     "(update_demonstrated_continuous). Any bad input changes no agent. -> PoolIntArray of actions (null on error)",
     7,
     {{"agents", GODOT_VARIANT_TYPE_ARRAY},
      {"rewards", GODOT_VARIANT_TYPE_POOL_REAL_ARRAY},
      {"discrete", GODOT_VARIANT_TYPE_POOL_INT_ARRAY},
      {"continuous", GODOT_VARIANT_TYPE_POOL_REAL_ARRAY},
      {"dt", GODOT_VARIANT_TYPE_REAL},
      {"demonstrated", GODOT_VARIANT_TYPE_POOL_INT_ARRAY},
      {"continuous_actions", GODOT_VARIANT_TYPE_POOL_REAL_ARRAY}}},
    {"get_worker_count", vg_batch_get_worker_count, "Threads an update uses, the calling one included. -> int", 0,
     {{0}}},
    {"has_batch", vg_batch_has_batch, "Whether create() succeeded (and close() was not called). -> bool", 0, {{0}}},
    {"close", vg_batch_close, "Joins the batch's threads now instead of with the last reference.", 0, {{0}}},
    {"get_last_error", vg_batch_get_last_error, "The error of the latest failed call, \"\" after a success. -> String",
     0, {{0}}},
};

static const vg_method_info vg_recording_methods[] = {
    {"create", vg_recording_create,
     "An empty recording with the sensors and actions of a VerveAgent (docs/teaching.md, \"Recordings\"). -> bool",
     1, {{"agent", GODOT_VARIANT_TYPE_OBJECT}}},
    {"add_step", vg_recording_add_step,
     "Records a demonstrated step as VerveAgent.update_demonstrated() takes it; a refused one is not recorded. "
     "-> bool",
     5,
     {{"reward", GODOT_VARIANT_TYPE_REAL},
      {"discrete", GODOT_VARIANT_TYPE_POOL_INT_ARRAY},
      {"continuous", GODOT_VARIANT_TYPE_POOL_REAL_ARRAY},
      {"dt", GODOT_VARIANT_TYPE_REAL},
      {"action", GODOT_VARIANT_TYPE_INT}}},
    {"add_step_continuous", vg_recording_add_step_continuous,
     "Records a demonstrated step as VerveAgent.update_demonstrated_continuous() takes it (no mask); a refused one "
     "is not recorded. -> bool",
     6,
     {{"reward", GODOT_VARIANT_TYPE_REAL},
      {"discrete", GODOT_VARIANT_TYPE_POOL_INT_ARRAY},
      {"continuous", GODOT_VARIANT_TYPE_POOL_REAL_ARRAY},
      {"dt", GODOT_VARIANT_TYPE_REAL},
      {"action", GODOT_VARIANT_TYPE_INT},
      {"continuous_action", GODOT_VARIANT_TYPE_POOL_REAL_ARRAY}}},
    {"add_end_episode", vg_recording_add_end_episode, "Records the end of a trial with its final reward. -> bool", 1,
     {{"final_reward", GODOT_VARIANT_TYPE_REAL}}},
    {"add_truncation", vg_recording_add_truncation, "Records a trial cut off at a time limit. -> bool", 1,
     {{"reward", GODOT_VARIANT_TYPE_REAL}}},
    {"get_size", vg_recording_get_size, "Entries (steps and trial ends) so far. -> int (-1 on error)", 0, {{0}}},
    {"save", vg_recording_save, "Saves the recording to a file (res://, user:// or a path), atomically. -> bool", 1,
     {{"path", GODOT_VARIANT_TYPE_STRING}}},
    {"save_bytes", vg_recording_save_bytes, "The recording's save as bytes (null on error). -> PoolByteArray", 0,
     {{0}}},
    {"load", vg_recording_load, "Replaces the recording with one loaded from a file. -> bool", 1,
     {{"path", GODOT_VARIANT_TYPE_STRING}}},
    {"load_bytes", vg_recording_load_bytes, "Replaces the recording with one loaded from save_bytes() data. -> bool",
     1, {{"data", GODOT_VARIANT_TYPE_POOL_BYTE_ARRAY}}},
    {"has_recording", vg_recording_has_recording,
     "Whether a recording was created or loaded (and not closed). -> bool", 0, {{0}}},
    {"close", vg_recording_close, "Frees the recording now instead of with the last reference.", 0, {{0}}},
    {"get_last_error", vg_recording_get_last_error,
     "The error of the latest failed call, \"\" after a success. -> String", 0, {{0}}},
};

typedef struct vg_class_info {
    const char* name; /* one of the vg_*_class names: its address is the class's type tag */
    const vg_method_info* methods;
    size_t method_count;
    size_t instance_size; /* calloc'd per instance: no handle until create() or load() */
    void (*destroy)(void* instance); /* frees what the instance holds */
} vg_class_info;

#define VG_COUNT(table) (sizeof table / sizeof table[0])
static const vg_class_info vg_classes[] = {
    {vg_agent_class, vg_agent_methods, VG_COUNT(vg_agent_methods), sizeof(vg_agent), vg_agent_destroy},
    {vg_brain_class, vg_brain_methods, VG_COUNT(vg_brain_methods), sizeof(vg_brain), vg_brain_destroy},
    {vg_batch_class, vg_batch_methods, VG_COUNT(vg_batch_methods), sizeof(vg_batch), vg_batch_destroy},
    {vg_recording_class, vg_recording_methods, VG_COUNT(vg_recording_methods), sizeof(vg_recording),
     vg_recording_destroy},
};

static void* vg_construct(godot_object* object, void* method_data) {
    (void)object;
    return calloc(1, ((const vg_class_info*)method_data)->instance_size);
}

static void vg_destruct(godot_object* object, void* method_data, void* user_data) {
    (void)object;
    if (user_data) ((const vg_class_info*)method_data)->destroy(user_data);
    free(user_data);
}

static void vg_document(void* handle, const char* class_name, const vg_method_info* m) {
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
    vg_ns11->godot_nativescript_set_method_argument_information(handle, class_name, m->name, m->argc, args);
    for (i = 0; i < m->argc; ++i) {
        vg_core->godot_string_destroy(&args[i].name);
        vg_core->godot_string_destroy(&args[i].hint_string);
    }
    doc = vg_string(m->doc);
    vg_ns11->godot_nativescript_set_method_documentation(handle, class_name, m->name, doc);
    vg_core->godot_string_destroy(&doc);
}

/* Registers one class: a Reference with its type tag, its methods and their documentation. */
static void vg_register_class(void* handle, const vg_class_info* info) {
    godot_instance_create_func create = {vg_construct, (void*)info, NULL};
    godot_instance_destroy_func destroy = {vg_destruct, (void*)info, NULL};
    godot_method_attributes attributes = {GODOT_METHOD_RPC_MODE_DISABLED};
    size_t i;
    vg_ns->godot_nativescript_register_class(handle, info->name, "Reference", create, destroy);
    if (vg_ns11) vg_ns11->godot_nativescript_set_type_tag(handle, info->name, info->name);
    for (i = 0; i < info->method_count; ++i) {
        godot_instance_method method = {info->methods[i].fn, NULL, NULL};
        vg_ns->godot_nativescript_register_method(handle, info->name, info->methods[i].name, attributes, method);
        vg_document(handle, info->name, &info->methods[i]);
    }
}

VG_EXPORT void godot_gdnative_init(godot_gdnative_init_options* options) {
    if (!vg_api_init(options->api_struct, options->gd_native_library))
        options->report_loading_error(options->gd_native_library, "verve: this Godot has no NativeScript");
    else
        vg_warnings_install(); /* before any agent: libverve takes the log hook only while it holds no memory */
}

VG_EXPORT void godot_gdnative_terminate(godot_gdnative_terminate_options* options) {
    (void)options;
}

VG_EXPORT void godot_nativescript_init(void* handle) {
    godot_property_attributes learning;
    godot_property_set_func set_learning = {vg_set_learning, NULL, NULL};
    godot_property_get_func get_learning = {vg_get_learning, NULL, NULL};
    godot_property_set_func set_greedy = {vg_set_greedy, NULL, NULL};
    godot_property_get_func get_greedy = {vg_get_greedy, NULL, NULL};
    size_t i;
    if (!vg_ns) return;
    for (i = 0; i < VG_COUNT(vg_classes); ++i) vg_register_class(handle, &vg_classes[i]);
    learning.rset_type = GODOT_METHOD_RPC_MODE_DISABLED;
    learning.type = GODOT_VARIANT_TYPE_BOOL;
    learning.hint = GODOT_PROPERTY_HINT_NONE;
    vg_core->godot_string_new(&learning.hint_string);
    learning.usage = GODOT_PROPERTY_USAGE_NOEDITOR; /* a run-time switch: not in the inspector */
    learning.default_value = vg_variant_bool(1);
    vg_ns->godot_nativescript_register_property(handle, vg_agent_class, "learning", &learning, set_learning, get_learning);
    vg_core->godot_variant_destroy(&learning.default_value);
    learning.default_value = vg_variant_bool(0); /* `greedy`: the same kind of run-time switch */
    vg_ns->godot_nativescript_register_property(handle, vg_agent_class, "greedy", &learning, set_greedy, get_greedy);
    vg_core->godot_string_destroy(&learning.hint_string);
    vg_core->godot_variant_destroy(&learning.default_value);
}
