// Planning through the public Agent: statistics, the step cap, snapshots, bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/horizon.hpp"
#include "core/predictive_model.hpp"
#include "core/weight_table.hpp"
#include "tasks/corridor.hpp"
#include "tasks/registry.hpp"
#include "verve/agent.hpp"

using namespace verve;
using namespace verve::tasks;

namespace {

// The longest plan over `trials` trials of `env`, each begun with seed `sameStart ? 0 : trial`.
std::uint32_t longestPlan(Agent& agent, Environment& env, std::uint64_t trials, bool sameStart) {
    Observation obs(agent.descriptor());
    std::uint32_t longest = 0;
    for (std::uint64_t t = 0; t < trials; ++t) {
        env.beginTrial(sameStart ? 0 : t);
        float reward = 0.0f;
        for (std::uint32_t i = 0; i < env.maxStepsPerTrial(); ++i) {
            env.observe(obs);
            const std::uint32_t action = agent.update(reward, obs, 0.1f);
            longest = std::max(longest, agent.stats().planningSteps);
            const StepResult step = env.act(action);
            if (step.terminal) {
                agent.endEpisode(step.reward);
                break;
            }
            reward = step.reward;
        }
    }
    return longest;
}

// A planning agent of one continuous sensor and `actions` actions after one update at 0: one RBF
// (one lattice, no fine one beside it), nothing learned yet, no previous step. Tests write its model
// through the snapshot.
AgentSnapshot oneRbfPlanner(std::uint32_t actions) {
    AgentDescriptor d;
    d.adaptation &= ~verve::Adaptation::FineLattice;
    d.addContinuousSensor();
    d.numActions = actions;
    d.planning = true;
    Agent agent(d);
    agent.update(0.0f, Observation(d), 0.1f);
    agent.resetShortTermMemory();
    AgentSnapshot s = agent.snapshot();
    EXPECT_EQ(s.featureKeys.size(), 1u);
    return s;
}

// Makes that one RBF's model predict, for `action`, the end of the trial with `reward`, as sure as
// `certainty` (the model block of one continuous sensor: change, reward, terminal, certainty, ...).
void predictEnd(AgentSnapshot& s, std::uint32_t action, float reward, float certainty) {
    const auto blockSize = static_cast<std::uint32_t>(core::PredictiveModel::outputsPerAction(s.descriptor));
    float* block = s.weights.data() + core::WeightLayout{s.descriptor.numActions, 0}.modelOffset() + action * blockSize;
    block[1] = reward;
    block[2] = 1.0f;
    block[3] = certainty;
}

AgentDescriptor mazeAgent(std::uint32_t cap) {
    AgentDescriptor d = findTask("maze2-planning")->make(1)->agentDescriptor();
    d.maxPlanningSteps = cap;
    return d;
}

}  // namespace

TEST(PlanningAgent, FillsStatisticsAndRespectsTheCap) {
    auto env = findTask("maze2-planning")->make(1);
    Agent agent(mazeAgent(7));
    const std::uint32_t most = longestPlan(agent, *env, 20, true);
    EXPECT_EQ(most, 7u);  // plans reach the cap once the maze is known, and never exceed it
    EXPECT_GE(agent.stats().modelError, 0.0f);
    EXPECT_FLOAT_EQ(agent.stats().curiosityReward, 0.0f);  // no curiosity configured
}

TEST(PlanningAgent, NonPlanningAgentsCarryNoModelColumns) {
    AgentDescriptor d = mazeAgent(10);
    d.planning = false;
    Agent plain(d);
    Agent planner(mazeAgent(10));
    EXPECT_EQ(plain.snapshot().stride, 1u + 5u);
    EXPECT_GT(planner.snapshot().stride, plain.snapshot().stride);
}

TEST(PlanningAgent, SnapshotRestoresTheModelAndTheSameFuture) {
    auto env = findTask("curiosity-grid-curious")->make(1);
    AgentDescriptor d = env->agentDescriptor();
    Agent agent(d);
    for (std::uint64_t t = 0; t < 5; ++t) runTrial(agent, *env, t);
    Agent copy(agent.snapshot());
    auto envCopy = findTask("curiosity-grid-curious")->make(1);
    for (std::uint64_t t = 5; t < 8; ++t) {
        const TrialResult a = runTrial(agent, *env, t);
        const TrialResult b = runTrial(copy, *envCopy, t);
        EXPECT_EQ(a.rewardSum, b.rewardSum);
    }
    EXPECT_EQ(agent.snapshot().weights, copy.snapshot().weights);
}

TEST(PlanningAgent, BadInputLeavesThePlannerUntouched) {
    Agent agent(mazeAgent(10));
    Observation obs(agent.descriptor());
    agent.update(0.0f, obs, 0.1f);
    const auto before = agent.snapshot().weights;
    obs.discrete[0] = 42;
    EXPECT_THROW(agent.update(-1.0f, obs, 0.1f), Error);
    EXPECT_EQ(agent.snapshot().weights, before);
    AgentDescriptor bad = mazeAgent(10);
    bad.discretePrediction = static_cast<DiscretePrediction>(9);
    EXPECT_THROW(Agent{bad}, Error);
}

// With continuous sensors and no curiosity a plan teaches only if it reaches the end of the trial:
// in the corridor's first trial the goal is far beyond any plan, so no plan teaches, and the
// agent acts exactly as without planning; the same agent with curiosity plans from the start.
TEST(PlanningAgent, ContinuousPlansTeachOnlyWhenTheyReachTheEnd) {
    auto env = findTask("corridor-planning")->make(1);
    AgentDescriptor d = env->agentDescriptor();
    AgentDescriptor plain = d;
    plain.planning = false;
    AgentDescriptor curious = d;
    curious.curiosity = CuriosityMode::Novelty;
    Agent planner(d), rl(plain), explorer(curious);
    Observation obs(d);
    std::uint32_t planned = 0, curiousPlanned = 0;
    for (int i = 0; i < 30; ++i) {
        env->observe(obs);
        const std::uint32_t a = planner.update(-1.0f, obs, 0.1f);
        EXPECT_EQ(a, rl.update(-1.0f, obs, 0.1f)) << "step " << i;
        explorer.update(-1.0f, obs, 0.1f);
        planned += planner.stats().planningSteps;
        curiousPlanned += explorer.stats().planningSteps;
        env->act(a);
    }
    EXPECT_EQ(planned, 0u);
    EXPECT_GT(curiousPlanned, 0u);
}

// Such plans trust only an end the model is sure of (planner.cpp): beside a goal the model's RBFs
// blur the terminal step into the ordinary ones, its end comes a step early with a reward between
// the two, and its error estimate there is high. One RBF, a model that predicts the end on every
// action's first step, certain to 0.95 (uncertainty 0.05) or to 0.7 (0.3: within the plan's
// threshold of 0.5, beyond the trusted end's 0.2).
TEST(PlanningAgent, ContinuousPlansTrustOnlyEndsTheModelIsSureOf) {
    const AgentSnapshot seed = oneRbfPlanner(2);
    const Observation obs(seed.descriptor);
    for (const float certainty : {0.95f, 0.7f}) {
        AgentSnapshot s = seed;
        for (std::uint32_t a = 0; a < 2; ++a) predictEnd(s, a, 1.0f, certainty);
        Agent agent(s);
        agent.update(0.0f, obs, 0.1f);
        EXPECT_EQ(agent.stats().planningSteps, certainty > 0.8f ? 1u : 0u) << "certainty " << certainty;
    }
}

// After such a plan teaches, the actor weighs every action at the real state by the model's
// one-step prediction of it (core/planner.hpp), not only the action the plan drew. One RBF, three
// actions whose first step ends the trial: action 0 with +1, action 1 with -1, both certain to 0.95;
// action 2 with +1 but certain only to 0.7, so it is left to exploration. Actions 1 and 2 start at a
// preference of -20, so the plan draws action 0: 0's preference rises, 1's falls (only the weighing
// moves it) and 2's stays; masked in this step, 1's stays too.
TEST(PlanningAgent, ContinuousPlansWeighEveryActionTheModelIsSureOf) {
    AgentSnapshot s = oneRbfPlanner(3);
    const Observation obs(s.descriptor);
    s.rewardLow = s.finalRewardLow = -1.0f;  // real rewards seen: imagined ones are clamped to them
    s.rewardHigh = s.finalRewardHigh = 1.0f;
    predictEnd(s, 0, 1.0f, 0.95f);
    predictEnd(s, 1, -1.0f, 0.95f);
    predictEnd(s, 2, 1.0f, 0.7f);
    float* preference = s.weights.data() + 1;  // the row: critic, then one actor weight per action
    preference[1] = preference[2] = -20.0f;
    for (const bool masked : {false, true}) {
        Agent agent(s);
        const std::uint8_t allowed[3] = {1, 0, 1};
        agent.update(0.0f, obs.view(), 0.1f, masked ? ActionMask{allowed, 3} : ActionMask{});
        ASSERT_EQ(agent.stats().planningSteps, 1u);
        const AgentSnapshot taught = agent.snapshot();
        const float* after = taught.weights.data() + 1;
        EXPECT_GT(after[0], preference[0]) << "masked " << masked;
        if (masked) EXPECT_EQ(after[1], preference[1]);
        else EXPECT_LT(after[1], preference[1]);
        EXPECT_EQ(after[2], preference[2]) << "masked " << masked;
    }
}

// Such plans look one discount time constant ahead: tau_discount / dt imagined steps, whatever the
// cap (rollouts that reach the end from further away are the policy's lucky ones; docs/planning.md).
// A 12-cell corridor learned with plans of up to 50 steps: at tau_discount 0.3 s and dt 0.1 s no plan
// is longer than 3 steps; at 10 s plans grow longer than that once the end is known.
TEST(PlanningAgent, ContinuousPlansLookOneDiscountTimeConstantAhead) {
    for (const float tau : {0.3f, 10.0f}) {
        auto env = std::make_unique<Corridor>(12);
        env->settings().planning = true;
        env->settings().tauModel = 0.0f;
        env->settings().maxPlanningSteps = 50;
        env->settings().tauDiscount = tau;
        AgentDescriptor d = env->agentDescriptor();
        d.seed = 5;
        Agent agent(d);
        const std::uint32_t longest = longestPlan(agent, *env, 30, false);
        if (tau < 1.0f) {
            EXPECT_EQ(longest, 3u);  // reached, never passed
        } else {
            EXPECT_GT(longest, 3u);
        }
    }
}

// Such plans teach the actor only at the real state they start from, the critic all along (imagined
// actor updates leaked through overlapping RBFs into dead ends: docs/planning.md). Real steps learn
// nothing here, so every weight change of an update is its plan's.
TEST(PlanningAgent, ContinuousPlansTeachTheActorOnlyWhereTheyStart) {
    auto env = std::make_unique<Corridor>(12);  // short: a random walk finds the end
    env->settings().planning = true;
    env->settings().tauModel = 0.0f;
    env->settings().maxPlanningSteps = 50;
    env->settings().resolution = 30;  // narrow RBFs: a plan's states share few of them
    AgentDescriptor d = env->agentDescriptor();
    d.learnFromRealSteps = false;
    d.seed = 7;
    Agent agent(d);
    Observation obs(d);
    const std::uint32_t actorColumns = d.numActions;
    int plansChecked = 0;
    for (std::uint64_t trial = 0; trial < 20 && plansChecked < 20; ++trial) {
        env->beginTrial(trial);
        float reward = 0.0f;
        for (std::uint32_t step = 0; step < env->maxStepsPerTrial(); ++step) {
            env->observe(obs);
            const AgentSnapshot before = agent.snapshot();
            const std::uint32_t a = agent.update(reward, obs, 0.1f);
            if (agent.stats().planningSteps >= 6) {
                const AgentSnapshot after = agent.snapshot();
                int criticRows = 0, actorRows = 0;
                for (std::size_t row = 0; row < before.featureKeys.size(); ++row) {
                    const float* x = before.weights.data() + row * before.stride;
                    const float* y = after.weights.data() + row * after.stride;
                    criticRows += x[0] != y[0];
                    actorRows += !std::equal(x + 1, x + 1 + actorColumns, y + 1);
                }
                EXPECT_GT(actorRows, 0);
                EXPECT_LT(actorRows, criticRows) << "a plan of " << agent.stats().planningSteps << " steps, " << before.featureKeys.size() << " RBFs";
                ++plansChecked;
            }
            const StepResult r = env->act(a);
            if (r.terminal) {
                agent.endEpisode(r.reward);
                break;
            }
            reward = r.reward;
        }
    }
    EXPECT_GT(plansChecked, 0);
}

// An imagined step that stays at the real state is not learned (core/planner.hpp): in a one-state
// task (a bandit) every imagined step does, so plans learn nothing. Both agents below pull the lever
// each step's mask allows (plans draw their imagined actions from all three), so with the same
// rewards a planning agent's weights stay exactly those of one without planning. A curious agent's
// plans still learn there: their curiosity bonus is what they are for.
TEST(PlanningAgent, ImaginedStepsThatStayAtTheRealStateAreNotLearned) {
    AgentDescriptor d;
    d.numActions = 3;
    d.planning = true;
    d.tauModel = 0.0f;
    d.seed = 3;
    Agent planner(d);
    d.curiosity = CuriosityMode::Novelty;
    Agent curious(d);
    d.curiosity = CuriosityMode::None;
    d.planning = false;
    Agent plain(d);
    Observation obs(d);
    std::uint32_t curiousSteps = 0;
    float reward = 0.0f;
    for (std::uint32_t pull = 0; pull < 60; ++pull) {
        std::uint8_t allowed[3] = {0, 0, 0};
        allowed[pull % 3] = 1;
        const ActionMask mask{allowed, 3};
        ASSERT_EQ(planner.update(reward, obs.view(), 0.1f, mask), pull % 3);
        ASSERT_EQ(plain.update(reward, obs.view(), 0.1f, mask), pull % 3);
        curious.update(reward, obs.view(), 0.1f, mask);
        EXPECT_EQ(planner.stats().planningSteps, 0u) << "pull " << pull;
        curiousSteps += curious.stats().planningSteps;
        reward = pull % 3 == 2 ? 1.0f : -0.5f;
    }
    const AgentSnapshot p = planner.snapshot(), q = plain.snapshot();
    ASSERT_EQ(p.featureKeys.size(), q.featureKeys.size());
    const std::uint32_t learned = 1 + d.numActions;  // critic and actor columns (the planner's rows add the model's)
    for (std::size_t row = 0; row < p.featureKeys.size(); ++row) {
        EXPECT_TRUE(std::equal(p.weights.data() + row * p.stride, p.weights.data() + row * p.stride + learned,
                               q.weights.data() + row * q.stride))
            << "row " << row;
    }
    EXPECT_GT(curiousSteps, 0u);
}

// Every real reward of this walk is -1 until the goal, where the trial ends with `goal` (0, or +1
// once), so no policy can earn a value above `goal`. Unnormalised RBFs plus TD(lambda) still push the
// weights' sum above it at some states (+4.9 over these runs before values were bounded by the
// rewards seen; with the goal's +1, values up to +6.3 on the long corridor while a final reward
// bounded them as if it came every step); what the agent uses and reports -- bootstrapped values,
// stats.value, the sampled value function -- stays within [-1 / (1 - gamma), goal], with planning on
// or off.
TEST(PlanningAgent, ValuesStayWithinWhatTheRealRewardsAllow) {
    constexpr int kCells = 40;
    for (const float goal : {0.0f, 1.0f}) {
        for (const bool planning : {true, false}) {
            float highest = -1e9f, lowest = 1e9f, highestSampled = -1e9f;
            for (std::uint64_t run = 0; run < 5; ++run) {
                AgentDescriptor d;
                d.addContinuousSensor();
                d.numActions = 3;  // left, right, stay
                d.tauDiscount = 10.0f;  // gamma 0.99 at dt 0.1
                d.planning = planning;
                d.tauModel = 0.0f;
                d.maxPlanningSteps = 50;
                d.seed = 1000 + run;
                Agent agent(d);
                Observation obs(d);
                for (int trial = 0; trial < 30; ++trial) {
                    int x = 0;
                    float reward = 0.0f;
                    bool reached = false;
                    for (int step = 0; step < 2000 && !reached; ++step) {
                        obs.continuous[0] = -1.0f + 2.0f * static_cast<float>(x) / (kCells - 1);
                        const std::uint32_t a = agent.update(reward, obs, 0.1f);
                        highest = std::max(highest, agent.stats().value);
                        lowest = std::min(lowest, agent.stats().value);
                        x = a == 0 ? std::max(0, x - 1) : a == 1 ? std::min(kCells - 1, x + 1) : x;
                        reached = x == kCells - 1;
                        reward = -1.0f;
                    }
                    if (reached) agent.endEpisode(goal);
                    else agent.truncateEpisode(reward);
                }
                float sampled[64];
                agent.sampleValueFunction({ValueAxis{SensorKind::Continuous, 0, 64}}, obs, sampled, 64);
                for (float v : sampled) highestSampled = std::max(highestSampled, v);
            }
            // The horizon the trials set (core/horizon.hpp) reaches its longest, 300 decisions.
            const float horizon = std::max(10.0f, core::AdaptiveHorizon::kMaxSteps * 0.1f);
            const float floor = -1.0f / (1.0f - std::exp(-0.1f / horizon));
            EXPECT_LE(highest, goal) << "planning " << planning << ", goal " << goal;
            EXPECT_LE(highestSampled, goal) << "planning " << planning << ", goal " << goal;
            EXPECT_GE(lowest, floor) << "planning " << planning << ", goal " << goal;
            EXPECT_LT(lowest, -5.0f) << "planning " << planning << ", goal " << goal;  // the values did learn the cost
        }
    }
}
