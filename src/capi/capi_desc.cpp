#include "capi/capi_desc.hpp"

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <string>

#include "verve/error.hpp"

namespace verve::capi {
namespace {

[[noreturn]] void refuse(const std::string& message) { throw Error(ErrorCode::InvalidArgument, message); }

void requireKnownSize(std::uint32_t size) {
    if (!isKnownDescSize(size)) {
        refuse("struct_size " + std::to_string(size) + " is not a verve_agent_desc size this library knows (" +
               std::to_string(VERVE_AGENT_DESC_SIZE_V1) + ", " + std::to_string(VERVE_AGENT_DESC_SIZE_V2) + ", " +
               std::to_string(VERVE_AGENT_DESC_SIZE_V3) + ", " + std::to_string(VERVE_AGENT_DESC_SIZE_V4) + ", " +
               std::to_string(VERVE_AGENT_DESC_SIZE_V5) + ", " + std::to_string(VERVE_AGENT_DESC_SIZE_V6) + ", " +
               std::to_string(VERVE_AGENT_DESC_SIZE_V7) + " or " + std::to_string(VERVE_AGENT_DESC_SIZE_V8) +
               "); fill the struct with verve_agent_desc_init");
    }
}

void requireFlag(std::uint32_t value, const std::string& name) {
    if (value > 1) refuse(name + " must be 0 or 1, not " + std::to_string(value));
}

}  // namespace

bool isKnownDescSize(std::uint32_t size) noexcept {
    return size == VERVE_AGENT_DESC_SIZE_V1 || size == VERVE_AGENT_DESC_SIZE_V2 || size == VERVE_AGENT_DESC_SIZE_V3 ||
           size == VERVE_AGENT_DESC_SIZE_V4 || size == VERVE_AGENT_DESC_SIZE_V5 || size == VERVE_AGENT_DESC_SIZE_V6 ||
           size == VERVE_AGENT_DESC_SIZE_V7 || size == VERVE_AGENT_DESC_SIZE_V8;
}

// Sensors a struct of `size` bytes can describe: 16 of each kind before V8.
static std::uint32_t sensorsIn(std::uint32_t size) noexcept {
    return size >= VERVE_AGENT_DESC_SIZE_V8 ? VERVE_MAX_SENSORS : VERVE_MAX_DISCRETE_SENSORS;
}

// Each new field starts where the struct before it ended (the V6 struct's size: its last field's
// end rounded up to the struct's alignment), so an older host's tail padding is never read as a field.
constexpr std::size_t kV6End = offsetof(verve_agent_desc, action_branches) + sizeof(verve_agent_desc::action_branches);
static_assert(VERVE_AGENT_DESC_SIZE_V6 == (kV6End + alignof(verve_agent_desc) - 1) / alignof(verve_agent_desc) * alignof(verve_agent_desc),
              "num_continuous_actions starts where the V6 struct ended");
static_assert(VERVE_MAX_CONTINUOUS_ACTIONS == DescriptorLimits::kMaxContinuousActions, "one limit");
// V8 likewise: V7 ended on a 64-bit field, so its size is its end and V8's arrays start there.
constexpr std::size_t kV7End = offsetof(verve_agent_desc, num_continuous_actions) + sizeof(verve_agent_desc::num_continuous_actions);
static_assert(VERVE_AGENT_DESC_SIZE_V7 == kV7End, "more_discrete_sensor_values starts where the V7 struct ended");
static_assert(offsetof(verve_agent_desc, more_continuous_sensor_circular) ==
                  offsetof(verve_agent_desc, more_discrete_sensor_values) + sizeof(verve_agent_desc::more_discrete_sensor_values),
              "the V8 arrays are packed");
static_assert(VERVE_AGENT_DESC_SIZE_V8 == kV7End + sizeof(verve_agent_desc::more_discrete_sensor_values) +
                                              sizeof(verve_agent_desc::more_continuous_sensor_circular),
              "no tail padding after V8's arrays");
static_assert(VERVE_MAX_SENSORS == DescriptorLimits::kMaxSensors, "one limit");
static_assert(VERVE_MAX_LATTICE_SENSORS == DescriptorLimits::kMaxLatticeSensors, "one limit");
static_assert(VERVE_MAX_DISCRETE_SENSORS == 16 && VERVE_MAX_CONTINUOUS_SENSORS == 16, "V1-V7 hosts' arrays");

// Sensor i's entry: the V1-V7 array below 16, the V8 one above.
static std::uint32_t& discreteValues(verve_agent_desc& d, std::size_t i) noexcept {
    return i < VERVE_MAX_DISCRETE_SENSORS ? d.discrete_sensor_values[i] : d.more_discrete_sensor_values[i - VERVE_MAX_DISCRETE_SENSORS];
}
static std::uint8_t& circularFlag(verve_agent_desc& d, std::size_t i) noexcept {
    return i < VERVE_MAX_CONTINUOUS_SENSORS ? d.continuous_sensor_circular[i]
                                            : d.more_continuous_sensor_circular[i - VERVE_MAX_CONTINUOUS_SENSORS];
}

// The full current struct for a descriptor: the one place the two layouts meet field by field.
static verve_agent_desc fullDesc(const AgentDescriptor& in) noexcept {
    verve_agent_desc d;
    std::memset(&d, 0, sizeof d);  // also the padding, so the bytes are deterministic
    d.struct_size = sizeof d;
    d.num_discrete_sensors = static_cast<std::uint32_t>(in.discreteSensors.size());
    // Validated: at most VERVE_MAX_SENSORS of each kind.
    for (std::size_t i = 0; i < in.discreteSensors.size() && i < VERVE_MAX_SENSORS; ++i) discreteValues(d, i) = in.discreteSensors[i];
    d.num_continuous_sensors = static_cast<std::uint32_t>(in.continuousSensors.size());
    for (std::size_t i = 0; i < in.continuousSensors.size() && i < VERVE_MAX_SENSORS; ++i) {
        circularFlag(d, i) = in.continuousSensors[i].circular ? 1 : 0;
    }
    d.resolution = in.resolution;
    d.num_actions = in.numActions;
    d.rbf_allocation = static_cast<std::uint32_t>(in.allocation);
    d.tau_value = in.tauValue;
    d.tau_discount = in.tauDiscount;
    d.tau_eligibility = in.tauEligibility;
    d.policy_multiplier = in.policyMultiplier;
    d.trace_threshold = in.traceThreshold;
    d.seed = in.seed;
    d.planning = in.planning ? 1u : 0u;
    d.tau_model = in.tauModel;
    d.max_planning_steps = in.maxPlanningSteps;
    d.planning_uncertainty_threshold = in.planningUncertaintyThreshold;
    d.curiosity = static_cast<std::uint32_t>(in.curiosity);
    d.curiosity_factor = in.curiosityFactor;
    d.planning_accumulates_uncertainty = in.planningAccumulatesUncertainty ? 1u : 0u;
    d.learn_from_real_steps = in.learnFromRealSteps ? 1u : 0u;
    d.discrete_prediction = static_cast<std::uint32_t>(in.discretePrediction);
    d.max_rbfs = in.maxRbfs;
    d.policy_weight_bound = in.policyWeightBound;
    d.adaptation = in.adaptation;
    d.sensor_grouping = static_cast<std::uint32_t>(in.grouping);
    d.num_sensor_groups = static_cast<std::uint32_t>(in.sensorGroups.size());  // validated: <= VERVE_MAX_SENSOR_GROUPS
    for (std::size_t i = 0; i < in.sensorGroups.size() && i < VERVE_MAX_SENSOR_GROUPS; ++i) d.sensor_groups[i] = in.sensorGroups[i];
    d.num_action_branches = static_cast<std::uint32_t>(in.actionBranches.size());  // validated: <= VERVE_MAX_ACTION_BRANCHES
    for (std::size_t i = 0; i < in.actionBranches.size() && i < VERVE_MAX_ACTION_BRANCHES; ++i) d.action_branches[i] = in.actionBranches[i];
    d.num_continuous_actions = in.continuousActions;
    return d;
}

// One source of truth for defaults: the C++ descriptor's.
verve_agent_desc defaultDesc() noexcept { return fullDesc(AgentDescriptor{}); }

void initDesc(verve_agent_desc& out, std::uint32_t size) {
    requireKnownSize(size);
    verve_agent_desc d = defaultDesc();
    d.struct_size = size;
    std::memcpy(&out, &d, size);
}

AgentDescriptor toDescriptor(const verve_agent_desc& in) {
    requireKnownSize(in.struct_size);
    verve_agent_desc d = defaultDesc();
    std::memcpy(&d, &in, in.struct_size);

    // A struct before V8 has room for 16 sensors of each kind: more would read past its end.
    const std::uint32_t maxSensors = sensorsIn(in.struct_size);
    const std::string why = maxSensors < VERVE_MAX_SENSORS ? " (struct_size " + std::to_string(in.struct_size) +
                                                                 " holds 16; VERVE_AGENT_DESC_SIZE_V8 holds " +
                                                                 std::to_string(VERVE_MAX_SENSORS) + ")"
                                                           : "";
    if (d.num_discrete_sensors > maxSensors) {
        refuse("num_discrete_sensors is " + std::to_string(d.num_discrete_sensors) + ", at most " + std::to_string(maxSensors) + why);
    }
    if (d.num_continuous_sensors > maxSensors) {
        refuse("num_continuous_sensors is " + std::to_string(d.num_continuous_sensors) + ", at most " +
               std::to_string(maxSensors) + why);
    }
    requireFlag(d.rbf_allocation, "rbf_allocation");
    requireFlag(d.planning, "planning");
    requireFlag(d.planning_accumulates_uncertainty, "planning_accumulates_uncertainty");
    requireFlag(d.learn_from_real_steps, "learn_from_real_steps");
    requireFlag(d.discrete_prediction, "discrete_prediction");
    if (d.curiosity > VERVE_CURIOSITY_PROGRESS) refuse("curiosity must be 0, 1 or 2, not " + std::to_string(d.curiosity));

    AgentDescriptor out;
    for (std::uint32_t i = 0; i < d.num_discrete_sensors; ++i) out.addDiscreteSensor(discreteValues(d, i));
    for (std::uint32_t i = 0; i < d.num_continuous_sensors; ++i) {
        const std::uint8_t flag = circularFlag(d, i);
        requireFlag(flag, i < VERVE_MAX_CONTINUOUS_SENSORS
                              ? "continuous_sensor_circular[" + std::to_string(i) + "]"
                              : "more_continuous_sensor_circular[" + std::to_string(i - VERVE_MAX_CONTINUOUS_SENSORS) + "]");
        out.addContinuousSensor(flag != 0);
    }
    out.resolution = d.resolution;
    out.numActions = d.num_actions;
    out.allocation = static_cast<RbfAllocation>(d.rbf_allocation);
    out.tauValue = d.tau_value;
    out.tauDiscount = d.tau_discount;
    out.tauEligibility = d.tau_eligibility;
    out.policyMultiplier = d.policy_multiplier;
    out.traceThreshold = d.trace_threshold;
    out.seed = d.seed;
    out.planning = d.planning != 0;
    out.tauModel = d.tau_model;
    out.maxPlanningSteps = d.max_planning_steps;
    out.planningUncertaintyThreshold = d.planning_uncertainty_threshold;
    out.curiosity = static_cast<CuriosityMode>(d.curiosity);
    out.curiosityFactor = d.curiosity_factor;
    out.planningAccumulatesUncertainty = d.planning_accumulates_uncertainty != 0;
    out.learnFromRealSteps = d.learn_from_real_steps != 0;
    out.discretePrediction = static_cast<DiscretePrediction>(d.discrete_prediction);
    out.maxRbfs = d.max_rbfs;
    out.policyWeightBound = d.policy_weight_bound;
    if (d.adaptation > VERVE_ADAPT_ALL) {
        refuse("adaptation has bits no adaptation uses: " + std::to_string(d.adaptation) + " (VERVE_ADAPT_* bits, at most " +
               std::to_string(VERVE_ADAPT_ALL) + ")");
    }
    out.adaptation = static_cast<std::uint32_t>(d.adaptation);
    if (d.sensor_grouping > VERVE_GROUPING_CUSTOM) {
        refuse("sensor_grouping must be 0 (AUTO), 1 (JOINT) or 2 (CUSTOM), not " + std::to_string(d.sensor_grouping));
    }
    if (d.num_sensor_groups > VERVE_MAX_SENSOR_GROUPS) {
        refuse("num_sensor_groups is " + std::to_string(d.num_sensor_groups) + ", at most " +
               std::to_string(VERVE_MAX_SENSOR_GROUPS));
    }
    out.grouping = static_cast<SensorGrouping>(d.sensor_grouping);
    out.sensorGroups.assign(d.sensor_groups, d.sensor_groups + d.num_sensor_groups);
    if (d.num_action_branches > VERVE_MAX_ACTION_BRANCHES) {
        refuse("num_action_branches is " + std::to_string(d.num_action_branches) + ", at most " +
               std::to_string(VERVE_MAX_ACTION_BRANCHES));
    }
    out.actionBranches.assign(d.action_branches, d.action_branches + d.num_action_branches);
    // num_actions 0 with branches: their product (validate() refuses any other number but it).
    if (!out.actionBranches.empty() && d.num_actions == 0) out.setActionBranches(out.actionBranches);
    if (d.num_continuous_actions > VERVE_MAX_CONTINUOUS_ACTIONS) {
        refuse("num_continuous_actions is " + std::to_string(d.num_continuous_actions) + ", at most " +
               std::to_string(VERVE_MAX_CONTINUOUS_ACTIONS));
    }
    out.continuousActions = static_cast<std::uint32_t>(d.num_continuous_actions);
    // num_actions 0 with continuous actions only: the one discrete action they keep.
    if (out.continuousActions != 0 && out.actionBranches.empty() && d.num_actions == 0) out.numActions = 1;
    out.validate(FieldNaming::CAbi);
    return out;
}

void writeDesc(const AgentDescriptor& in, verve_agent_desc& out) {
    const std::uint32_t size = out.struct_size;
    requireKnownSize(size);
    // An older struct cannot hold this agent's sensors: a host would read a count past its arrays.
    const std::size_t sensors = std::max(in.discreteSensors.size(), in.continuousSensors.size());
    if (sensors > sensorsIn(size)) {
        refuse("the agent has " + std::to_string(sensors) + " sensors of a kind; struct_size " + std::to_string(size) +
               " holds 16: pass a VERVE_AGENT_DESC_SIZE_V8 struct");
    }
    verve_agent_desc d = fullDesc(in);
    d.struct_size = size;
    std::memcpy(&out, &d, size);  // an older, smaller struct gets only its own bytes
}

}  // namespace verve::capi
