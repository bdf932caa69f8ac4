#include "verve/agent.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "discrete_obs.hpp"

using namespace verve;
using verve::coretest::discreteObs;

namespace {

AgentDescriptor twoStateAgent() {
    AgentDescriptor d;
    d.addDiscreteSensor(2);
    d.numActions = 2;
    d.tauValue = 0.1f;
    d.tauDiscount = 1.0f;
    d.tauEligibility = 0.1f;
    d.policyMultiplier = 1.0f;
    return d;
}

// Drives a 1D continuous agent with a fixed pseudo-random input sequence.
std::vector<std::uint32_t> actionsOf(Agent& agent, int steps, int offset = 0) {
    std::vector<std::uint32_t> actions;
    Observation o;
    o.continuous = {0.0f, 0.0f};
    for (int i = offset; i < offset + steps; ++i) {
        o.continuous[0] = std::sin(0.37f * static_cast<float>(i));
        o.continuous[1] = std::cos(0.11f * static_cast<float>(i));
        actions.push_back(agent.update((i % 7 == 0) ? 1.0f : -0.1f, o, 0.1f));
    }
    return actions;
}

AgentDescriptor continuousAgent(std::uint64_t seed = 7) {
    AgentDescriptor d;
    d.addContinuousSensor(true).addContinuousSensor();
    d.numActions = 3;
    d.seed = seed;
    return d;
}

}  // namespace

TEST(TdLearning, OneUpdateComputedByHand) {
    Agent agent(twoStateAgent());
    const std::uint32_t a1 = agent.update(0.0f, discreteObs(0), 0.1f);
    agent.update(1.0f, discreteObs(1), 0.1f);
    const float eta = 1.0f - std::exp(-1.0f);  // (1 - e^(-dt/tau)) / sum, sum = 1 (discrete only)
    const float gamma = std::exp(-0.1f);
    const float traceDecay = std::exp(-1.1f);  // gamma * lambda
    // delta = r + gamma V(s') - V(s) = 1: the critic weight of s moves by eta, and so does the
    // chosen action's policy weight; the other action's is untouched.
    AgentSnapshot snap = agent.snapshot();
    ASSERT_EQ(snap.stride, 3u);
    EXPECT_NEAR(snap.weights[0], eta, 1e-6f);
    EXPECT_NEAR(snap.weights[1 + a1], eta, 1e-6f);
    EXPECT_EQ(snap.weights[1 + (1 - a1)], 0.0f);
    EXPECT_NEAR(agent.tdError(), 1.0f, 1e-6f);

    agent.update(0.0f, discreteObs(0), 0.1f);  // delta = 0 + gamma * V(s0) - V(s1) = gamma * eta
    const float delta = gamma * eta;
    EXPECT_NEAR(agent.tdError(), delta, 1e-6f);
    snap = agent.snapshot();
    EXPECT_NEAR(snap.weights[0], eta + eta * delta * traceDecay, 1e-6f);  // s0's trace decayed once
    EXPECT_NEAR(snap.weights[3], eta * delta, 1e-6f);                     // s1's trace is fresh
}

// Adaptation::DecisionRate (core/decision_rate.hpp): an update 0.02 s after the previous one learns
// with the rates and trace decay of a 0.1 s decision; discounting stays in real seconds.
TEST(TdLearning, UpdatesCloserThanATenthOfASecondLearnAsATenthOfASecond) {
    for (const bool decisions : {true, false}) {
        AgentDescriptor d = twoStateAgent();
        d.adaptation = decisions ? Adaptation::All : Adaptation::All & ~Adaptation::DecisionRate;
        Agent agent(d);
        const std::uint32_t a1 = agent.update(0.0f, discreteObs(0), 0.02f);
        agent.update(1.0f, discreteObs(1), 0.02f);
        const float seconds = decisions ? 0.1f : 0.02f;
        const float eta = 1.0f - std::exp(-seconds / 0.1f);
        AgentSnapshot snap = agent.snapshot();
        EXPECT_NEAR(snap.weights[0], eta, 1e-6f) << decisions;
        EXPECT_NEAR(snap.weights[1 + a1], eta, 1e-6f) << decisions;

        agent.update(0.0f, discreteObs(0), 0.02f);
        const float delta = std::exp(-0.02f) * eta;  // gamma over the real 0.02 s
        EXPECT_NEAR(agent.tdError(), delta, 1e-6f) << decisions;
        const float traceDecay = std::exp(-0.02f) * std::exp(-seconds / 0.1f);
        snap = agent.snapshot();
        EXPECT_NEAR(snap.weights[0], eta + eta * delta * traceDecay, 1e-6f) << decisions;
    }
}

TEST(TdLearning, EndEpisodeIsTerminalAndForgetsTheStep) {
    Agent agent(twoStateAgent());
    agent.update(0.0f, discreteObs(0), 0.1f);
    agent.update(0.0f, discreteObs(1), 0.1f);
    agent.endEpisode(-1.0f);  // delta = r - V(s1) = -1: no bootstrap
    EXPECT_NEAR(agent.tdError(), -1.0f, 1e-6f);
    const AgentSnapshot snap = agent.snapshot();
    EXPECT_FALSE(snap.hasPrevious);
    EXPECT_TRUE(snap.traceFeatures.empty());
    const float eta = 1.0f - std::exp(-1.0f);
    EXPECT_NEAR(snap.weights[3], -eta, 1e-6f);
    EXPECT_NEAR(snap.weights[0], -eta * std::exp(-1.1f), 1e-6f);
}

TEST(TdLearning, RewardIsClampedToUnitRange) {
    Agent a(twoStateAgent()), b(twoStateAgent());
    for (Agent* agent : {&a, &b}) agent->update(0.0f, discreteObs(0), 0.1f);
    a.update(100.0f, discreteObs(1), 0.1f);
    b.update(1.0f, discreteObs(1), 0.1f);
    EXPECT_EQ(a.tdError(), b.tdError());
}

TEST(TdLearning, TracesDecayAndAreDroppedBelowTheThreshold) {
    AgentDescriptor d = twoStateAgent();
    d.addDiscreteSensor(100);
    d.discreteSensors = {100};
    Agent agent(d);
    for (int i = 0; i < 60; ++i) agent.update(0.0f, discreteObs(i), 0.1f);
    // gamma * lambda = e^-1.1 per step: a trace of 1 falls below 0.01 after 5 steps.
    EXPECT_EQ(agent.stats().liveTraces, 5u);
}

TEST(Agent, SameSeedSameInputsSameActions) {
    Agent a(continuousAgent()), b(continuousAgent());
    EXPECT_EQ(actionsOf(a, 500), actionsOf(b, 500));
    Agent c(continuousAgent(8));
    Agent d(continuousAgent(7));
    EXPECT_NE(actionsOf(c, 500), actionsOf(d, 500));
}

TEST(Agent, SnapshotRestoresAnAgentThatActsIdentically) {
    Agent a(continuousAgent());
    actionsOf(a, 300);
    Agent b(a.snapshot());
    EXPECT_EQ(actionsOf(a, 300, 300), actionsOf(b, 300, 300));
    EXPECT_EQ(a.rbfCount(), b.rbfCount());
}

TEST(Agent, RejectsBadInputAndChangesNothing) {
    Agent agent(continuousAgent());
    actionsOf(agent, 50);
    const AgentSnapshot before = agent.snapshot();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    Observation good;
    good.continuous = {0.1f, 0.2f};
    Observation wrongSize;
    wrongSize.continuous = {0.1f};
    Observation hasNan = good;
    hasNan.continuous[1] = nan;
    Observation hasInf = good;
    hasInf.continuous[0] = -inf;
    Observation extraDiscrete = good;
    extraDiscrete.discrete = {0};
    auto expectRefused = [&](auto call) {
        try {
            call();
            ADD_FAILURE() << "accepted bad input";
        } catch (const Error& e) {
            EXPECT_EQ(e.code(), ErrorCode::InvalidArgument);
            EXPECT_GT(std::string(e.what()).size(), 10u);
        }
    };
    expectRefused([&] { agent.update(0.0f, wrongSize, 0.1f); });
    expectRefused([&] { agent.update(0.0f, hasNan, 0.1f); });
    expectRefused([&] { agent.update(0.0f, hasInf, 0.1f); });
    expectRefused([&] { agent.update(0.0f, extraDiscrete, 0.1f); });
    expectRefused([&] { agent.update(nan, good, 0.1f); });
    expectRefused([&] { agent.update(0.0f, good, 0.0f); });
    expectRefused([&] { agent.update(0.0f, good, -0.1f); });
    expectRefused([&] { agent.update(0.0f, good, nan); });
    expectRefused([&] { agent.endEpisode(inf); });
    const AgentSnapshot after = agent.snapshot();
    EXPECT_EQ(before.weights, after.weights);
    EXPECT_EQ(before.traces, after.traces);
    EXPECT_EQ(before.rng, after.rng);
    EXPECT_EQ(before.steps, after.steps);
    EXPECT_EQ(before.featureKeys.size(), after.featureKeys.size());
}

TEST(Agent, RejectsOutOfRangeDiscreteValues) {
    Agent agent(twoStateAgent());
    EXPECT_THROW(agent.update(0.0f, discreteObs(2), 0.1f), Error);
    EXPECT_THROW(agent.update(0.0f, discreteObs(-1), 0.1f), Error);
    EXPECT_EQ(agent.rbfCount(), 0u);
}

TEST(Agent, ClampsAndWrapsContinuousValues) {
    Agent agent(continuousAgent());
    Observation o;
    o.continuous = {2.5f, 7.0f};  // circular 2.5 wraps to 0.5; 7 clamps to 1
    agent.update(0.0f, o, 0.1f);
    const AgentSnapshot snap = agent.snapshot();
    ASSERT_EQ(snap.centres.size(), 4u);  // one RBF in the lattice, one in its fine lattice, both there
    for (std::size_t f = 0; f < 2; ++f) {
        EXPECT_FLOAT_EQ(snap.centres[2 * f], 0.5f);
        EXPECT_FLOAT_EQ(snap.centres[2 * f + 1], 1.0f);
    }
}

TEST(Agent, LearningOffActsButLearnsAndAllocatesNothing) {
    Agent agent(continuousAgent());
    actionsOf(agent, 100);
    agent.setLearning(false);
    const AgentSnapshot before = agent.snapshot();
    actionsOf(agent, 100, 5000);
    const AgentSnapshot after = agent.snapshot();
    EXPECT_EQ(before.weights, after.weights);
    EXPECT_EQ(before.featureKeys.size(), after.featureKeys.size());
    EXPECT_FALSE(agent.learning());
}

// Learning off from the start: no RBF and no weight row exists, so every action's sum is over an
// empty table. (fuzz_calls found the AVX2 kernel's second 8-column pass offsetting the empty
// table's null pointer; only clang's UBSan sees that, so the input is a seed in corpus/calls/.)
TEST(Agent, ActsWithNoRbfsAtAll) {
    AgentDescriptor d = continuousAgent();
    d.numActions = 12;  // more columns than one 8-wide pass
    Agent agent(d);
    agent.setLearning(false);
    std::vector<bool> chosen(d.numActions, false);
    for (const std::uint32_t a : actionsOf(agent, 400)) chosen.at(a) = true;
    EXPECT_EQ(agent.snapshot().featureKeys.size(), 0u);
    EXPECT_EQ(std::count(chosen.begin(), chosen.end(), true), 12);  // all equal values: every action is tried
}

TEST(Agent, InvalidDescriptorsAreRefused) {
    AgentDescriptor d;
    d.numActions = 0;
    EXPECT_THROW(Agent{d}, Error);
    d.numActions = 2;
    d.addDiscreteSensor(0);
    EXPECT_THROW(Agent{d}, Error);
    AgentDescriptor e;
    e.tauValue = -1.0f;
    EXPECT_THROW(Agent{e}, Error);
    AgentDescriptor f;
    f.addContinuousSensor();
    f.resolution = 0;
    EXPECT_THROW(Agent{f}, Error);
}

TEST(Agent, CorruptSnapshotsAreRefused) {
    Agent a(continuousAgent());
    actionsOf(a, 50);
    AgentSnapshot snap = a.snapshot();
    snap.weights.pop_back();
    EXPECT_THROW(Agent{snap}, Error);
    snap = a.snapshot();
    snap.weights[3] = std::numeric_limits<float>::quiet_NaN();
    EXPECT_THROW(Agent{snap}, Error);
    snap = a.snapshot();
    snap.centres[0] = 3.0f;
    EXPECT_THROW(Agent{snap}, Error);
    snap = a.snapshot();
    snap.previousAction = 99;
    EXPECT_THROW(Agent{snap}, Error);
    snap = a.snapshot();
    snap.traceFeatures.push_back(100000);
    snap.traces.resize(snap.traces.size() + 4);
    EXPECT_THROW(Agent{snap}, Error);
}

TEST(Agent, SamplesTheValueFunctionWithoutChangingIt) {
    AgentDescriptor d = twoStateAgent();
    Agent agent(d);
    agent.update(0.0f, discreteObs(0), 0.1f);
    agent.update(1.0f, discreteObs(1), 0.1f);
    const AgentSnapshot before = agent.snapshot();
    float values[2] = {-5, -5};
    agent.sampleValueFunction({ValueAxis{SensorKind::Discrete, 0, 2}}, Observation(d), values, 2);
    EXPECT_NEAR(values[0], 1.0f - std::exp(-1.0f), 1e-6f);
    EXPECT_EQ(values[1], 0.0f);
    EXPECT_EQ(agent.snapshot().weights, before.weights);
    EXPECT_THROW(agent.sampleValueFunction({ValueAxis{SensorKind::Discrete, 0, 3}}, Observation(d), values, 2), Error);
    EXPECT_THROW(agent.sampleValueFunction({ValueAxis{SensorKind::Discrete, 0, 2}}, Observation(d), values, 1), Error);
}
