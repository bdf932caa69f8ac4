// Turns fuzzer bytes into the inputs a careless or hostile host could pass to the C ABI: mostly
// plausible values (so the fuzzer reaches deep states), sometimes absurd ones (NaN, infinities,
// denormals, huge counts, wrong sizes), so every check sits on the path of some input.
#pragma once
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#include <fuzzer/FuzzedDataProvider.h>

#include "action_choices.h"
#include "verve_c.h"

namespace verve_fuzz {

// A float that is usually in [lo, hi] and sometimes anything at all.
inline float anyFloat(FuzzedDataProvider& in, float lo, float hi) {
    switch (in.ConsumeIntegralInRange<int>(0, 15)) {
        case 0: return std::numeric_limits<float>::quiet_NaN();
        case 1: return in.ConsumeBool() ? INFINITY : -INFINITY;
        case 2: return std::numeric_limits<float>::denorm_min() * static_cast<float>(in.ConsumeIntegral<int8_t>());
        case 3: return in.ConsumeFloatingPoint<float>();  // any finite float, huge ones included
        case 4: return 0.0f;
        default: return in.ConsumeFloatingPointInRange<float>(lo, hi);
    }
}

// A count that is usually small and sometimes at the edge of its type.
inline uint32_t anyCount(FuzzedDataProvider& in, uint32_t typicalMax) {
    switch (in.ConsumeIntegralInRange<int>(0, 15)) {
        case 0: return 0;
        case 1: return UINT32_MAX;
        case 2: return in.ConsumeIntegral<uint32_t>();
        case 3: return 1u << in.ConsumeIntegralInRange<int>(0, 31);
        default: return in.ConsumeIntegralInRange<uint32_t>(1, typicalMax);
    }
}

inline verve_agent_desc anyDescriptor(FuzzedDataProvider& in) {
    verve_agent_desc d;
    verve_agent_desc_default(&d);
    if (in.ConsumeIntegralInRange<int>(0, 31) == 0) d.struct_size = in.ConsumeIntegral<uint32_t>();
    d.num_discrete_sensors = in.ConsumeIntegralInRange<uint32_t>(0, 3);
    if (in.ConsumeIntegralInRange<int>(0, 31) == 0) d.num_discrete_sensors = anyCount(in, 20);
    for (uint32_t i = 0; i < VERVE_MAX_DISCRETE_SENSORS; ++i) d.discrete_sensor_values[i] = anyCount(in, 6);
    d.num_continuous_sensors = in.ConsumeIntegralInRange<uint32_t>(0, 3);
    if (in.ConsumeIntegralInRange<int>(0, 31) == 0) d.num_continuous_sensors = anyCount(in, 20);
    for (uint32_t i = 0; i < VERVE_MAX_CONTINUOUS_SENSORS; ++i) d.continuous_sensor_circular[i] = in.ConsumeIntegral<uint8_t>() % 3;
    d.resolution = anyCount(in, 10);
    d.num_actions = anyCount(in, 8);
    d.rbf_allocation = in.ConsumeIntegralInRange<uint32_t>(0, 2);
    d.tau_value = anyFloat(in, 0.0f, 2.0f);
    d.tau_discount = anyFloat(in, 0.0f, 5.0f);
    d.tau_eligibility = anyFloat(in, 0.0f, 2.0f);
    d.policy_multiplier = anyFloat(in, 0.0f, 20.0f);
    d.trace_threshold = anyFloat(in, 0.0f, 0.5f);
    d.seed = in.ConsumeIntegral<uint64_t>();
    d.planning = in.ConsumeIntegralInRange<uint32_t>(0, 2);
    d.tau_model = anyFloat(in, 0.0f, 2.0f);
    d.max_planning_steps = anyCount(in, 20);
    d.planning_uncertainty_threshold = anyFloat(in, 0.0f, 2.0f);
    d.curiosity = in.ConsumeIntegralInRange<uint32_t>(0, 3);
    d.curiosity_factor = anyFloat(in, 0.0f, 10.0f);
    d.planning_accumulates_uncertainty = in.ConsumeIntegralInRange<uint32_t>(0, 2);
    d.learn_from_real_steps = in.ConsumeIntegralInRange<uint32_t>(0, 2);
    d.discrete_prediction = in.ConsumeIntegralInRange<uint32_t>(0, 2);
    // A host's RBF budget: modest, so that every accepted agent is quick to build and a slow input
    // means a real hang (now and then beyond the limit, which must be refused).
    d.max_rbfs = in.ConsumeIntegralInRange<int>(0, 63) == 0 ? UINT64_MAX : in.ConsumeIntegralInRange<uint64_t>(1, 4000);
    // ... and modest in weights too: a planning agent with many discrete values has thousands of
    // model weights per RBF, and 4,000 such RBFs take seconds to save as XML under ASan.
    uint64_t row = 1 + uint64_t{d.num_actions};
    if (d.planning != 0) {
        uint64_t outputs = 5 + d.num_continuous_sensors;
        for (uint32_t i = 0; i < d.num_discrete_sensors && i < VERVE_MAX_DISCRETE_SENSORS; ++i) {
            outputs += d.discrete_prediction == VERVE_DISCRETE_PREDICTION_ORDINAL ? 1 : d.discrete_sensor_values[i];
        }
        row += uint64_t{d.num_actions} * outputs;
    }
    const uint64_t weightBudget = 400000 / (row == 0 ? 1 : row);
    if (d.max_rbfs > weightBudget && (d.max_rbfs != UINT64_MAX || row > 64)) d.max_rbfs = weightBudget == 0 ? 1 : weightBudget;
    // A struct_size that ends before max_rbfs (a host built against an older header) leaves the
    // default budget of a million RBFs, and a full lattice that large takes seconds to build under
    // ASan (fuzz_crowd: 14 s): such descriptors grow their RBFs where observations land instead.
    if (d.struct_size < offsetof(verve_agent_desc, max_rbfs) + sizeof d.max_rbfs) d.rbf_allocation = VERVE_RBF_DYNAMIC;
    // Any adaptation bits, now and then unknown ones (which must be refused).
    d.adaptation = in.ConsumeIntegralInRange<int>(0, 31) == 0 ? in.ConsumeIntegral<uint64_t>()
                                                              : in.ConsumeIntegralInRange<uint64_t>(0, VERVE_ADAPT_ALL);
    // Sensor groups: now and then more than 4 continuous sensors (Auto's groups), custom groups
    // that mostly name the agent's sensors, and now and then bad values (which must be refused).
    if (in.ConsumeIntegralInRange<int>(0, 7) == 0) d.num_continuous_sensors = in.ConsumeIntegralInRange<uint32_t>(5, 8);
    d.sensor_grouping = in.ConsumeIntegralInRange<uint32_t>(0, 3);
    d.num_sensor_groups = in.ConsumeIntegralInRange<int>(0, 31) == 0 ? anyCount(in, 70)
                          : d.sensor_grouping == VERVE_GROUPING_CUSTOM ? in.ConsumeIntegralInRange<uint32_t>(0, 4) : 0;
    const uint64_t sensors = d.num_continuous_sensors < 64 ? (uint64_t{1} << d.num_continuous_sensors) - 1 : ~uint64_t{0};
    for (uint32_t i = 0; i < VERVE_MAX_SENSOR_GROUPS; ++i) {
        const uint64_t g = in.ConsumeIntegral<uint64_t>();
        d.sensor_groups[i] = in.ConsumeIntegralInRange<int>(0, 15) == 0 ? g : (g & sensors);
    }
    // Action branches, now and then: mostly 1-3 branches of 1-4 choices with num_actions 0 (their
    // product), now and then a wrong num_actions, too many branches or a branch of 0 (refused).
    if (in.ConsumeIntegralInRange<int>(0, 3) == 0) {
        d.num_action_branches = in.ConsumeIntegralInRange<int>(0, 31) == 0 ? anyCount(in, 10) : in.ConsumeIntegralInRange<uint32_t>(1, 3);
        for (uint32_t& b : d.action_branches) b = in.ConsumeIntegralInRange<int>(0, 31) == 0 ? anyCount(in, 5000) : in.ConsumeIntegralInRange<uint32_t>(1, 4);
        if (in.ConsumeIntegralInRange<int>(0, 7) != 0) d.num_actions = 0;
    }
    // Continuous actions, now and then: mostly 1-3 (with num_actions 0, the one discrete action they
    // keep), now and then beyond the limit or with planning (refused).
    if (in.ConsumeIntegralInRange<int>(0, 3) == 0) {
        d.num_continuous_actions = in.ConsumeIntegralInRange<int>(0, 31) == 0 ? in.ConsumeIntegral<uint64_t>()
                                                                               : in.ConsumeIntegralInRange<uint64_t>(1, 3);
        if (d.num_action_branches == 0 && in.ConsumeBool()) d.num_actions = 0;
    }
    // More than 16 sensors (the V8 struct's arrays), now and then: 17-40 continuous (Auto's groups
    // up to 32, refused beyond; Joint and wide Custom groups refused over 16) and 17-20 discrete of
    // mostly 1-2 values. No planning: its model's rows grow with the sensors past the budget above.
    if (in.ConsumeIntegralInRange<int>(0, 15) == 0) {
        d.planning = 0;
        d.num_continuous_sensors = in.ConsumeIntegralInRange<uint32_t>(17, 40);
        const uint64_t circular = in.ConsumeIntegral<uint64_t>();
        for (uint32_t i = 0; i < VERVE_MAX_SENSORS - VERVE_MAX_CONTINUOUS_SENSORS; ++i) {
            d.more_continuous_sensor_circular[i] = static_cast<uint8_t>((circular >> i) & 1u);
        }
        if (in.ConsumeIntegralInRange<int>(0, 15) == 0) d.more_continuous_sensor_circular[in.ConsumeIntegralInRange<int>(0, 47)] = 2;
        if (in.ConsumeBool()) {
            d.num_discrete_sensors = in.ConsumeIntegralInRange<uint32_t>(17, 20);
            for (uint32_t i = 0; i < VERVE_MAX_DISCRETE_SENSORS; ++i) d.discrete_sensor_values[i] = in.ConsumeIntegralInRange<uint32_t>(1, 2);
            for (uint32_t& v : d.more_discrete_sensor_values) v = in.ConsumeIntegralInRange<int>(0, 31) == 0 ? anyCount(in, 3) : 1;
        }
    }
    return d;
}

// Sensor i's value count in any struct (V8 holds sensors 16 and up in a second array).
inline uint32_t discreteValues(const verve_agent_desc& d, uint32_t i) {
    return i < VERVE_MAX_DISCRETE_SENSORS ? d.discrete_sensor_values[i]
           : i < VERVE_MAX_SENSORS        ? d.more_discrete_sensor_values[i - VERVE_MAX_DISCRETE_SENSORS]
                                          : 1;
}

// Flags in an accepted agent's action mask: one per choice of each branch, or num_actions (as the
// Lua and Godot bindings count them).
inline uint32_t actionChoices(const verve_agent_desc& d) { return vb_action_choices(&d); }

// Whether an accepted agent's combined `action` is one `mask` (actionChoices(d) flags) allows.
inline bool maskAllows(const verve_agent_desc& d, const uint8_t* mask, uint32_t action) {
    if (d.num_action_branches == 0) return mask[action] == 1;
    for (uint32_t b = 0, at = 0; b < d.num_action_branches; at += d.action_branches[b], ++b) {
        if (mask[at + action % d.action_branches[b]] != 1) return false;
        action /= d.action_branches[b];
    }
    return true;
}

// Observation arrays sized for any agent: counts are chosen separately (and may be wrong).
struct Observation {
    int32_t discrete[VERVE_MAX_SENSORS + 4] = {};
    float continuous[VERVE_MAX_SENSORS + 4] = {};
    uint32_t numDiscrete = 0;
    uint32_t numContinuous = 0;
};

// Usually the agent's own shape with in-range values; sometimes wrong counts or values.
inline Observation anyObservation(FuzzedDataProvider& in, const verve_agent_desc& d) {
    Observation o;
    const bool wrongCounts = in.ConsumeIntegralInRange<int>(0, 15) == 0;
    o.numDiscrete = wrongCounts ? in.ConsumeIntegralInRange<uint32_t>(0, VERVE_MAX_SENSORS + 4) : d.num_discrete_sensors;
    o.numContinuous = wrongCounts ? in.ConsumeIntegralInRange<uint32_t>(0, VERVE_MAX_SENSORS + 4) : d.num_continuous_sensors;
    // Values only for the counts passed (the input's bytes are few; the rest of the arrays stay 0).
    for (uint32_t i = 0; i < o.numDiscrete; ++i) {
        const uint32_t values = discreteValues(d, i);
        o.discrete[i] = in.ConsumeIntegralInRange<int>(0, 31) == 0
                            ? in.ConsumeIntegral<int32_t>()
                            : static_cast<int32_t>(in.ConsumeIntegralInRange<uint32_t>(0, values > 0 ? values - 1 : 0));
    }
    for (uint32_t i = 0; i < o.numContinuous; ++i) o.continuous[i] = anyFloat(in, -1.2f, 1.2f);
    return o;
}

}  // namespace verve_fuzz
