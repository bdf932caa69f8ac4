#include "io/snapshot_check.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/horizon.hpp"
#include "core/lattice_layout.hpp"
#include "core/sensor_groups.hpp"
#include "verve/error.hpp"

namespace verve::io {
namespace {

[[noreturn]] void fail(const std::string& message) { throw Error(ErrorCode::Format, message); }

// The rewards learned from lie in [-1, 1] and a range includes 0.
void checkRewardRange(float low, float high, const char* which) {
    if (!(low >= -1.0f && low <= 0.0f && high >= 0.0f && high <= 1.0f)) {
        fail(std::string("the ") + which + " is not -1 <= low <= 0 <= high <= 1");
    }
}

void requireSize(const char* field, std::size_t actual, std::size_t expected, const char* why) {
    if (actual != expected) {
        fail(std::string(field) + " holds " + std::to_string(actual) + " values, expected " +
             std::to_string(expected) + " (" + why + ")");
    }
}

void requireFinite(const char* field, const std::vector<float>& values) {
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (!std::isfinite(values[i])) fail(std::string(field) + "[" + std::to_string(i) + "] is not a finite number");
    }
}

void requireBelow(const char* field, const std::vector<std::uint32_t>& values, std::uint64_t limit,
                  const char* what) {
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (values[i] >= limit) {
            fail(std::string(field) + "[" + std::to_string(i) + "] = " + std::to_string(values[i]) +
                 " is out of range (" + what + " is " + std::to_string(limit) + ")");
        }
    }
}

void requireUnique(const char* field, std::vector<std::uint32_t> values) {
    std::sort(values.begin(), values.end());
    const auto dup = std::adjacent_find(values.begin(), values.end());
    if (dup != values.end()) fail(std::string(field) + " lists feature " + std::to_string(*dup) + " twice");
}

std::uint64_t discreteCombinations(const AgentDescriptor& d) {
    std::uint64_t n = 1;
    for (auto c : d.discreteSensors) n *= c;  // bounded by validate() (<= 2^53)
    return n;
}

void checkDescriptor(const AgentDescriptor& d) {
    try {
        d.validate(FieldNaming::CAbi);  // the names a host sees in its verve_agent_desc
    } catch (const Error& e) {
        fail(std::string("descriptor: ") + e.what());
    }
}

void checkFeatures(const AgentSnapshot& s) {
    const std::size_t features = s.featureKeys.size();
    const std::size_t nc = s.descriptor.continuousSensors.size();
    if (features > s.descriptor.rbfBudget()) {
        fail("the save holds " + std::to_string(features) + " RBFs, more than its max_rbfs allows (" +
             std::to_string(s.descriptor.rbfBudget()) + ")");
    }
    // A feature's key: its lattice times the discrete combinations, plus its combination.
    const std::uint64_t combos = discreteCombinations(s.descriptor);
    const std::uint64_t keys = combos * core::lattices(s.descriptor).size();  // <= 2^53 * 64
    for (std::size_t i = 0; i < features; ++i) {
        if (s.featureKeys[i] >= keys) {
            fail("featureKeys[" + std::to_string(i) + "] = " + std::to_string(s.featureKeys[i]) +
                 " is out of range (the descriptor has " + std::to_string(combos) +
                 " discrete combinations in each of its RBF lattices)");
        }
    }
    requireSize("centres", s.centres.size(), features * nc, "features x continuous sensors");
    for (std::size_t i = 0; i < s.centres.size(); ++i) {
        if (!(std::fabs(s.centres[i]) <= 1.0f)) {  // also refuses NaN
            fail("centres[" + std::to_string(i) + "] is not a number in [-1, 1]");
        }
    }
    if (features > 0 && s.stride == 0) fail("weight stride is 0");
    requireSize("weights", s.weights.size(), features * s.stride, "features x stride");
    requireFinite("weights", s.weights);
    for (std::size_t i = 0; i < s.weights.size(); ++i) {
        if (std::fabs(s.weights[i]) > AgentSnapshot::kWeightLimit) {
            fail("weights[" + std::to_string(i) + "] = " + std::to_string(s.weights[i]) +
                 " lies beyond +-1e20, which no learning reaches (corrupt or edited)");
        }
    }
}

void checkTraces(const AgentSnapshot& s) {
    const std::size_t features = s.featureKeys.size();
    requireBelow("traceFeatures", s.traceFeatures, features, "the feature count");
    requireUnique("traceFeatures", s.traceFeatures);
    requireSize("traces", s.traces.size(), s.traceFeatures.size() * s.traceStride, "trace features x trace stride");
    requireFinite("traces", s.traces);
    // The continuous actions' short-term memory: all of it, or none.
    if (!s.continuousValues.empty() || !s.continuousNoise.empty()) {
        requireSize("continuousValues", s.continuousValues.size(), s.descriptor.continuousActions, "one per continuous action");
        requireSize("continuousNoise", s.continuousNoise.size(), s.descriptor.continuousActions, "one per continuous action");
        requireFinite("continuousValues", s.continuousValues);
        requireFinite("continuousNoise", s.continuousNoise);
    }
}

// Adaptation::GroupRates' state: all three lists or none, a rate and a norm per lattice and a
// history value per feature (the core checks the lattice count and the values' ranges).
void checkGroupRates(const AgentSnapshot& s) {
    if (s.groupLogRates.empty() && s.groupNorms.empty() && s.groupHistory.empty()) return;
    requireSize("groupNorms", s.groupNorms.size(), s.groupLogRates.size(), "one per group log rate");
    requireSize("groupHistory", s.groupHistory.size(), s.featureKeys.size(), "one per feature");
    requireFinite("groupLogRates", s.groupLogRates);
    requireFinite("groupNorms", s.groupNorms);
    requireFinite("groupHistory", s.groupHistory);
}

void checkPrevious(const AgentSnapshot& s) {
    if (!s.hasPrevious) return;
    const AgentDescriptor& d = s.descriptor;
    requireBelow("previousFeatures", s.previousFeatures, s.featureKeys.size(), "the feature count");
    requireSize("previousActivations", s.previousActivations.size(), s.previousFeatures.size(),
                "one per previous feature");
    requireFinite("previousActivations", s.previousActivations);
    for (std::size_t i = 0; i < s.previousActivations.size(); ++i) {
        const float a = s.previousActivations[i];
        if (a < 0.0f || a > 1.0f) fail("previousActivations[" + std::to_string(i) + "] = " + std::to_string(a) + " is outside [0, 1]");
    }
    if (s.previousAction >= d.numActions) {
        fail("previousAction = " + std::to_string(s.previousAction) + " is out of range (the agent has " +
             std::to_string(d.numActions) + " actions)");
    }
    requireSize("previousDiscrete", s.previousDiscrete.size(), d.discreteSensors.size(), "one per discrete sensor");
    for (std::size_t i = 0; i < s.previousDiscrete.size(); ++i) {
        const std::int32_t v = s.previousDiscrete[i];
        if (v < 0 || static_cast<std::uint32_t>(v) >= d.discreteSensors[i]) {
            fail("previousDiscrete[" + std::to_string(i) + "] = " + std::to_string(v) +
                 " is out of range (the sensor has " + std::to_string(d.discreteSensors[i]) + " values)");
        }
    }
    requireSize("previousContinuous", s.previousContinuous.size(), d.continuousSensors.size(),
                "one per continuous sensor");
    requireFinite("previousContinuous", s.previousContinuous);
}

}  // namespace

void checkSnapshot(const AgentSnapshot& s) {
    checkDescriptor(s.descriptor);
    checkFeatures(s);
    checkTraces(s);
    checkGroupRates(s);
    checkPrevious(s);
    if (s.rng[0] == 0 && s.rng[1] == 0 && s.rng[2] == 0 && s.rng[3] == 0) {
        fail("rng state is all zero (not a state the generator can be in)");
    }
    if (!(std::isfinite(s.lastDt) && s.lastDt > 0.0f)) fail("lastDt is not a finite number > 0");
    if (!(std::isfinite(s.modelError) && s.modelError >= 0.0f)) fail("modelError is not a finite number >= 0");
    checkRewardRange(s.rewardLow, s.rewardHigh, "reward range");
    checkRewardRange(s.finalRewardLow, s.finalRewardHigh, "final reward range");
    if (!(std::isfinite(s.horizonTrialSeconds) && s.horizonTrialSeconds >= 0.0f)) {
        fail("horizonTrialSeconds is not a finite number >= 0");
    }
    if (s.horizonTrials > core::AdaptiveHorizon::kTrialWindow) fail("horizonTrials is above " + std::to_string(core::AdaptiveHorizon::kTrialWindow));
    if (!(std::isfinite(s.trialSeconds) && s.trialSeconds >= 0.0f)) fail("trialSeconds is not a finite number >= 0");
    if (!(std::isfinite(s.tdMeanSquare) && s.tdMeanSquare >= 0.0f)) fail("tdMeanSquare is not a finite number >= 0");
}

SensorGrouping legacyGrouping(const AgentDescriptor& d) {
    return d.continuousSensors.size() > core::kJointLatticeSensors ? SensorGrouping::Joint : SensorGrouping::Auto;
}

}  // namespace verve::io
