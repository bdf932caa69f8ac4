/* verve_batch_methods.c - what each VerveBatch method does. update() checks everything the C ABI
 * cannot see (that each element is one of our VerveAgents, that the arrays' sizes fit the agents)
 * before verve_batch_update checks the values: on any error no agent changes. */
#include "verve_batch_methods.h"

#include <stdlib.h>

#define VG_METHOD(name)                                                                                     \
    godot_variant vg_batch_##name(godot_object* object, void* method_data, void* user_data, int argc, \
                                  godot_variant** argv)
#define VG_UNUSED (void)object, (void)method_data

/* The pool arrays are handed to libverve as they are: their elements must be its types. */
typedef char vg_godot_int_is_int32[sizeof(godot_int) == sizeof(int32_t) ? 1 : -1];
typedef char vg_godot_real_is_float[sizeof(godot_real) == sizeof(float) ? 1 : -1];

void vg_batch_destroy(void* instance) {
    vg_batch* self = instance;
    verve_batch_destroy(self->handle);
    free(self->agents);
}

static int vg_begin_batch(vg_call* c, void* user_data, const char* method, int argc, godot_variant** argv,
                          int min_args, int max_args) {
    vg_batch* self = user_data;
    return vg_begin_class(c, vg_batch_class, self ? self->last_error : NULL, method, argc, argv, min_args, max_args);
}

/* The batch, or 0 with an error when there is none. */
static int vg_batch_handle(vg_call* c, void* user_data, verve_batch** out) {
    *out = ((vg_batch*)user_data)->handle;
    if (*out) return 1;
    return vg_fail(c, "this VerveBatch has no batch: call create() first (or it was closed)");
}

VG_METHOD(create) {
    vg_call c;
    verve_batch_desc d;
    verve_batch* fresh = NULL;
    vg_batch* self = user_data;
    int64_t workers = 0;
    VG_UNUSED;
    if (!vg_begin_batch(&c, user_data, "create", argc, argv, 0, 1)) return vg_variant_bool(0);
    if (argc > 0) {
        if (vg_core->godot_variant_get_type(argv[0]) != GODOT_VARIANT_TYPE_INT)
            return vg_variant_bool(vg_fail(&c, "worker_count must be an int (got %s)", vg_type_name(argv[0])));
        workers = vg_core->godot_variant_as_int(argv[0]);
        if (workers < 0 || workers > (int64_t)UINT32_MAX)
            return vg_variant_bool(vg_fail(&c, "worker_count must be 0 (one per hardware thread) or more (got %ld)",
                                           (long)workers));
    }
    verve_batch_desc_default(&d);
    d.worker_count = (uint32_t)workers; /* libverve refuses counts above its own limit */
    if (!vg_check(&c, verve_batch_create(&d, &fresh))) return vg_variant_bool(0);
    verve_batch_destroy(self->handle);
    self->handle = fresh;
    return vg_variant_bool(1);
}

/* Argument i as a pool array of `type`, or null when `nullable`; its size in *n (0 for null). */
static int vg_arg_pool(vg_call* c, int i, const char* name, godot_variant_type type, int nullable, uint32_t* n) {
    godot_variant_type t = vg_core->godot_variant_get_type(c->argv[i]);
    const char* type_name = type == GODOT_VARIANT_TYPE_POOL_INT_ARRAY ? "PoolIntArray" : "PoolRealArray";
    *n = 0;
    if (t == GODOT_VARIANT_TYPE_NIL && nullable) return 1;
    if (t != type)
        return vg_fail(c, "%s must be a %s%s (got %s)", name, type_name, nullable ? " or null" : "",
                       vg_type_name(c->argv[i]));
    if (type == GODOT_VARIANT_TYPE_POOL_INT_ARRAY) {
        godot_pool_int_array a = vg_core->godot_variant_as_pool_int_array(c->argv[i]);
        *n = (uint32_t)vg_core->godot_pool_int_array_size(&a);
        vg_core->godot_pool_int_array_destroy(&a);
    } else {
        godot_pool_real_array a = vg_core->godot_variant_as_pool_real_array(c->argv[i]);
        *n = (uint32_t)vg_core->godot_pool_real_array_size(&a);
        vg_core->godot_pool_real_array_destroy(&a);
    }
    return 1;
}

/* Fills self->agents from the Array: each element must be one of our VerveAgents holding an agent.
 * Sums the agents' sensors, which the packed arrays must hold exactly, and their continuous
 * actions (for update's continuous_actions). */
static int vg_read_agents(vg_call* c, vg_batch* self, const godot_array* list, uint32_t n, uint64_t* discrete,
                          uint64_t* continuous, uint64_t* continuous_actions) {
    verve_agent_desc d;
    uint32_t i;
    *discrete = *continuous = *continuous_actions = 0;
    if (n > self->capacity) {
        /* As many pointers as the Array has elements: bounded by what the caller already holds. */
        verve_agent** grown = realloc(self->agents, (size_t)n * sizeof *grown);
        if (!grown) return vg_fail(c, "out of memory for %u agents", n);
        self->agents = grown;
        self->capacity = n;
    }
    verve_agent_desc_default(&d);
    for (i = 0; i < n; ++i) {
        const godot_variant* e = vg_core->godot_array_operator_index_const(list, (godot_int)i);
        vg_agent* agent = vg_instance_of(e, vg_agent_class);
        if (!agent) return vg_fail(c, "agents[%u] is not a VerveAgent (got %s)", i, vg_describe(e));
        if (!agent->handle)
            return vg_fail(c, "agents[%u] is a VerveAgent without an agent (never created, or closed)", i);
        if (!vg_check(c, verve_agent_get_desc(agent->handle, &d))) return 0;
        self->agents[i] = agent->handle;
        *discrete += d.num_discrete_sensors;
        *continuous += d.num_continuous_sensors;
        *continuous_actions += d.num_continuous_actions;
    }
    return 1;
}

/* Steps the checked agents: the pool arrays are read in place and the actions written in place.
 * With argument 5 (demonstrated: one action per agent, -1 for the agent's own choice, which is
 * VERVE_AGENT_CHOOSES read as unsigned) the call is verve_batch_update_demonstrated; with argument 6
 * too (continuous_actions, every agent's packed after the previous one's),
 * verve_batch_update_demonstrated_continuous. */
static godot_variant vg_run(vg_call* c, vg_batch* self, uint32_t n, float dt) {
    godot_pool_real_array rewards, continuous, values;
    godot_pool_int_array discrete, actions, shown;
    godot_pool_real_array_read_access *rewards_read, *continuous_read = NULL, *values_read = NULL;
    godot_pool_int_array_read_access *discrete_read = NULL, *shown_read = NULL;
    const int32_t* discrete_ptr;
    const float* continuous_ptr;
    uint32_t* actions_ptr;
    godot_pool_int_array_write_access* actions_write;
    uint32_t n_discrete = 0, n_continuous = 0;
    godot_variant out;
    int ok;
    rewards = vg_core->godot_variant_as_pool_real_array(c->argv[1]);
    rewards_read = vg_core->godot_pool_real_array_read(&rewards);
    if (vg_core->godot_variant_get_type(c->argv[2]) != GODOT_VARIANT_TYPE_NIL) {
        discrete = vg_core->godot_variant_as_pool_int_array(c->argv[2]);
        n_discrete = (uint32_t)vg_core->godot_pool_int_array_size(&discrete);
        discrete_read = vg_core->godot_pool_int_array_read(&discrete);
    }
    if (vg_core->godot_variant_get_type(c->argv[3]) != GODOT_VARIANT_TYPE_NIL) {
        continuous = vg_core->godot_variant_as_pool_real_array(c->argv[3]);
        n_continuous = (uint32_t)vg_core->godot_pool_real_array_size(&continuous);
        continuous_read = vg_core->godot_pool_real_array_read(&continuous);
    }
    vg_core->godot_pool_int_array_new(&actions);
    vg_core->godot_pool_int_array_resize(&actions, (godot_int)n);
    actions_write = vg_core->godot_pool_int_array_write(&actions);
    if (c->argc > 5) {
        shown = vg_core->godot_variant_as_pool_int_array(c->argv[5]);
        shown_read = vg_core->godot_pool_int_array_read(&shown);
    }
    if (c->argc > 6) {
        values = vg_core->godot_variant_as_pool_real_array(c->argv[6]);
        values_read = vg_core->godot_pool_real_array_read(&values);
    }
    discrete_ptr = discrete_read ? (const int32_t*)vg_core->godot_pool_int_array_read_access_ptr(discrete_read) : NULL;
    continuous_ptr = continuous_read ? vg_core->godot_pool_real_array_read_access_ptr(continuous_read) : NULL;
    actions_ptr = (uint32_t*)vg_core->godot_pool_int_array_write_access_ptr(actions_write);
    ok = vg_check(c, values_read
        ? verve_batch_update_demonstrated_continuous(
              self->handle, self->agents, n, vg_core->godot_pool_real_array_read_access_ptr(rewards_read), discrete_ptr,
              NULL, n_discrete, continuous_ptr, NULL, n_continuous, dt,
              (const uint32_t*)vg_core->godot_pool_int_array_read_access_ptr(shown_read),
              vg_core->godot_pool_real_array_read_access_ptr(values_read), NULL,
              (uint32_t)vg_core->godot_pool_real_array_size(&values), actions_ptr, NULL)
        : shown_read
        ? verve_batch_update_demonstrated(self->handle, self->agents, n,
                                          vg_core->godot_pool_real_array_read_access_ptr(rewards_read), discrete_ptr,
                                          NULL, n_discrete, continuous_ptr, NULL, n_continuous, dt,
                                          (const uint32_t*)vg_core->godot_pool_int_array_read_access_ptr(shown_read),
                                          actions_ptr, NULL)
        : verve_batch_update(self->handle, self->agents, n, vg_core->godot_pool_real_array_read_access_ptr(rewards_read),
                             discrete_ptr, NULL, n_discrete, continuous_ptr, NULL, n_continuous, dt, actions_ptr, NULL));
    vg_core->godot_pool_int_array_write_access_destroy(actions_write);
    if (values_read) {
        vg_core->godot_pool_real_array_read_access_destroy(values_read);
        vg_core->godot_pool_real_array_destroy(&values);
    }
    if (shown_read) {
        vg_core->godot_pool_int_array_read_access_destroy(shown_read);
        vg_core->godot_pool_int_array_destroy(&shown);
    }
    if (ok) vg_core->godot_variant_new_pool_int_array(&out, &actions);
    else out = vg_variant_nil();
    vg_core->godot_pool_int_array_destroy(&actions);
    if (continuous_read) {
        vg_core->godot_pool_real_array_read_access_destroy(continuous_read);
        vg_core->godot_pool_real_array_destroy(&continuous);
    }
    if (discrete_read) {
        vg_core->godot_pool_int_array_read_access_destroy(discrete_read);
        vg_core->godot_pool_int_array_destroy(&discrete);
    }
    vg_core->godot_pool_real_array_read_access_destroy(rewards_read);
    vg_core->godot_pool_real_array_destroy(&rewards);
    return out;
}

VG_METHOD(update) {
    vg_call c;
    vg_batch* self = user_data;
    verve_batch* batch;
    godot_array list;
    uint32_t n, n_rewards, n_discrete, n_continuous, n_shown = 0, n_values = 0;
    uint64_t need_discrete, need_continuous, need_values;
    float dt = 0.0f;
    int ok;
    VG_UNUSED;
    if (!vg_begin_batch(&c, user_data, "update", argc, argv, 5, 7) || !vg_batch_handle(&c, user_data, &batch) ||
        !vg_arg_type(&c, 0, "agents", GODOT_VARIANT_TYPE_ARRAY) ||
        !vg_arg_pool(&c, 1, "rewards", GODOT_VARIANT_TYPE_POOL_REAL_ARRAY, 0, &n_rewards) ||
        !vg_arg_pool(&c, 2, "discrete", GODOT_VARIANT_TYPE_POOL_INT_ARRAY, 1, &n_discrete) ||
        !vg_arg_pool(&c, 3, "continuous", GODOT_VARIANT_TYPE_POOL_REAL_ARRAY, 1, &n_continuous) ||
        !vg_arg_float(&c, 4, "dt", &dt) ||
        (argc > 5 && !vg_arg_pool(&c, 5, "demonstrated", GODOT_VARIANT_TYPE_POOL_INT_ARRAY, 0, &n_shown)) ||
        (argc > 6 && !vg_arg_pool(&c, 6, "continuous_actions", GODOT_VARIANT_TYPE_POOL_REAL_ARRAY, 0, &n_values)))
        return vg_variant_nil();
    list = vg_core->godot_variant_as_array(argv[0]);
    n = (uint32_t)vg_core->godot_array_size(&list);
    ok = vg_read_agents(&c, self, &list, n, &need_discrete, &need_continuous, &need_values);
    vg_core->godot_array_destroy(&list);
    if (!ok) return vg_variant_nil();
    /* libverve reads one reward per agent and accepts longer sensor arrays: the sizes are ours to check. */
    if (n_rewards != n) ok = vg_fail(&c, "%u agents need %u rewards (got %u)", n, n, n_rewards);
    else if (argc > 5 && n_shown != n)
        ok = vg_fail(&c, "%u agents need %u demonstrated actions, -1 for their own choice (got %u)", n, n, n_shown);
    else if (n_discrete != need_discrete)
        ok = vg_fail(&c, "discrete has %u values; the agents' discrete sensors take %lu, agent after agent",
                     n_discrete, (unsigned long)need_discrete);
    else if (n_continuous != need_continuous)
        ok = vg_fail(&c, "continuous has %u values; the agents' continuous sensors take %lu, agent after agent",
                     n_continuous, (unsigned long)need_continuous);
    else if (argc > 6 && n_values != need_values)
        ok = vg_fail(&c, "continuous_actions has %u values; the agents' continuous actions take %lu, agent after agent",
                     n_values, (unsigned long)need_values);
    if (!ok) return vg_variant_nil();
    return vg_run(&c, self, n, dt);
}

VG_METHOD(get_worker_count) {
    vg_call c;
    verve_batch* b;
    uint32_t n = 0;
    VG_UNUSED;
    if (!vg_begin_batch(&c, user_data, "get_worker_count", argc, argv, 0, 0) || !vg_batch_handle(&c, user_data, &b) ||
        !vg_check(&c, verve_batch_get_worker_count(b, &n)))
        return vg_variant_nil();
    return vg_variant_int(n);
}

VG_METHOD(has_batch) {
    vg_call c;
    VG_UNUSED;
    return vg_variant_bool(vg_begin_batch(&c, user_data, "has_batch", argc, argv, 0, 0) &&
                           ((vg_batch*)user_data)->handle != NULL);
}

VG_METHOD(close) {
    vg_call c;
    VG_UNUSED;
    if (vg_begin_batch(&c, user_data, "close", argc, argv, 0, 0)) {
        verve_batch_destroy(((vg_batch*)user_data)->handle);
        ((vg_batch*)user_data)->handle = NULL;
    }
    return vg_variant_nil();
}

VG_METHOD(get_last_error) {
    VG_UNUSED, (void)argc, (void)argv;
    return vg_variant_string(user_data ? ((vg_batch*)user_data)->last_error : "");
}
