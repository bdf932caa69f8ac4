// Truncation, greedy play, action probabilities, action masks and the actor weight bound.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

#include "discrete_obs.hpp"
#include "verve/agent.hpp"

using namespace verve;
using verve::coretest::discreteObs;

namespace {

AgentDescriptor discreteAgent(std::uint32_t actions) {
    AgentDescriptor d;
    d.addDiscreteSensor(2);
    d.numActions = actions;
    d.policyMultiplier = 1.0f;
    return d;
}

void expectRefused(const std::function<void()>& call) {
    try {
        call();
        ADD_FAILURE() << "accepted bad input";
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), ErrorCode::InvalidArgument);
        EXPECT_GT(std::string(e.what()).size(), 10u);
    }
}

// Teaches state 0 to prefer action `best` (reward 1 for it, -1 for the others), `trials` times.
void teach(Agent& agent, std::uint32_t best, int trials) {
    for (int t = 0; t < trials; ++t) {
        const std::uint32_t a = agent.update(0.0f, discreteObs(0), 0.1f);
        agent.endEpisode(a == best ? 1.0f : -1.0f);
    }
}

}  // namespace

TEST(Truncation, LearnsTheLastRewardAndBootstrapsFromTheLastState) {
    Agent agent(discreteAgent(2));
    agent.update(0.0f, discreteObs(0), 0.1f);
    agent.update(0.0f, discreteObs(1), 0.1f);
    agent.endEpisode(1.0f);  // V(s1) > 0 now
    agent.update(0.0f, discreteObs(1), 0.1f);
    const float v = agent.valueEstimate();
    ASSERT_GT(v, 0.0f);
    const float gamma = std::exp(-0.1f);
    agent.truncateEpisode(-0.5f);
    // Not terminal: delta = r + gamma V(s) - V(s), where endEpisode would give r - V(s).
    EXPECT_NEAR(agent.tdError(), -0.5f + gamma * v - v, 1e-6f);
    EXPECT_EQ(agent.stats().liveTraces, 0u);  // the short-term memory is cleared
    expectRefused([&] { agent.truncateEpisode(std::numeric_limits<float>::quiet_NaN()); });
}

TEST(Truncation, WithoutAPreviousStepOrLearningLearnsNothing) {
    Agent agent(discreteAgent(2));
    agent.truncateEpisode(1.0f);
    agent.update(0.0f, discreteObs(0), 0.1f);
    agent.setLearning(false);
    agent.update(0.0f, discreteObs(0), 0.1f);
    const AgentSnapshot before = agent.snapshot();
    agent.truncateEpisode(1.0f);
    EXPECT_EQ(before.weights, agent.snapshot().weights);
}

TEST(ActionProbabilities, AreUniformAtFirstAndFollowTheLearnedPreference) {
    Agent agent(discreteAgent(4));
    for (float p : agent.actionProbabilities()) EXPECT_FLOAT_EQ(p, 0.25f);
    teach(agent, 2, 300);
    agent.update(0.0f, discreteObs(0), 0.1f);
    const std::vector<float>& p = agent.actionProbabilities();
    ASSERT_EQ(p.size(), 4u);
    EXPECT_NEAR(std::accumulate(p.begin(), p.end(), 0.0f), 1.0f, 1e-5f);
    EXPECT_GT(p[2], 0.9f);
}

TEST(ActionSelection, GreedyPlaysTheMostProbableActionAndDrawsNoRandomNumber) {
    Agent agent(discreteAgent(3));
    EXPECT_EQ(agent.actionSelection(), ActionSelection::Sample);
    teach(agent, 1, 200);
    agent.setLearning(false);
    agent.setActionSelection(ActionSelection::Greedy);
    const auto rngBefore = agent.snapshot().rng;
    for (int i = 0; i < 100; ++i) {
        const std::uint32_t a = agent.update(0.0f, discreteObs(0), 0.1f);
        const std::vector<float>& p = agent.actionProbabilities();
        EXPECT_EQ(a, static_cast<std::uint32_t>(std::max_element(p.begin(), p.end()) - p.begin()));
        EXPECT_EQ(a, 1u);
    }
    EXPECT_EQ(agent.snapshot().rng, rngBefore);
    // An untrained state: all tie, the lowest index wins.
    EXPECT_EQ(agent.update(0.0f, discreteObs(1), 0.1f), 0u);
    expectRefused([&] { agent.setActionSelection(static_cast<ActionSelection>(7)); });
    EXPECT_EQ(agent.actionSelection(), ActionSelection::Greedy);
}

namespace {

// A three-action agent that has seen states 0 .. states - 1 (one RBF each, all weights 0) and has
// no short-term memory: a snapshot whose rows a test then sets.
AgentSnapshot visited(std::int32_t states) {
    Agent seed(discreteAgent(3));
    for (std::int32_t i = 0; i < states; ++i) seed.update(0.0f, discreteObs(i), 0.1f);
    seed.resetShortTermMemory();
    return seed.snapshot();
}

// State 0 valued below the floor that -1 per step for ever earns (-1 / (1 - gamma)), state 1 at 0,
// and both with an actor saturated on action 0 (sigma(30) against sigma(-30)).
AgentSnapshot saturatedAtTheFloor(float rewardLow) {
    AgentSnapshot s = visited(2);
    s.rewardLow = rewardLow;
    for (std::size_t f = 0; f < 2; ++f) {
        float* row = s.weights.data() + f * s.stride;
        row[0] = f == 0 ? -20.0f : 0.0f;
        row[1] = 30.0f;
        row[2] = row[3] = -30.0f;
    }
    return s;
}

// Counts each action chosen over `n` updates in `state`, rewarded `reward` each step.
std::vector<int> choices(Agent& agent, std::int32_t state, float reward, int n, ActionMask mask = {}) {
    std::vector<int> count(3, 0);
    for (int i = 0; i < n; ++i) ++count[agent.update(reward, discreteObs(state).view(), 0.1f, mask)];
    return count;
}

// An agent whose state 0 has value 0 and actor preferences `x`, learning off.
Agent withPreferences(std::array<float, 3> x) {
    AgentSnapshot s = visited(1);
    std::copy(x.begin(), x.end(), s.weights.begin() + 1);
    Agent agent(s);
    agent.setLearning(false);
    return agent;
}

}  // namespace

// Sigmoids tie in float at 1 (above about 17) and at 0 (below about -88) where preferences differ.
TEST(ActionSelection, GreedyFollowsThePreferenceWhereActivationsSaturate) {
    for (const auto& x : {std::array<float, 3>{30.0f, 45.0f, 40.0f}, std::array<float, 3>{-120.0f, -95.0f, -100.0f}}) {
        Agent agent = withPreferences(x);
        agent.setActionSelection(ActionSelection::Greedy);
        EXPECT_EQ(agent.update(0.0f, discreteObs(0), 0.1f), 1u) << x[1];
    }
}

// Preferences all below about -88 underflow every sigmoid to 0; the roulette then keeps their
// proportions (e^(x_a - max x), the limit of sigmoid ratios) rather than turning uniform.
TEST(ActionSelection, UnderflowedActivationsStillFollowThePreferences) {
    Agent agent = withPreferences({-101.0f, -100.0f, -130.0f});
    const std::vector<int> count = choices(agent, 0, 0.0f, 2000);
    const std::vector<float>& p = agent.actionProbabilities();
    const float e = std::exp(-1.0f);
    EXPECT_NEAR(p[0], e / (1.0f + e), 1e-5f);
    EXPECT_NEAR(p[1], 1.0f / (1.0f + e), 1e-5f);
    EXPECT_LT(p[2], 1e-12f);
    EXPECT_EQ(count[2], 0);
    EXPECT_NEAR(count[1] / 2000.0, 1.0 / (1.0 + e), 0.04);  // 0.731; sd of the fraction ~0.01
}

// Every step of a loop valued at the floor has a TD error of 0, so nothing there is learned: a
// learning agent that samples explores such a state uniformly instead of keeping a saturated habit
// (docs/algorithm.md, "A changing world: hopeless states explore").
TEST(HopelessStates, ExploreUniformlyWhileLearningAndSampling) {
    const AgentSnapshot s = saturatedAtTheFloor(-1.0f);
    Agent agent(s);
    const std::vector<int> count = choices(agent, 0, -1.0f, 600);
    for (int c : count) EXPECT_GT(c, 150) << "expected ~200 of 600 each";
    for (float p : agent.actionProbabilities()) EXPECT_FLOAT_EQ(p, 1.0f / 3.0f);
    EXPECT_NEAR(agent.snapshot().weights[0], -20.0f, 1e-3f);  // at the floor nothing is learned

    Agent above(s);  // state 1 is not at the floor: the habit plays
    EXPECT_EQ(choices(above, 1, -1.0f, 100)[0], 100);
    EXPECT_GT(above.actionProbabilities()[0], 0.999f);

    Agent greedy(s);
    greedy.setActionSelection(ActionSelection::Greedy);
    EXPECT_EQ(choices(greedy, 0, -1.0f, 100)[0], 100);

    Agent frozen(s);
    frozen.setLearning(false);
    EXPECT_EQ(choices(frozen, 0, -1.0f, 100)[0], 100);
    EXPECT_GT(frozen.actionProbabilities()[0], 0.999f);

    // With an action mask, uniformly among the allowed actions.
    Agent masked(s);
    const std::uint8_t allowed[3] = {0, 1, 1};
    const std::vector<int> maskedCount = choices(masked, 0, -1.0f, 400, ActionMask{allowed, 3});
    EXPECT_EQ(maskedCount[0], 0);
    EXPECT_GT(maskedCount[1], 150);
    EXPECT_GT(maskedCount[2], 150);
    EXPECT_FLOAT_EQ(masked.actionProbabilities()[1], 0.5f);
}

// Rewards that were never negative set no floor below 0: a state valued at 0 or below plays its policy.
TEST(HopelessStates, NoFloorWithoutNegativeRewards) {
    Agent agent(saturatedAtTheFloor(0.0f));
    EXPECT_EQ(choices(agent, 0, 0.0f, 100)[0], 100);
}

TEST(ActionMask, MaskedActionsAreNeverChosenAndGetNoCredit) {
    Agent agent(discreteAgent(4));
    const std::uint8_t allowed[4] = {0, 1, 0, 1};
    for (int t = 0; t < 200; ++t) {
        const std::uint32_t a = agent.update(0.0f, discreteObs(0).view(), 0.1f, ActionMask{allowed, 4});
        EXPECT_TRUE(a == 1 || a == 3) << a;
        EXPECT_EQ(agent.actionProbabilities()[0], 0.0f);
        EXPECT_EQ(agent.actionProbabilities()[2], 0.0f);
        agent.endEpisode(1.0f);
    }
    const AgentSnapshot s = agent.snapshot();
    EXPECT_EQ(s.weights[1 + 0], 0.0f);  // state 0's actor weights of the masked actions
    EXPECT_EQ(s.weights[1 + 2], 0.0f);
    EXPECT_GT(s.weights[1 + 1] + s.weights[1 + 3], 0.0f);
}

TEST(ActionMask, BadMasksAreRefusedAndChangeNothing) {
    Agent agent(discreteAgent(3));
    teach(agent, 0, 20);
    agent.update(0.0f, discreteObs(0), 0.1f);
    const AgentSnapshot before = agent.snapshot();
    const std::uint8_t none[3] = {0, 0, 0};
    const std::uint8_t two[3] = {1, 2, 0};
    const std::uint8_t ok[3] = {1, 1, 1};
    expectRefused([&] { agent.update(0.0f, discreteObs(0).view(), 0.1f, ActionMask{none, 3}); });
    expectRefused([&] { agent.update(0.0f, discreteObs(0).view(), 0.1f, ActionMask{two, 3}); });
    expectRefused([&] { agent.update(0.0f, discreteObs(0).view(), 0.1f, ActionMask{ok, 2}); });
    expectRefused([&] { agent.update(0.0f, discreteObs(0).view(), 0.1f, ActionMask{nullptr, 3}); });
    const AgentSnapshot after = agent.snapshot();
    EXPECT_EQ(before.weights, after.weights);
    EXPECT_EQ(before.traces, after.traces);
    EXPECT_EQ(before.rng, after.rng);
    EXPECT_EQ(before.steps, after.steps);
}

TEST(PolicyWeightBound, KeepsEveryActorWeightWithinTheBound) {
    AgentDescriptor d = discreteAgent(3);
    d.policyMultiplier = 50.0f;
    d.policyWeightBound = 4.0f;
    Agent agent(d);
    teach(agent, 1, 300);
    const AgentSnapshot s = agent.snapshot();
    float largest = 0.0f;
    for (std::size_t f = 0; f < s.weights.size() / s.stride; ++f) {
        for (std::uint32_t a = 0; a < 3; ++a) largest = std::max(largest, std::abs(s.weights[f * s.stride + 1 + a]));
    }
    EXPECT_FLOAT_EQ(largest, 4.0f);  // reached, never passed

    d.policyWeightBound = 0.0f;  // unbounded: the same lessons go further
    Agent free(d);
    teach(free, 1, 300);
    EXPECT_GT(free.snapshot().weights[1 + 1], 4.0f);

    for (float bad : {-1.0f, std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
        d.policyWeightBound = bad;
        expectRefused([&] { Agent refused(d); });
    }
}

// Adaptation::HabitBound (core/habit_bound.hpp): with no policy_weight_bound, no actor weight rises
// above +10, while a failing action falls as far as its failures take it.
TEST(HabitBound, CapsHabitsAtTenAndLeavesFailuresUnbounded) {
    const auto extremes = [](const AgentSnapshot& s, std::uint32_t actions) {
        float high = -std::numeric_limits<float>::infinity(), low = std::numeric_limits<float>::infinity();
        for (std::size_t f = 0; f < s.weights.size() / s.stride; ++f) {
            for (std::uint32_t a = 0; a < actions; ++a) {
                high = std::max(high, s.weights[f * s.stride + 1 + a]);
                low = std::min(low, s.weights[f * s.stride + 1 + a]);
            }
        }
        return std::make_pair(low, high);
    };
    AgentDescriptor d = discreteAgent(3);
    d.policyMultiplier = 50.0f;
    ASSERT_NE(d.adaptation & Adaptation::HabitBound, 0u);  // the default
    Agent capped(d);
    teach(capped, 1, 300);
    const auto [low, high] = extremes(capped.snapshot(), 3);
    EXPECT_FLOAT_EQ(high, 10.0f);  // reached, never passed
    EXPECT_LT(low, -10.0f);

    d.adaptation &= ~Adaptation::HabitBound;
    Agent free(d);
    teach(free, 1, 300);
    EXPECT_GT(extremes(free.snapshot(), 3).second, 10.0f);

    d.adaptation = Adaptation::All;
    d.policyWeightBound = 4.0f;  // the user's bound replaces the ceiling, both ways
    Agent bounded(d);
    teach(bounded, 1, 300);
    const auto [bLow, bHigh] = extremes(bounded.snapshot(), 3);
    EXPECT_FLOAT_EQ(bHigh, 4.0f);
    EXPECT_FLOAT_EQ(bLow, -4.0f);
}
