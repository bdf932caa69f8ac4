// Everything an agent is, as plain data: what src/io writes to XML and reads back.
// The core fills it (Agent::snapshot) and rebuilds from it (Agent(const AgentSnapshot&));
// io knows nothing of the algorithm, only these fields.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "verve/agent_descriptor.hpp"

namespace verve {

struct AgentSnapshot {
    // 2: sensor groups, 3: action branches, 4: continuous actions, 5: group rates (each written
    // only by saves that have them).
    static constexpr std::uint32_t kFormatVersion = 5;

    AgentDescriptor descriptor;
    bool learning = true;

    // Features (RBFs). Feature i belongs to discrete combination featureKeys[i] and is centred at
    // centres[i * numContinuous ... + numContinuous) (no centre when there are no continuous sensors).
    std::vector<std::uint64_t> featureKeys;
    std::vector<float> centres;

    // Learned parameters: featureCount rows of `stride` floats (critic, actor, model outputs),
    // each within +-kWeightLimit. Learning cannot reach it (with rewards in [-1, 1] and float
    // steps, a weight stops growing long before 1e16), and below it no update can overflow to
    // inf: a save with a larger weight is corrupt or hostile.
    static constexpr float kWeightLimit = 1e20f;
    std::uint32_t stride = 0;
    std::vector<float> weights;
    // The real rewards learned from, widened to include 0 (-1 <= rewardLow <= 0 <= rewardHigh <= 1):
    // they bound the values TD errors bootstrap from. Saves that predate them read [-1, 1], the
    // bound those versions used.
    float rewardLow = -1.0f;
    float rewardHigh = 1.0f;
    // Of those, the ones that ended a trial (end_episode) are counted here instead, within the same
    // limits: a final reward bounds a value once, not for ever. Saves that predate the split read
    // [0, 0] (their rewardLow/High hold every reward, so their bounds are as wide as they were).
    float finalRewardLow = 0.0f;
    float finalRewardHigh = 0.0f;
    // Whether the model's weights predict how far each continuous sensor moves (true: every agent
    // made now) or where it lands (false: saves that predate the field, 0.1.0 among them, which keep
    // working so).
    bool modelPredictsChange = false;
    // What the adaptations measured (AgentDescriptor::adaptation): the recent mean trial length in
    // seconds over `horizonTrials` trials (at most core::AdaptiveHorizon::kTrialWindow), and the
    // running mean squared TD error. Saves that predate them read 0 (and their descriptor's
    // adaptation reads 0: they keep learning as they did).
    float horizonTrialSeconds = 0.0f;
    std::uint32_t horizonTrials = 0;
    float tdMeanSquare = 0.0f;
    // Adaptation::GroupRates (with two or more sensor groups; otherwise empty): each lattice's log
    // rate and gradient normaliser, and each feature's recent critic change (core/group_rates.hpp).
    // Empty lists in a save of such an agent read as a fresh start (every rate equal).
    std::vector<float> groupLogRates;
    std::vector<float> groupNorms;
    std::vector<float> groupHistory;

    // Live eligibility traces: traceFeatures[j] with traceStride floats in traces (value, policy[A]);
    // a value trace lies in (0, 1], or up to GroupRates::traceLimit with group rates.
    std::uint32_t traceStride = 0;
    std::vector<std::uint32_t> traceFeatures;
    std::vector<float> traces;
    // Seconds of learning updates since the trial began.
    float trialSeconds = 0.0f;
    // The trial's stretches of an unchanged step reward (core/reward_stretch.hpp; the horizon
    // counts the longest when the trial ends): the current one's seconds, the longest finished
    // one's, the latest step reward and whether the trial has learned one. Saves that predate them
    // read the whole trial as one stretch (stretchSeconds = trialSeconds), as the horizon then did.
    float stretchSeconds = 0.0f;
    float stretchLongest = 0.0f;
    float stretchReward = 0.0f;
    bool stretchSeen = false;

    // Short-term memory: the previous step, for the next TD error.
    bool hasPrevious = false;
    std::vector<std::uint32_t> previousFeatures;
    std::vector<float> previousActivations;
    std::uint32_t previousAction = 0;
    std::vector<std::int32_t> previousDiscrete;   // previous observation (model input/targets)
    std::vector<float> previousContinuous;
    float lastDt = 0.1f;  // dt of the latest update (the duration of a terminal transition)
    // Continuous actions (descriptor.continuousActions values each, or none in a save without
    // short-term memory): the latest values, in [-1, 1], and the exploration noise, which runs on
    // from its last value unless noiseRunning is false.
    std::vector<float> continuousValues;
    std::vector<float> continuousNoise;
    bool continuousNoiseRunning = false;

    std::array<std::uint64_t, 4> rng{};  // generator state: same state, same future actions

    // Running statistics worth keeping across a save.
    std::uint64_t steps = 0;
    float modelError = 0.0f;  // running mean squared prediction error
};

}  // namespace verve
