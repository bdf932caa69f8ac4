// Shared helpers for the save/load tests: agents with something learned, exact comparisons.
#pragma once
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "verve/agent.hpp"
#include "verve/brain.hpp"

namespace verve::iotest {

// Two continuous sensors (one circular), one discrete sensor, 3 actions.
inline AgentDescriptor mixedDescriptor(std::uint64_t seed = 7) {
    AgentDescriptor d;
    d.addDiscreteSensor(3).addContinuousSensor(false).addContinuousSensor(true);
    d.numActions = 3;
    d.resolution = 8;
    d.seed = seed;
    return d;
}

// Full lattice, planning, progress curiosity, every non-default planning variant, an RBF budget.
inline AgentDescriptor plannerDescriptor() {
    AgentDescriptor d = mixedDescriptor();
    d.allocation = RbfAllocation::Full;
    d.resolution = 5;
    d.planning = true;
    d.curiosity = CuriosityMode::Progress;
    d.curiosityFactor = 0.25f;
    d.maxPlanningSteps = 50;
    d.planningAccumulatesUncertainty = false;
    d.learnFromRealSteps = false;
    d.discretePrediction = DiscretePrediction::Ordinal;
    d.maxRbfs = 5000;
    return d;
}

// Six continuous sensors: Auto gives each a lattice and each neighbouring pair one (11 groups).
inline AgentDescriptor groupedDescriptor() {
    AgentDescriptor d = mixedDescriptor();
    for (int i = 0; i < 4; ++i) d.addContinuousSensor(i == 2);
    return d;
}

// Custom groups over full lattices: sensor 0 with 2, and 1 alone.
inline AgentDescriptor customGroupsDescriptor() {
    AgentDescriptor d = mixedDescriptor();
    d.addContinuousSensor(false);
    d.resolution = 5;
    d.allocation = RbfAllocation::Full;
    d.grouping = SensorGrouping::Custom;
    d.sensorGroups = {0b101, 0b010};
    return d;
}

// Three action branches (3 x 2 x 2): 12 combined actions, 7 actor columns.
inline AgentDescriptor branchedDescriptor() {
    AgentDescriptor d = mixedDescriptor();
    d.setActionBranches({3, 2, 2});
    return d;
}

// A deterministic stream of observations and rewards, the same for every agent that replays it.
class Feed {
public:
    explicit Feed(std::uint64_t seed) : state_(seed * 2654435761u + 1) {}
    std::uint64_t bits() {
        state_ = state_ * 6364136223846793005ULL + 1442695040888963407ULL;
        return state_ >> 33;
    }
    float uniform() { return static_cast<float>(bits() & 0xFFFFFF) / 8388608.0f - 1.0f; }  // [-1, 1)
    Observation next(const AgentDescriptor& d) {
        Observation o(d);
        for (std::size_t i = 0; i < o.discrete.size(); ++i) {
            o.discrete[i] = static_cast<std::int32_t>(bits() % d.discreteSensors[i]);
        }
        for (auto& c : o.continuous) c = uniform();
        return o;
    }

private:
    std::uint64_t state_;
};

// Runs `steps` updates (ending a trial every 25 steps), returns the actions chosen.
inline std::vector<std::uint32_t> drive(Agent& agent, Feed& feed, int steps) {
    std::vector<std::uint32_t> actions;
    for (int i = 0; i < steps; ++i) {
        const Observation o = feed.next(agent.descriptor());
        actions.push_back(agent.update(feed.uniform(), o, 0.1f));
        if (i % 25 == 24) agent.endEpisode(feed.uniform());
    }
    return actions;
}

inline Agent trainedAgent(const AgentDescriptor& d, int steps = 400, std::uint64_t feedSeed = 3) {
    Agent agent(d);
    Feed feed(feedSeed);
    drive(agent, feed, steps);
    return agent;
}

// A brain trained by two bodies taking turns on one feed (`steps` updates in all).
inline Brain trainedBrain(const AgentDescriptor& d, int steps = 400, std::uint64_t feedSeed = 3) {
    Brain brain(d);
    Agent bodies[2] = {brain.makeBody(), brain.makeBody()};
    Feed feed(feedSeed);
    for (int i = 0; i < steps; ++i) drive(bodies[i % 2], feed, 1);
    return brain;
}

inline bool sameBits(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0);
}

inline void expectSameDescriptor(const AgentDescriptor& a, const AgentDescriptor& b) {
    EXPECT_EQ(a.discreteSensors, b.discreteSensors);
    ASSERT_EQ(a.continuousSensors.size(), b.continuousSensors.size());
    for (std::size_t i = 0; i < a.continuousSensors.size(); ++i) {
        EXPECT_EQ(a.continuousSensors[i].circular, b.continuousSensors[i].circular);
    }
    EXPECT_EQ(a.resolution, b.resolution);
    EXPECT_EQ(a.numActions, b.numActions);
    EXPECT_EQ(a.allocation, b.allocation);
    EXPECT_EQ(a.tauValue, b.tauValue);
    EXPECT_EQ(a.tauDiscount, b.tauDiscount);
    EXPECT_EQ(a.tauEligibility, b.tauEligibility);
    EXPECT_EQ(a.policyMultiplier, b.policyMultiplier);
    EXPECT_EQ(a.traceThreshold, b.traceThreshold);
    EXPECT_EQ(a.seed, b.seed);
    EXPECT_EQ(a.planning, b.planning);
    EXPECT_EQ(a.tauModel, b.tauModel);
    EXPECT_EQ(a.maxPlanningSteps, b.maxPlanningSteps);
    EXPECT_EQ(a.planningUncertaintyThreshold, b.planningUncertaintyThreshold);
    EXPECT_EQ(a.curiosity, b.curiosity);
    EXPECT_EQ(a.curiosityFactor, b.curiosityFactor);
    EXPECT_EQ(a.planningAccumulatesUncertainty, b.planningAccumulatesUncertainty);
    EXPECT_EQ(a.learnFromRealSteps, b.learnFromRealSteps);
    EXPECT_EQ(a.discretePrediction, b.discretePrediction);
    EXPECT_EQ(a.maxRbfs, b.maxRbfs);
    EXPECT_EQ(a.adaptation, b.adaptation);
    EXPECT_EQ(a.grouping, b.grouping);
    EXPECT_EQ(a.sensorGroups, b.sensorGroups);
}

// Every field, floats compared bit for bit.
inline void expectSameSnapshot(const AgentSnapshot& a, const AgentSnapshot& b, bool withTraces = true) {
    expectSameDescriptor(a.descriptor, b.descriptor);
    EXPECT_EQ(a.learning, b.learning);
    EXPECT_EQ(a.featureKeys, b.featureKeys);
    EXPECT_TRUE(sameBits(a.centres, b.centres));
    EXPECT_EQ(a.stride, b.stride);
    EXPECT_TRUE(sameBits(a.weights, b.weights));
    EXPECT_EQ(a.rewardLow, b.rewardLow);
    EXPECT_EQ(a.rewardHigh, b.rewardHigh);
    EXPECT_EQ(a.finalRewardLow, b.finalRewardLow);
    EXPECT_EQ(a.finalRewardHigh, b.finalRewardHigh);
    EXPECT_EQ(a.modelPredictsChange, b.modelPredictsChange);
    EXPECT_EQ(std::memcmp(&a.horizonTrialSeconds, &b.horizonTrialSeconds, sizeof(float)), 0);
    EXPECT_EQ(a.horizonTrials, b.horizonTrials);
    EXPECT_EQ(std::memcmp(&a.tdMeanSquare, &b.tdMeanSquare, sizeof(float)), 0);
    EXPECT_TRUE(sameBits(a.groupLogRates, b.groupLogRates));
    EXPECT_TRUE(sameBits(a.groupNorms, b.groupNorms));
    EXPECT_TRUE(sameBits(a.groupHistory, b.groupHistory));
    EXPECT_EQ(a.rng, b.rng);
    EXPECT_EQ(a.steps, b.steps);
    EXPECT_EQ(std::memcmp(&a.modelError, &b.modelError, sizeof(float)), 0);
    EXPECT_EQ(std::memcmp(&a.lastDt, &b.lastDt, sizeof(float)), 0);
    if (!withTraces) return;
    EXPECT_EQ(a.traceStride, b.traceStride);
    EXPECT_EQ(a.traceFeatures, b.traceFeatures);
    EXPECT_TRUE(sameBits(a.traces, b.traces));
    EXPECT_EQ(std::memcmp(&a.trialSeconds, &b.trialSeconds, sizeof(float)), 0);
    EXPECT_EQ(std::memcmp(&a.stretchSeconds, &b.stretchSeconds, sizeof(float)), 0);
    EXPECT_EQ(std::memcmp(&a.stretchLongest, &b.stretchLongest, sizeof(float)), 0);
    EXPECT_EQ(std::memcmp(&a.stretchReward, &b.stretchReward, sizeof(float)), 0);
    EXPECT_EQ(a.stretchSeen, b.stretchSeen);
    EXPECT_TRUE(sameBits(a.continuousValues, b.continuousValues));
    EXPECT_TRUE(sameBits(a.continuousNoise, b.continuousNoise));
    EXPECT_EQ(a.continuousNoiseRunning, b.continuousNoiseRunning);
    EXPECT_EQ(a.hasPrevious, b.hasPrevious);
    if (a.hasPrevious && b.hasPrevious) {
        EXPECT_EQ(a.previousFeatures, b.previousFeatures);
        EXPECT_TRUE(sameBits(a.previousActivations, b.previousActivations));
        EXPECT_EQ(a.previousAction, b.previousAction);
        EXPECT_EQ(a.previousDiscrete, b.previousDiscrete);
        EXPECT_TRUE(sameBits(a.previousContinuous, b.previousContinuous));
    }
}

// Both agents see the same observations and rewards from here on and keep learning: a loaded
// agent must choose exactly the same actions and end with exactly the same weights as its original.
inline void expectSameFuture(Agent& original, Agent& loaded) {
    Feed a(99), b(99);
    EXPECT_EQ(drive(original, a, 300), drive(loaded, b, 300));
    expectSameSnapshot(original.snapshot(), loaded.snapshot());
}

}  // namespace verve::iotest
