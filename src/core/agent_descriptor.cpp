#include <algorithm>
#include <cmath>
#include <string>

#include "core/lattice_layout.hpp"
#include "core/predictive_model.hpp"
#include "core/sensor_groups.hpp"
#include "verve/agent.hpp"

namespace verve {
namespace {

using Limits = DescriptorLimits;

// A field's name in the C++ API and in the C ABI (verve_agent_desc), for messages.
struct Field {
    const char* cpp;
    const char* c;
};
constexpr Field kNumActions{"numActions", "num_actions"};
constexpr Field kDiscreteSensors{"discreteSensors", "num_discrete_sensors"};
constexpr Field kDiscreteValues{"discreteSensors", "discrete_sensor_values"};
constexpr Field kContinuousSensors{"continuousSensors", "num_continuous_sensors"};
constexpr Field kResolution{"resolution", "resolution"};
constexpr Field kAllocation{"allocation", "rbf_allocation"};
constexpr Field kTauValue{"tauValue", "tau_value"};
constexpr Field kTauDiscount{"tauDiscount", "tau_discount"};
constexpr Field kTauEligibility{"tauEligibility", "tau_eligibility"};
constexpr Field kTauModel{"tauModel", "tau_model"};
constexpr Field kPolicyMultiplier{"policyMultiplier", "policy_multiplier"};
constexpr Field kTraceThreshold{"traceThreshold", "trace_threshold"};
constexpr Field kMaxPlanningSteps{"maxPlanningSteps", "max_planning_steps"};
constexpr Field kUncertaintyThreshold{"planningUncertaintyThreshold", "planning_uncertainty_threshold"};
constexpr Field kCuriosity{"curiosity", "curiosity"};
constexpr Field kCuriosityFactor{"curiosityFactor", "curiosity_factor"};
constexpr Field kDiscretePrediction{"discretePrediction", "discrete_prediction"};
constexpr Field kMaxRbfs{"maxRbfs", "max_rbfs"};
constexpr Field kPolicyWeightBound{"policyWeightBound", "policy_weight_bound"};
constexpr Field kAdaptation{"adaptation", "adaptation"};
constexpr Field kGrouping{"grouping", "sensor_grouping"};
constexpr Field kSensorGroups{"sensorGroups", "sensor_groups"};
constexpr Field kActionBranches{"actionBranches", "action_branches"};
constexpr Field kPlanning{"planning", "planning"};
constexpr Field kContinuousActions{"continuousActions", "num_continuous_actions"};

class Validator {
public:
    explicit Validator(FieldNaming naming) : naming_(naming) {}

    std::string name(Field f) const { return naming_ == FieldNaming::CAbi ? f.c : f.cpp; }
    // An enumerator as each API spells it: "Joint" / "JOINT".
    std::string value(const char* cpp, const char* c) const { return naming_ == FieldNaming::CAbi ? c : cpp; }
    std::string name(Field f, std::size_t i) const { return name(f) + "[" + std::to_string(i) + "]"; }

    void require(bool ok, const std::string& message) const {
        if (!ok) throw Error(ErrorCode::InvalidArgument, "invalid agent descriptor: " + message);
    }
    void requireTimeConstant(float tau, Field f) const {
        require(std::isfinite(tau) && tau >= 0.0f, name(f) + " must be a finite number >= 0");
    }
    void requireAtMost(std::uint64_t value, std::uint64_t limit, const std::string& what) const {
        require(value <= limit, what + " is " + std::to_string(value) + ", at most " + std::to_string(limit));
    }

private:
    FieldNaming naming_;
};

// The product of the value counts, saturating just above the limit: checked before each multiply,
// since a product past the limit can wrap (2^19 x 2^19 x 2^26 is 2^64, which is 0).
std::uint64_t combinations(const AgentDescriptor& d) {
    std::uint64_t n = 1;
    for (auto c : d.discreteSensors) {
        if (c != 0 && n > Limits::kMaxDiscreteCombinations / c) return Limits::kMaxDiscreteCombinations + 1;
        n *= c;
    }
    return n;
}

// resolution^(sensors in the lattice) RBFs per lattice and discrete combination, summed (saturating).
std::uint64_t fullLatticeSize(const AgentDescriptor& d) {
    std::uint64_t total = 0;
    for (const auto& lattice : core::lattices(d)) {
        std::uint64_t n = combinations(d);
        for (auto bits = lattice.sensors; bits != 0 && n <= Limits::kMaxFullLattice; bits &= bits - 1) n *= lattice.resolution;
        total += std::min(n, Limits::kMaxFullLattice + 1);
        if (total > Limits::kMaxFullLattice) return Limits::kMaxFullLattice + 1;
    }
    return total;
}

void validateGroups(const AgentDescriptor& d, const Validator& v) {
    v.require(d.grouping == SensorGrouping::Auto || d.grouping == SensorGrouping::Joint ||
                  d.grouping == SensorGrouping::Custom,
              v.name(kGrouping) + " must be Auto, Joint or Custom");
    if (d.grouping != SensorGrouping::Custom) {
        v.require(d.sensorGroups.empty(), v.name(kSensorGroups) + " is only read with Custom " + v.name(kGrouping));
        return;
    }
    const std::size_t n = d.continuousSensors.size();
    v.require(!d.sensorGroups.empty() || n == 0, "Custom " + v.name(kGrouping) + " needs at least one group in " +
                                                     v.name(kSensorGroups));
    v.requireAtMost(d.sensorGroups.size(), Limits::kMaxSensorGroups, "the number of " + v.name(kSensorGroups));
    const std::uint64_t all = n >= 64 ? ~std::uint64_t(0) : (std::uint64_t(1) << n) - 1;
    std::uint64_t covered = 0;
    for (std::size_t i = 0; i < d.sensorGroups.size(); ++i) {
        const std::uint64_t g = d.sensorGroups[i];
        v.require(g != 0, v.name(kSensorGroups, i) + " is empty");
        v.require((g & ~all) == 0, v.name(kSensorGroups, i) + " names a continuous sensor the agent does not have (bit " +
                                       std::to_string(63 - __builtin_clzll(g)) + ")");
        covered |= g;
    }
    if (covered != all) {
        v.require(false, "continuous sensor " + std::to_string(__builtin_ctzll(all & ~covered)) + " is in none of " +
                             v.name(kSensorGroups) + ": its readings would be ignored");
    }
}

// Every lattice within what one lattice may span, and no more lattices than a group mask holds
// (Joint over many sensors, Custom groups too wide, Auto's 2n - 1 groups beyond 32 sensors).
void validateLattices(const AgentDescriptor& d, const Validator& v) {
    const auto groups = core::sensorGroups(d);
    v.require(groups.size() <= Limits::kMaxSensorGroups,
              std::to_string(d.continuousSensors.size()) + " continuous sensors make " + std::to_string(groups.size()) +
                  " " + v.value("Auto", "AUTO") + " " + v.name(kSensorGroups) + " (one per sensor and per neighbouring pair), at most " +
                  std::to_string(Limits::kMaxSensorGroups) + "; list " + v.value("Custom", "CUSTOM") + " " + v.name(kSensorGroups));
    for (std::size_t i = 0; i < groups.size(); ++i) {
        const int n = __builtin_popcountll(groups[i]);
        if (n <= static_cast<int>(Limits::kMaxLatticeSensors)) continue;
        v.require(false, d.grouping == SensorGrouping::Custom
                             ? v.name(kSensorGroups, i) + " spans " + std::to_string(n) + " continuous sensors, one lattice at most " +
                                   std::to_string(Limits::kMaxLatticeSensors) + "; split it into smaller groups"
                             : v.value("Joint", "JOINT") + " " + v.name(kGrouping) + " puts all " + std::to_string(n) +
                                   " continuous sensors in one lattice, which spans at most " +
                                   std::to_string(Limits::kMaxLatticeSensors) + "; use " + v.value("Auto", "AUTO") + " or " +
                                   v.value("Custom", "CUSTOM") + " " + v.name(kGrouping));
    }
}

void validateBranches(const AgentDescriptor& d, const Validator& v) {
    if (d.actionBranches.empty()) return;
    v.requireAtMost(d.actionBranches.size(), Limits::kMaxActionBranches, "the number of " + v.name(kActionBranches));
    std::uint64_t product = 1;
    for (std::size_t i = 0; i < d.actionBranches.size(); ++i) {
        v.require(d.actionBranches[i] >= 1, v.name(kActionBranches, i) + " must be at least 1");
        product = std::min<std::uint64_t>(product * d.actionBranches[i], std::uint64_t(Limits::kMaxActions) + 1);
    }
    v.require(product <= Limits::kMaxActions, "the product of " + v.name(kActionBranches) + " (the combined actions) is above " +
                                                  std::to_string(Limits::kMaxActions));
    v.require(product == d.numActions, v.name(kNumActions) + " must be the product of " + v.name(kActionBranches) + " (" +
                                           std::to_string(product) + "), got " + std::to_string(d.numActions));
    // The model predicts per combined action; its planner chooses from one action set.
    v.require(!d.planning, v.name(kPlanning) + " needs one action set (no " + v.name(kActionBranches) + ")");
}

// Every size derived from several fields at once: each alone may be in range while their
// product asks for gigabytes or overflows 32 bits.
void validateDerivedSizes(const AgentDescriptor& d, const Validator& v) {
    v.require(combinations(d) <= Limits::kMaxDiscreteCombinations,
              "the product of " + v.name(kDiscreteValues) + " (discrete value combinations) is above 2^53");
    if (d.allocation == RbfAllocation::Full) {
        v.require(fullLatticeSize(d) <= Limits::kMaxFullLattice,
                  "full " + v.name(kAllocation) + " would create " + v.name(kResolution) +
                      "^(sensors in a group) RBFs per group and discrete value combination, more than " +
                      std::to_string(Limits::kMaxFullLattice) + " in all; use dynamic allocation");
        v.require(fullLatticeSize(d) <= d.rbfBudget(),
                  "full " + v.name(kAllocation) + " would create more RBFs than " + v.name(kMaxRbfs) + " allows");
    }
    if (!d.planning) return;
    const std::uint64_t outputs = core::PredictiveModel::outputsPerAction(d);
    v.require(outputs <= Limits::kMaxModelOutputs,
              "planning predicts " + std::to_string(outputs) + " outputs per action (one per value of each of " +
                  v.name(kDiscreteValues) + " with categorical " + v.name(kDiscretePrediction) + "), at most " +
                  std::to_string(Limits::kMaxModelOutputs) + "; use fewer values or ordinal prediction");
    const std::uint64_t perRbf = 1 + std::uint64_t(d.numActions) * (1 + outputs);
    v.require(perRbf <= Limits::kMaxWeightsPerRbf,
              "planning needs " + std::to_string(perRbf) + " weights per RBF (" + v.name(kNumActions) +
                  " x model outputs), at most " + std::to_string(Limits::kMaxWeightsPerRbf) +
                  "; use fewer actions or discrete values");
}

}  // namespace

void AgentDescriptor::validate(FieldNaming naming) const {
    const Validator v(naming);
    validateBranches(*this, v);  // first: a bad branch is what a wrong numActions would come from
    v.require(numActions >= 1, v.name(kNumActions) + " must be at least 1");
    v.requireAtMost(numActions, Limits::kMaxActions, v.name(kNumActions));
    v.requireAtMost(discreteSensors.size(), Limits::kMaxSensors, v.name(kDiscreteSensors));
    v.requireAtMost(continuousSensors.size(), Limits::kMaxSensors, v.name(kContinuousSensors));
    for (std::size_t i = 0; i < discreteSensors.size(); ++i) {
        v.require(discreteSensors[i] >= 1, v.name(kDiscreteValues, i) + " must be at least 1");
        v.requireAtMost(discreteSensors[i], Limits::kMaxDiscreteValues, v.name(kDiscreteValues, i));
    }
    if (!continuousSensors.empty()) {
        v.require(resolution >= 1 && resolution <= Limits::kMaxResolution,
                  v.name(kResolution) + " must be in [1, " + std::to_string(Limits::kMaxResolution) + "]");
    }
    v.requireTimeConstant(tauValue, kTauValue);
    v.requireTimeConstant(tauDiscount, kTauDiscount);
    v.requireTimeConstant(tauEligibility, kTauEligibility);
    v.requireTimeConstant(tauModel, kTauModel);
    v.require((adaptation & ~Adaptation::All) == 0,
              v.name(kAdaptation) + " has bits no adaptation uses (known: " + std::to_string(Adaptation::All) + ")");
    v.require(std::isfinite(policyMultiplier) && policyMultiplier >= 0.0f,
              v.name(kPolicyMultiplier) + " must be a finite number >= 0");
    v.require(std::isfinite(traceThreshold) && traceThreshold > 0.0f && traceThreshold < 1.0f,
              v.name(kTraceThreshold) + " must be in (0, 1)");
    v.require(std::isfinite(policyWeightBound) && policyWeightBound >= 0.0f,
              v.name(kPolicyWeightBound) + " must be a finite number >= 0 (0: unbounded)");
    v.require(allocation == RbfAllocation::Dynamic || allocation == RbfAllocation::Full,
              v.name(kAllocation) + " must be Dynamic or Full");
    v.requireAtMost(maxPlanningSteps, Limits::kMaxPlanningSteps, v.name(kMaxPlanningSteps));
    v.require(std::isfinite(planningUncertaintyThreshold) && planningUncertaintyThreshold >= 0.0f,
              v.name(kUncertaintyThreshold) + " must be a finite number >= 0");
    v.require(curiosity == CuriosityMode::None || curiosity == CuriosityMode::Novelty ||
                  curiosity == CuriosityMode::Progress,
              v.name(kCuriosity) + " must be None, Novelty or Progress");
    v.require(discretePrediction == DiscretePrediction::Categorical || discretePrediction == DiscretePrediction::Ordinal,
              v.name(kDiscretePrediction) + " must be Categorical or Ordinal");
    v.require(std::isfinite(curiosityFactor) && curiosityFactor >= 0.0f,
              v.name(kCuriosityFactor) + " must be a finite number >= 0");
    v.requireAtMost(maxRbfs, Limits::kMaxRbfs, v.name(kMaxRbfs));
    v.requireAtMost(continuousActions, Limits::kMaxContinuousActions, v.name(kContinuousActions));
    // The model predicts per discrete action; a continuous one has no such index.
    v.require(continuousActions == 0 || !planning, v.name(kPlanning) + " needs discrete actions only (no " +
                                                      v.name(kContinuousActions) + ")");
    validateGroups(*this, v);
    validateLattices(*this, v);
    validateDerivedSizes(*this, v);
}

}  // namespace verve
