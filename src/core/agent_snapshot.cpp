// Agent <-> AgentSnapshot. Restoring validates every field, so a corrupt save can never build an
// agent that reads out of bounds or carries NaN weights.
#include <cmath>
#include <string>

#include "core/agent_impl.hpp"
#include "core/sensor_groups.hpp"

namespace verve {
namespace {

[[noreturn]] void corrupt(const std::string& message) { throw Error(ErrorCode::Format, "invalid agent data: " + message); }

void requireFinite(const std::vector<float>& values, const char* what) {
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (!std::isfinite(values[i])) corrupt(std::string(what) + " value " + std::to_string(i) + " is not finite");
    }
}

void requireSize(std::size_t actual, std::size_t expected, const char* what) {
    if (actual != expected) {
        corrupt(std::string(what) + " has " + std::to_string(actual) + " values, expected " + std::to_string(expected));
    }
}

// A reward range a save may hold: the rewards learned from lie in [-1, 1] and the range includes 0.
void requireRewardRange(float low, float high, const char* which) {
    if (!(low >= -1.0f && low <= 0.0f && high >= 0.0f && high <= 1.0f)) {
        corrupt(std::string("the ") + which + " must satisfy -1 <= low <= 0 <= high <= 1");
    }
}

// The continuous actions' short-term memory: none (a save without it) starts them afresh.
void restoreContinuous(const AgentSnapshot& snap, Agent::Impl& s) {
    const std::size_t n = s.desc.continuousActions;
    if (snap.continuousValues.empty() && snap.continuousNoise.empty()) {
        if (snap.continuousNoiseRunning) corrupt("the continuous actions' noise runs but is not saved");
        return;
    }
    requireSize(snap.continuousValues.size(), n, "continuous action values");
    requireSize(snap.continuousNoise.size(), n, "continuous action noise");
    requireFinite(snap.continuousNoise, "continuous action noise");
    for (float v : snap.continuousValues) {
        if (!(v >= -1.0f && v <= 1.0f)) corrupt("a continuous action's value lies outside [-1, 1]");
    }
    for (float v : snap.continuousNoise) {
        if (std::fabs(v) > core::ContinuousPolicy::kNoiseLimit) corrupt("a continuous action's noise is beyond any draw");
    }
    s.continuous.restore(snap.continuousNoise, snap.continuousNoiseRunning, snap.continuousValues);
}

// The group rates (core/group_rates.hpp): none in a save (or empty lists) start them afresh, as a
// new agent's are, with a history of 0 for every restored feature.
void restoreGroupRates(const AgentSnapshot& snap, const core::StateRepresentation& rep, core::GroupRates& rates,
                       std::size_t features) {
    const bool saved = !snap.groupLogRates.empty() || !snap.groupNorms.empty() || !snap.groupHistory.empty();
    if (!saved) return rates.grow(static_cast<std::uint32_t>(features));
    if (!rates.active()) corrupt("group rates are saved for an agent without two or more sensor groups that adapt their rates");
    requireSize(snap.groupLogRates.size(), rates.lattices(), "group log rates");
    requireSize(snap.groupNorms.size(), rates.lattices(), "group norms");
    requireSize(snap.groupHistory.size(), features, "group history");
    for (float v : snap.groupLogRates) {
        if (!(std::fabs(v) <= core::GroupRates::kLogLimit)) corrupt("a group's log rate lies beyond +-6 or is not finite");
    }
    for (float v : snap.groupNorms) {
        if (!(v >= 0.0f && std::isfinite(v))) corrupt("a group's norm is negative or not finite");
    }
    for (float v : snap.groupHistory) {
        if (!(std::fabs(v) <= core::GroupRates::kHistoryLimit)) corrupt("a feature's group history lies beyond +-1e6 or is not finite");
    }
    rates.restore(rep, snap.groupLogRates, snap.groupNorms, snap.groupHistory);
}

}  // namespace

std::unique_ptr<Agent::Impl> restoreAgent(const AgentSnapshot& snap) {
    AgentDescriptor desc = snap.descriptor;
    // Saved features are restored one by one, whatever the allocation mode.
    desc.allocation = RbfAllocation::Dynamic;
    try {
        desc.validate();
    } catch (const Error& e) {
        corrupt(e.what());
    }
    auto impl = std::make_unique<Agent::Impl>(desc);
    impl->desc.allocation = snap.descriptor.allocation;
    Agent::Impl& s = *impl;

    const std::size_t count = snap.featureKeys.size();
    if (count > desc.rbfBudget()) corrupt("more RBFs (" + std::to_string(count) + ") than max_rbfs allows");
    const std::uint32_t nc = s.rep.numContinuous();
    requireSize(snap.centres.size(), count * nc, "RBF centres");
    requireFinite(snap.centres, "RBF centre");
    if (snap.stride != s.weights.stride()) {
        corrupt("weight stride is " + std::to_string(snap.stride) + ", the descriptor needs " + std::to_string(s.weights.stride()));
    }
    requireSize(snap.weights.size(), count * s.weights.stride(), "weights");
    requireFinite(snap.weights, "weight");
    for (std::size_t i = 0; i < snap.weights.size(); ++i) {
        if (std::fabs(snap.weights[i]) > AgentSnapshot::kWeightLimit) {
            corrupt("weight " + std::to_string(i) + " lies beyond +-1e20, which no learning reaches");
        }
    }
    for (std::size_t i = 0; i < count; ++i) {
        if (snap.featureKeys[i] >= s.rep.keyCount()) corrupt("feature " + std::to_string(i) + " has an out-of-range discrete key");
        for (std::uint32_t d = 0; d < nc; ++d) {
            const float c = snap.centres[i * nc + d];
            if (c < -1.0f || c > 1.0f) corrupt("RBF centre of feature " + std::to_string(i) + " lies outside [-1, 1]");
        }
        s.rep.addFeature(snap.featureKeys[i], snap.centres.data() + i * nc);
    }
    if (snap.descriptor.allocation == RbfAllocation::Full) s.rep.finishLattice();  // as it was made
    s.weights.resize(static_cast<std::uint32_t>(count));
    s.weights.data() = snap.weights;
    requireRewardRange(snap.rewardLow, snap.rewardHigh, "reward range");
    requireRewardRange(snap.finalRewardLow, snap.finalRewardHigh, "final reward range");
    s.brain->rewards = core::RewardRange{snap.rewardLow, snap.rewardHigh, snap.finalRewardLow, snap.finalRewardHigh};
    s.brain->modelPredictsChange = snap.modelPredictsChange;
    if (!(std::isfinite(snap.horizonTrialSeconds) && snap.horizonTrialSeconds >= 0.0f) ||
        snap.horizonTrials > core::AdaptiveHorizon::kTrialWindow) {
        corrupt("the horizon's trial statistics must be a finite length >= 0 over at most " +
                std::to_string(core::AdaptiveHorizon::kTrialWindow) + " trials");
    }
    if (!(std::isfinite(snap.tdMeanSquare) && snap.tdMeanSquare >= 0.0f)) corrupt("the mean squared TD error must be finite and >= 0");
    s.brain->horizon.meanTrialSeconds = snap.horizonTrialSeconds;
    s.brain->horizon.trials = snap.horizonTrials;
    s.brain->tdScale.meanSquare = snap.tdMeanSquare;
    restoreGroupRates(snap, s.rep, s.brain->groupRates, count);

    // Traces: optional (an empty list restores none).
    if (!snap.traceFeatures.empty() || !snap.traces.empty()) {
        if (snap.traceStride != s.td.traceStride()) corrupt("trace stride does not match the number of actions");
        requireSize(snap.traces.size(), snap.traceFeatures.size() * s.td.traceStride(), "traces");
        requireFinite(snap.traces, "trace");
        std::vector<bool> seen(count, false);
        const std::uint32_t stride = s.td.traceStride();
        const float limit = s.brain->groupRates.traceLimit(s.rep);
        for (std::size_t i = 0; i < snap.traceFeatures.size(); ++i) {
            const auto f = snap.traceFeatures[i];
            if (f >= count || seen[f]) corrupt("trace list names feature " + std::to_string(f) + " twice or out of range");
            seen[f] = true;
            // A live value trace lies in (0, 1] and bounds the feature's policy traces (a continuous
            // action's, which have either sign, in size).
            const float* e = snap.traces.data() + i * stride;
            if (!(e[0] > 0.0f && e[0] <= limit)) {
                corrupt("value trace of feature " + std::to_string(f) + " is outside (0, " + std::to_string(limit) + "]");
            }
            const std::uint32_t signedFrom = 1 + s.td.columns();
            for (std::uint32_t k = 1; k < stride; ++k) {
                if (e[k] < (k < signedFrom ? 0.0f : -e[0]) || e[k] > e[0]) {
                    corrupt("policy trace of feature " + std::to_string(f) + " is outside the value trace's range");
                }
            }
        }
        s.td.restore(snap.traceFeatures, snap.traces, static_cast<std::uint32_t>(count));
    }

    if (!(std::isfinite(snap.trialSeconds) && snap.trialSeconds >= 0.0f)) corrupt("the trial's seconds must be finite and >= 0");
    s.trialSeconds = snap.trialSeconds;
    if (!(std::isfinite(snap.stretchSeconds) && snap.stretchSeconds >= 0.0f && std::isfinite(snap.stretchLongest) &&
          snap.stretchLongest >= 0.0f && snap.stretchReward >= -1.0f && snap.stretchReward <= 1.0f)) {
        corrupt("the trial's reward stretches must be finite lengths >= 0 and a reward within [-1, 1]");
    }
    s.stretch = core::RewardStretch{snap.stretchSeconds, snap.stretchLongest, snap.stretchReward, snap.stretchSeen};
    s.hasPrevious = snap.hasPrevious;
    if (snap.hasPrevious) {
        requireSize(snap.previousActivations.size(), snap.previousFeatures.size(), "previous activations");
        requireFinite(snap.previousActivations, "previous activation");
        // An RBF's activation lies in [0, 1]; a larger one would scale the next update's steps
        // (a fuzzed save's activations overflowed model weights in one update).
        for (float a : snap.previousActivations) {
            if (a < 0.0f || a > 1.0f) corrupt("a previous activation lies outside [0, 1]");
        }
        for (std::size_t i = 0; i < snap.previousFeatures.size(); ++i) {
            if (snap.previousFeatures[i] >= count) corrupt("previous step names a feature out of range");
            s.previous.push_back(core::ActiveFeature{snap.previousFeatures[i], snap.previousActivations[i]});
        }
        if (snap.previousAction >= desc.numActions) corrupt("previous action out of range");
        s.previousAction = snap.previousAction;
        requireSize(snap.previousDiscrete.size(), desc.discreteSensors.size(), "previous discrete observation");
        requireSize(snap.previousContinuous.size(), desc.continuousSensors.size(), "previous continuous observation");
        for (std::size_t i = 0; i < snap.previousDiscrete.size(); ++i) {
            const auto v = snap.previousDiscrete[i];
            if (v < 0 || static_cast<std::uint32_t>(v) >= desc.discreteSensors[i]) corrupt("previous discrete value out of range");
        }
        requireFinite(snap.previousContinuous, "previous continuous observation");
        s.previousDiscrete = snap.previousDiscrete;
        s.previousContinuous = snap.previousContinuous;
    }
    restoreContinuous(snap, s);
    if (!std::isfinite(snap.lastDt) || snap.lastDt <= 0.0f) corrupt("last dt must be finite and > 0");
    s.lastDt = snap.lastDt;
    if (snap.rng[0] == 0 && snap.rng[1] == 0 && snap.rng[2] == 0 && snap.rng[3] == 0) corrupt("random generator state is all zero");
    s.rng.setState(snap.rng);
    s.learning = snap.learning;
    if (!std::isfinite(snap.modelError) || snap.modelError < 0.0f) corrupt("model error must be finite and >= 0");
    s.stats.steps = snap.steps;
    s.stats.modelError = snap.modelError;
    s.stats.rbfCount = s.rep.featureCount();
    s.stats.liveTraces = s.td.liveCount();
    s.latestValue = s.hasPrevious ? s.td.value(s.weights, s.previous) : 0.0f;
    s.stats.value = core::bounded(s.latestValue, s.constantsFor(s.lastDt).values);
    return impl;
}

void snapshotBrain(const BrainState& brain, AgentSnapshot& snap) {
    snap.descriptor = brain.desc;
    // A save keeps the groups it was made with, whatever a later library's Auto would choose.
    if (brain.desc.grouping == SensorGrouping::Auto && core::sensorGroups(brain.desc).size() > 1) {
        snap.descriptor.grouping = SensorGrouping::Custom;
        snap.descriptor.sensorGroups = core::sensorGroups(brain.desc);
    }
    brain.rep.features(snap.featureKeys, snap.centres);
    snap.stride = brain.weights.stride();
    snap.weights = brain.weights.data();
    snap.rewardLow = brain.rewards.low;
    snap.rewardHigh = brain.rewards.high;
    snap.finalRewardLow = brain.rewards.finalLow;
    snap.finalRewardHigh = brain.rewards.finalHigh;
    snap.modelPredictsChange = brain.modelPredictsChange;
    snap.horizonTrialSeconds = brain.horizon.meanTrialSeconds;
    snap.horizonTrials = brain.horizon.trials;
    snap.tdMeanSquare = brain.tdScale.meanSquare;
    snap.groupLogRates = brain.groupRates.logRates();
    snap.groupNorms = brain.groupRates.norms();
    snap.groupHistory = brain.groupRates.history();
    snap.traceStride = 1 + core::ActionBranches::of(brain.desc).columns + 2 * brain.desc.continuousActions;
}

Agent::Agent(const AgentSnapshot& snapshot) : impl_(restoreAgent(snapshot)) {}

AgentSnapshot Agent::snapshot() const {
    const Impl& s = *impl_;
    AgentSnapshot snap;
    snapshotBrain(*s.brain, snap);
    snap.learning = s.learning;
    snap.traceStride = s.td.traceStride();
    snap.traceFeatures = s.td.liveFeatures();
    snap.traces = s.td.liveTraces();
    snap.trialSeconds = s.trialSeconds;
    snap.stretchSeconds = s.stretch.seconds;
    snap.stretchLongest = s.stretch.longest;
    snap.stretchReward = s.stretch.last;
    snap.stretchSeen = s.stretch.seen;
    snap.hasPrevious = s.hasPrevious;
    for (const auto& f : s.previous) {
        snap.previousFeatures.push_back(f.index);
        snap.previousActivations.push_back(f.activation);
    }
    snap.previousAction = s.previousAction;
    snap.previousDiscrete = s.previousDiscrete;
    snap.previousContinuous = s.previousContinuous;
    snap.lastDt = s.lastDt;
    if (s.desc.continuousActions != 0) {
        snap.continuousValues = s.continuous.values();
        snap.continuousNoise = s.continuous.noise();
        snap.continuousNoiseRunning = s.continuous.noiseRunning();
    }
    snap.rng = s.rng.state();
    snap.steps = s.stats.steps;
    snap.modelError = s.stats.modelError;
    return snap;
}

}  // namespace verve
