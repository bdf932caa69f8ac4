/* Prints what the C compiler thinks of verve_c.h: sizes, field offsets, constants.
 * Built by Verve.Tests.csproj; NativeLayoutTests compares every line with the C# mirrors. */
#include <stddef.h>
#include <stdio.h>
#include "verve_c.h"

#define SIZE(type) printf("size %s %zu\n", #type, sizeof(type))
#define FIELD(type, field) printf("offset %s %s %zu\n", #type, #field, offsetof(type, field))

int main(void) {
    SIZE(verve_agent_desc);
    FIELD(verve_agent_desc, struct_size);
    FIELD(verve_agent_desc, num_discrete_sensors);
    FIELD(verve_agent_desc, discrete_sensor_values);
    FIELD(verve_agent_desc, num_continuous_sensors);
    FIELD(verve_agent_desc, continuous_sensor_circular);
    FIELD(verve_agent_desc, resolution);
    FIELD(verve_agent_desc, num_actions);
    FIELD(verve_agent_desc, rbf_allocation);
    FIELD(verve_agent_desc, tau_value);
    FIELD(verve_agent_desc, tau_discount);
    FIELD(verve_agent_desc, tau_eligibility);
    FIELD(verve_agent_desc, policy_multiplier);
    FIELD(verve_agent_desc, trace_threshold);
    FIELD(verve_agent_desc, seed);
    FIELD(verve_agent_desc, planning);
    FIELD(verve_agent_desc, tau_model);
    FIELD(verve_agent_desc, max_planning_steps);
    FIELD(verve_agent_desc, planning_uncertainty_threshold);
    FIELD(verve_agent_desc, curiosity);
    FIELD(verve_agent_desc, curiosity_factor);
    FIELD(verve_agent_desc, planning_accumulates_uncertainty);
    FIELD(verve_agent_desc, learn_from_real_steps);
    FIELD(verve_agent_desc, discrete_prediction);
    FIELD(verve_agent_desc, max_rbfs);
    FIELD(verve_agent_desc, policy_weight_bound);
    FIELD(verve_agent_desc, adaptation);
    FIELD(verve_agent_desc, sensor_grouping);
    FIELD(verve_agent_desc, num_sensor_groups);
    FIELD(verve_agent_desc, sensor_groups);
    FIELD(verve_agent_desc, num_action_branches);
    FIELD(verve_agent_desc, action_branches);
    FIELD(verve_agent_desc, num_continuous_actions);
    FIELD(verve_agent_desc, more_discrete_sensor_values);
    FIELD(verve_agent_desc, more_continuous_sensor_circular);

    SIZE(verve_agent_stats);
    FIELD(verve_agent_stats, struct_size);
    FIELD(verve_agent_stats, steps);
    FIELD(verve_agent_stats, rbf_count);
    FIELD(verve_agent_stats, live_traces);
    FIELD(verve_agent_stats, value);
    FIELD(verve_agent_stats, td_error);
    FIELD(verve_agent_stats, model_error);
    FIELD(verve_agent_stats, predicted_uncertainty);
    FIELD(verve_agent_stats, planning_steps);
    FIELD(verve_agent_stats, curiosity_reward);
    FIELD(verve_agent_stats, rbf_budget_hits);
    FIELD(verve_agent_stats, clamped_rewards);

    SIZE(verve_value_axis);
    FIELD(verve_value_axis, kind);
    FIELD(verve_value_axis, index);
    FIELD(verve_value_axis, samples);

    SIZE(verve_batch_desc);
    FIELD(verve_batch_desc, struct_size);
    FIELD(verve_batch_desc, worker_count);
    FIELD(verve_batch_desc, enqueue_task);
    FIELD(verve_batch_desc, finish_task);
    FIELD(verve_batch_desc, user_context);

    SIZE(verve_hooks);
    FIELD(verve_hooks, struct_size);
    FIELD(verve_hooks, malloc_fn);
    FIELD(verve_hooks, realloc_fn);
    FIELD(verve_hooks, free_fn);
    FIELD(verve_hooks, alloc_user);
    FIELD(verve_hooks, log_fn);
    FIELD(verve_hooks, log_user);

    printf("const VERVE_AGENT_DESC_SIZE_V2 %u\n", (unsigned)VERVE_AGENT_DESC_SIZE_V2);
    printf("const VERVE_AGENT_DESC_SIZE_V3 %u\n", (unsigned)VERVE_AGENT_DESC_SIZE_V3);
    printf("const VERVE_AGENT_DESC_SIZE_V4 %u\n", (unsigned)VERVE_AGENT_DESC_SIZE_V4);
    printf("const VERVE_AGENT_DESC_SIZE_V5 %u\n", (unsigned)VERVE_AGENT_DESC_SIZE_V5);
    printf("const VERVE_AGENT_DESC_SIZE_V6 %u\n", (unsigned)VERVE_AGENT_DESC_SIZE_V6);
    printf("const VERVE_AGENT_DESC_SIZE_V7 %u\n", (unsigned)VERVE_AGENT_DESC_SIZE_V7);
    printf("const VERVE_AGENT_DESC_SIZE_V8 %u\n", (unsigned)VERVE_AGENT_DESC_SIZE_V8);
    printf("const VERVE_MAX_SENSORS %d\n", VERVE_MAX_SENSORS);
    printf("const VERVE_MAX_LATTICE_SENSORS %d\n", VERVE_MAX_LATTICE_SENSORS);
    printf("const VERVE_MAX_ACTION_BRANCHES %d\n", VERVE_MAX_ACTION_BRANCHES);
    printf("const VERVE_MAX_CONTINUOUS_ACTIONS %d\n", VERVE_MAX_CONTINUOUS_ACTIONS);
    printf("const VERVE_MAX_SENSOR_GROUPS %d\n", VERVE_MAX_SENSOR_GROUPS);
    printf("const VERVE_GROUPING_AUTO %d\n", VERVE_GROUPING_AUTO);
    printf("const VERVE_GROUPING_JOINT %d\n", VERVE_GROUPING_JOINT);
    printf("const VERVE_GROUPING_CUSTOM %d\n", VERVE_GROUPING_CUSTOM);
    printf("const VERVE_ADAPT_ALL %u\n", (unsigned)VERVE_ADAPT_ALL);
    printf("const VERVE_GREEDY %d\n", VERVE_ACTION_GREEDY);
    printf("const VERVE_VERSION_NUMBER %d\n", VERVE_VERSION_NUMBER);
    printf("const VERVE_MAX_DISCRETE_SENSORS %d\n", VERVE_MAX_DISCRETE_SENSORS);
    printf("const VERVE_MAX_CONTINUOUS_SENSORS %d\n", VERVE_MAX_CONTINUOUS_SENSORS);
    printf("const VERVE_RBF_FULL %d\n", VERVE_RBF_FULL);
    printf("const VERVE_CURIOSITY_PROGRESS %d\n", VERVE_CURIOSITY_PROGRESS);
    printf("const VERVE_SENSOR_CONTINUOUS %d\n", VERVE_SENSOR_CONTINUOUS);
    printf("const VERVE_ERROR_INTERNAL %d\n", VERVE_ERROR_INTERNAL);
    printf("const sizeof_enum %zu\n", sizeof(verve_result));
    return 0;
}
