// The binary payload's layout, written once: transferPayload walks AgentSnapshot's fields in
// order through a writer (snapshot_binary_write.cpp) or a reader (snapshot_binary_read.cpp), so
// the two can never disagree. An Io provides:
//   value(name, T&)          one integer or float
//   flag(name, bool&)        one byte, 0 or 1
//   choice(name, Enum&, max) one byte, 0..max
//   list(name, vector<T>&)   u64 count, then the items
//   items(name, vector<T>&, itemBytes, f)  u64 count, then f(io, item) for each item
#pragma once
#include <cstdint>
#include <type_traits>

#include "io/snapshot_check.hpp"
#include "verve/agent_snapshot.hpp"

namespace verve::io {

template <typename Io, typename Descriptor>
void transferDescriptor(Io& io, Descriptor& d) {
    io.value("resolution", d.resolution);
    io.value("actions", d.numActions);
    io.choice("allocation", d.allocation, RbfAllocation::Full);
    io.value("tau_value", d.tauValue);
    io.value("tau_discount", d.tauDiscount);
    io.value("tau_eligibility", d.tauEligibility);
    io.value("policy_multiplier", d.policyMultiplier);
    io.value("trace_threshold", d.traceThreshold);
    io.value("seed", d.seed);
    io.flag("planning", d.planning);
    io.value("tau_model", d.tauModel);
    io.value("max_planning_steps", d.maxPlanningSteps);
    io.value("planning_uncertainty_threshold", d.planningUncertaintyThreshold);
    io.choice("curiosity", d.curiosity, CuriosityMode::Progress);
    io.value("curiosity_factor", d.curiosityFactor);
    io.flag("planning_accumulates_uncertainty", d.planningAccumulatesUncertainty);
    io.flag("learn_from_real_steps", d.learnFromRealSteps);
    io.choice("discrete_prediction", d.discretePrediction, DiscretePrediction::Ordinal);
    io.value("max_rbfs", d.maxRbfs);
    io.list("discrete_sensors", d.discreteSensors);
    io.items("continuous_sensors", d.continuousSensors, 1, [](Io& in, auto& sensor) { in.flag("circular", sensor.circular); });
}

// `shortTerm`: whether the traces and the previous step follow (SaveOptions::includeTraces).
// `version`: the binary format version of the save (fields added later are read only from saves
// that have them).
template <typename Io, typename Snapshot, typename Flag>
void transferPayload(Io& io, Snapshot& s, Flag& shortTerm, std::uint32_t version) {
    transferDescriptor(io, s.descriptor);
    io.flag("learning", s.learning);
    io.value("steps", s.steps);
    io.value("model_error", s.modelError);
    io.value("last_dt", s.lastDt);
    for (auto& word : s.rng) io.value("rng", word);
    io.list("feature_keys", s.featureKeys);
    io.list("centres", s.centres);
    io.value("stride", s.stride);
    io.list("weights", s.weights);
    if (version >= 2) {
        io.value("reward_low", s.rewardLow);
        io.value("reward_high", s.rewardHigh);
    }
    if (version >= 3) io.flag("model_predicts_change", s.modelPredictsChange);
    if (version >= 4) {
        io.value("final_reward_low", s.finalRewardLow);
        io.value("final_reward_high", s.finalRewardHigh);
    }
    if (version >= 5) {
        io.value("adaptation", s.descriptor.adaptation);
        io.value("horizon_trial_seconds", s.horizonTrialSeconds);
        io.value("horizon_trials", s.horizonTrials);
        io.value("td_mean_square", s.tdMeanSquare);
    } else if constexpr (!std::is_const_v<Snapshot>) {
        s.descriptor.adaptation = 0;  // an older save keeps every setting as given
    }
    if (version >= 6) {
        io.choice("grouping", s.descriptor.grouping, SensorGrouping::Custom);
        io.list("sensor_groups", s.descriptor.sensorGroups);
    } else if constexpr (!std::is_const_v<Snapshot>) {
        s.descriptor.grouping = legacyGrouping(s.descriptor);
    }
    if (version >= 7) io.list("action_branches", s.descriptor.actionBranches);
    if (version >= 8) io.value("continuous_actions", s.descriptor.continuousActions);
    if (version >= 9) {
        io.list("group_log_rates", s.groupLogRates);
        io.list("group_norms", s.groupNorms);
        io.list("group_history", s.groupHistory);
    }
    io.flag("short_term_memory", shortTerm);
    if (!shortTerm) return;
    if (version >= 5) io.value("trial_seconds", s.trialSeconds);
    if (version >= 8) {
        io.value("stretch_seconds", s.stretchSeconds);
        io.value("stretch_longest", s.stretchLongest);
        io.value("stretch_reward", s.stretchReward);
        io.flag("stretch_seen", s.stretchSeen);
    } else if constexpr (!std::is_const_v<Snapshot>) {
        s.stretchSeconds = s.trialSeconds;  // the whole trial one stretch, as the horizon then saw it
    }
    io.value("trace_stride", s.traceStride);
    io.list("trace_features", s.traceFeatures);
    io.list("traces", s.traces);
    // Only agents with continuous actions have these: every other save's bytes stay as before.
    if (version >= 8 && s.descriptor.continuousActions != 0) {
        io.list("continuous_values", s.continuousValues);
        io.list("continuous_noise", s.continuousNoise);
        io.flag("continuous_noise_running", s.continuousNoiseRunning);
    }
    io.flag("has_previous", s.hasPrevious);
    if (!s.hasPrevious) return;
    io.value("previous_action", s.previousAction);
    io.list("previous_features", s.previousFeatures);
    io.list("previous_activations", s.previousActivations);
    io.list("previous_discrete", s.previousDiscrete);
    io.list("previous_continuous", s.previousContinuous);
}

}  // namespace verve::io
