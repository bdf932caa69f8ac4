// Continuous actions: the descriptor's checks, values within [-1, 1], greedy means, determinism,
// saves that keep the noise, shared brains, and an agent that learns which way to push.
#include "core/continuous_actions.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "validation_error.hpp"
#include "verve/agent.hpp"
#include "verve/batch.hpp"
#include "verve/brain.hpp"
#include "verve/error.hpp"

using namespace verve;
using verve::coretest::validationError;

namespace {

AgentDescriptor steering(std::uint32_t continuous, std::uint64_t seed = 1) {
    AgentDescriptor d;
    d.addContinuousSensor();
    d.numActions = 1;
    d.continuousActions = continuous;
    d.seed = seed;
    return d;
}

Observation at(const AgentDescriptor& d, float x) {
    Observation obs(d);
    obs.setContinuous(0, x);
    return obs;
}

// The 1-D reach task: x moves by 2 dt a, every step costs |x|; returns the greedy action at `probe`.
void trainReach(Agent& agent, int episodes, std::uint32_t seed) {
    const AgentDescriptor& d = agent.descriptor();
    std::uint32_t state = seed;
    auto uniform = [&] {
        state = state * 1664525u + 1013904223u;
        return static_cast<float>(state >> 8) / 16777216.0f * 2.0f - 1.0f;
    };
    for (int e = 0; e < episodes; ++e) {
        float x = uniform(), reward = 0.0f;
        for (int t = 0; t < 100; ++t) {
            agent.update(reward, at(d, x), 0.05f);
            x = std::clamp(x + 0.1f * agent.continuousAction()[0], -1.0f, 1.0f);
            reward = -std::fabs(x);
        }
        agent.truncateEpisode(reward);
    }
}

float greedyAt(Agent& agent, float x) {
    agent.setActionSelection(ActionSelection::Greedy);
    const bool learning = agent.learning();
    agent.setLearning(false);
    agent.update(0.0f, at(agent.descriptor(), x), 0.05f);
    const float value = agent.continuousAction()[0];
    agent.setLearning(learning);
    agent.setActionSelection(ActionSelection::Sample);
    return value;
}

}  // namespace

TEST(ContinuousActions, TheDescriptorNamesWhatIsWrong) {
    EXPECT_EQ(validationError(steering(2)), "");
    EXPECT_NE(validationError(steering(9)).find("num_continuous_actions is 9, at most 8"), std::string::npos);
    AgentDescriptor d = steering(1);
    d.planning = true;
    EXPECT_NE(validationError(d).find("planning needs discrete actions only"), std::string::npos);
    EXPECT_THROW(Agent{d}, Error);
}

TEST(ContinuousActions, ValuesStayWithinTheBoundsAndTheDiscreteActionIsUntouched) {
    AgentDescriptor d = steering(3);
    d.numActions = 4;
    Agent agent(d);
    EXPECT_EQ(agent.continuousAction(), std::vector<float>(3, 0.0f));  // before any update
    float reward = 0.0f;
    for (int t = 0; t < 500; ++t) {
        const std::uint32_t action = agent.update(reward, at(d, std::sin(0.1f * t)), 0.02f);
        ASSERT_LT(action, 4u);
        ASSERT_EQ(agent.continuousAction().size(), 3u);
        for (float v : agent.continuousAction()) ASSERT_TRUE(v >= -1.0f && v <= 1.0f) << v;
        ASSERT_EQ(agent.actionProbabilities().size(), 4u);  // the continuous columns are not actions
        reward = agent.continuousAction()[0] > 0.0f ? 0.5f : -0.5f;
    }
}

TEST(ContinuousActions, NoiseIsCorrelatedOverADecisionNotDrawnAfreshEachFrame) {
    // At 60 updates a second, consecutive values stay close (the noise's correlation time is 0.1 s);
    // at 2 a second they are nearly independent.
    auto meanJump = [](float dt) {
        const AgentDescriptor d = steering(1);
        Agent agent(d);
        agent.setLearning(false);
        float previous = 0.0f, sum = 0.0f;
        for (int t = 0; t < 2000; ++t) {
            agent.update(0.0f, at(d, 0.0f), dt);
            if (t > 0) sum += std::fabs(agent.continuousAction()[0] - previous);
            previous = agent.continuousAction()[0];
        }
        return sum / 1999.0f;
    };
    EXPECT_LT(meanJump(1.0f / 60.0f), 0.5f * meanJump(0.5f));
}

TEST(ContinuousActions, GreedyPlaysTheMeanAndTheSameSeedTheSameValues) {
    const AgentDescriptor d = steering(2, 7);
    Agent a(d), b(d);
    for (int t = 0; t < 200; ++t) {
        a.update(-0.1f, at(d, 0.01f * t - 1.0f), 0.05f);
        b.update(-0.1f, at(d, 0.01f * t - 1.0f), 0.05f);
        ASSERT_EQ(a.continuousAction(), b.continuousAction());
    }
    a.setActionSelection(ActionSelection::Greedy);
    a.setLearning(false);
    a.update(0.0f, at(d, 0.3f), 0.05f);
    const std::vector<float> first = a.continuousAction();
    a.update(0.0f, at(d, 0.3f), 0.05f);
    EXPECT_EQ(a.continuousAction(), first);
    // A fresh agent's mean is 0 everywhere.
    Agent fresh(d);
    fresh.setActionSelection(ActionSelection::Greedy);
    fresh.update(0.0f, at(d, 0.3f), 0.05f);
    EXPECT_EQ(fresh.continuousAction(), std::vector<float>(2, 0.0f));
}

TEST(ContinuousActions, ASnapshotKeepsTheNoiseSoTheFutureIsTheSame) {
    const AgentDescriptor d = steering(2, 3);
    Agent a(d);
    for (int t = 0; t < 300; ++t) a.update(std::sin(0.05f * t), at(d, std::cos(0.03f * t)), 0.02f);
    Agent b(a.snapshot());
    EXPECT_EQ(b.continuousAction(), a.continuousAction());
    for (int t = 0; t < 100; ++t) {
        a.update(0.2f, at(d, 0.5f - 0.01f * t), 0.02f);
        b.update(0.2f, at(d, 0.5f - 0.01f * t), 0.02f);
        ASSERT_EQ(a.continuousAction(), b.continuousAction()) << t;
    }
    // A corrupt noise or value is refused.
    AgentSnapshot bad = a.snapshot();
    bad.continuousNoise[0] = 100.0f;
    EXPECT_THROW(Agent{bad}, Error);
    bad = a.snapshot();
    bad.continuousValues[1] = 1.5f;
    EXPECT_THROW(Agent{bad}, Error);
    bad = a.snapshot();
    bad.continuousValues.pop_back();
    EXPECT_THROW(Agent{bad}, Error);
}

TEST(ContinuousActions, BodiesOfOneBrainActInParallelAsOnOneThread) {
    // The bodies' phases (docs/crowds.md) act against the brain as the call found it: the same on
    // any number of threads, each body's values its own.
    auto run = [](std::uint32_t workers) {
        const AgentDescriptor d = steering(2, 5);
        Brain brain(d);
        std::vector<Agent> bodies;
        for (int i = 0; i < 6; ++i) bodies.push_back(brain.makeBody());
        std::vector<Agent*> pointers;
        for (Agent& a : bodies) pointers.push_back(&a);
        BatchOptions options;
        options.workerCount = workers;
        Batch batch(options);
        std::vector<float> values;
        std::vector<float> rewards(6), sensors(6);
        std::vector<std::uint32_t> actions(6);
        for (int t = 0; t < 300; ++t) {
            for (int i = 0; i < 6; ++i) {
                sensors[i] = std::sin(0.1f * t + i);
                rewards[i] = t == 0 ? 0.0f : -std::fabs(sensors[i] + bodies[i].continuousAction()[0]);
            }
            BatchStep s;
            s.agents = pointers.data();
            s.count = 6;
            s.rewards = rewards.data();
            s.continuous = sensors.data();
            s.continuousTotal = 6;
            s.dt = 0.05f;
            s.actions = actions.data();
            batch.update(s);
            for (Agent& a : bodies) values.insert(values.end(), a.continuousAction().begin(), a.continuousAction().end());
        }
        return values;
    };
    const std::vector<float> one = run(1), two = run(2);
    EXPECT_EQ(one, two);
    EXPECT_TRUE(std::all_of(one.begin(), one.end(), [](float v) { return v >= -1.0f && v <= 1.0f; }));
}

TEST(ContinuousActions, AnAgentLearnsWhichWayToPush) {
    Agent agent(steering(1, 3));
    trainReach(agent, 400, 1);
    // Measured: +1.00 and -0.99 (a fresh agent's mean is 0 everywhere).
    EXPECT_GT(greedyAt(agent, -0.6f), 0.5f);
    EXPECT_LT(greedyAt(agent, 0.6f), -0.5f);
}
