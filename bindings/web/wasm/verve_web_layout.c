/* The byte layout of the C ABI's structs as this wasm build sees them, for the JS binding
 * (src/layout.js): offsets come from the compiler, not from copies of them in JavaScript. */
#include <stddef.h>
#include <stdint.h>

#include <verve_c.h>

#define D(field) (uint32_t)offsetof(verve_agent_desc, field)
#define S(field) (uint32_t)offsetof(verve_agent_stats, field)

static const uint32_t layout[] = {
    /* 0: sizes */
    sizeof(verve_agent_desc), sizeof(verve_agent_stats), sizeof(verve_value_axis), sizeof(verve_batch_desc),
    /* 4: verve_agent_desc */
    D(num_discrete_sensors), D(discrete_sensor_values), D(num_continuous_sensors), D(continuous_sensor_circular),
    D(resolution), D(num_actions), D(rbf_allocation), D(tau_value), D(tau_discount), D(tau_eligibility),
    D(policy_multiplier), D(trace_threshold), D(seed), D(planning), D(tau_model), D(max_planning_steps),
    D(planning_uncertainty_threshold), D(curiosity), D(curiosity_factor), D(planning_accumulates_uncertainty),
    D(learn_from_real_steps), D(discrete_prediction), D(max_rbfs), D(policy_weight_bound),
    /* 28: verve_agent_stats */
    S(steps), S(rbf_count), S(live_traces), S(value), S(td_error), S(model_error), S(predicted_uncertainty),
    S(planning_steps), S(curiosity_reward), S(rbf_budget_hits), S(clamped_rewards),
    /* 39: verve_batch_desc */
    (uint32_t)offsetof(verve_batch_desc, worker_count),
    /* 40: verve_agent_desc, V4 */
    D(adaptation),
    /* 41: verve_agent_desc, V5 */
    D(sensor_grouping), D(num_sensor_groups), D(sensor_groups),
    /* 44: verve_agent_desc, V6 */
    D(num_action_branches), D(action_branches),
    /* 46: verve_agent_desc, V7 */
    D(num_continuous_actions),
    /* 47: verve_agent_desc, V8: sensors 16..63 */
    D(more_discrete_sensor_values), D(more_continuous_sensor_circular),
};

/* The table above and its length. */
const uint32_t* verve_web_layout(uint32_t* out_count) {
    *out_count = (uint32_t)(sizeof layout / sizeof layout[0]);
    return layout;
}
