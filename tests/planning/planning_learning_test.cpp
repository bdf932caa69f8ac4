// Planning on the shared maze #2 (thesis figs. 40-41; original, 10 runs: 1124 steps per trial
// over trials 41-50 without planning, 67 with plans of <= 50 steps; continuous runs hit the cap).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <vector>

#include "tasks/maze.hpp"
#include "tasks/registry.hpp"

using namespace verve;
using namespace verve::tasks;

namespace {

LearningCurve maze2(const char* task, std::uint32_t runs, const DescriptorOverride& overrides = {}) {
    return runExperiment(findTask(task)->make, runs, 51, 1, overrides, 2);
}

// Steps over trials [first, last) of `task`, `runs` runs per seed, and the share of them at the
// goal, averaged over the seeds, and the worst seed's share.
struct Late {
    double steps = 0.0, reached = 0.0, worstReached = 1.0;
};
Late lateTrials(const char* task, std::uint32_t runs, std::uint32_t trials, const std::vector<std::uint64_t>& seeds,
                std::size_t first, std::size_t last, const DescriptorOverride& overrides) {
    const TaskInfo* info = findTask(task);
    const double n = static_cast<double>(seeds.size());
    Late late;
    for (std::uint64_t seed : seeds) {
        const LearningCurve c = runExperiment(info->make, runs, trials, seed, overrides, 2);
        late.steps += windowMean(c.steps, first, last) / n;
        late.reached += windowMean(c.terminal, first, last) / n;
        late.worstReached = std::min(late.worstReached, windowMean(c.terminal, first, last));
    }
    return late;
}

void planByDefault(AgentDescriptor& d) { d.planning = true; }

const std::vector<std::uint64_t> kSeeds1To10{1, 2, 3, 4, 5, 6, 7, 8, 9, 10};

// lateTrials of `task` with the default plans and without, over the same runs.
struct PlannedAndPlain {
    Late planned, plain;
};
PlannedAndPlain withAndWithoutPlans(const char* task, std::uint32_t runs, std::uint32_t trials, std::size_t first,
                                    std::size_t last) {
    return {lateTrials(task, runs, trials, kSeeds1To10, first, last, planByDefault),
            lateTrials(task, runs, trials, kSeeds1To10, first, last, {})};
}

}  // namespace

TEST(PlanningLearning, PlanningSolvesMaze2FarFasterThanRlAlone) {
    const LearningCurve planning = maze2("maze2-planning", 10);
    const LearningCurve rl = maze2("maze2", 10);
    const double planned = windowMean(planning.steps, 41, 51);
    const double plain = windowMean(rl.steps, 41, 51);
    std::printf("maze2 trials 41-50: planning %.1f, no planning %.1f; trials 0-9: %.1f vs %.1f\n", planned, plain,
                windowMean(planning.steps, 0, 10), windowMean(rl.steps, 0, 10));
    EXPECT_LE(planned, 67.0);       // the original's planning result
    EXPECT_GE(plain, 2.0 * planned);  // far slower without planning
    EXPECT_LT(windowMean(planning.steps, 0, 10), 0.5 * windowMean(rl.steps, 0, 10));
}

TEST(PlanningLearning, ModelErrorFallsTowardZero) {
    auto make = findTask("maze2-planning")->make;
    auto env = make(3);
    AgentDescriptor d = env->agentDescriptor();
    d.seed = 3;
    Agent agent(d);
    runTrial(agent, *env, 0);
    const float early = agent.stats().modelError;
    for (std::uint64_t t = 1; t < 30; ++t) runTrial(agent, *env, t);
    const float late = agent.stats().modelError;
    EXPECT_GT(early, 0.05f);
    EXPECT_LT(late, 0.01f);  // a deterministic maze is learned exactly (rate 1)
}

namespace {

// Maze #2 with continuous sensors and planning (<= 50 steps, model rate 1). Continuous predictions
// are never exact: a tight threshold keeps plans where the model is good (0.5, the default measured
// on the discrete grids, lets errors compound here).
void planContinuously(AgentDescriptor& d) {
    d.planning = true;
    d.tauModel = 0.0f;
    d.maxPlanningSteps = 50;
    d.planningUncertaintyThreshold = 0.1f;
}

}  // namespace

// The original's continuous planning runs all hit the 10,000-step cap; before plans had to reach the
// end of the trial to teach (docs/planning.md), ours reached the goal in 90% of late trials (1035
// steps). Now every late trial of every run does (10 runs, seed 1: 606.8 steps over trials 41-50;
// 641.0 before the actor weighed every action after a plan).
TEST(PlanningLearning, PlanningWorksWithContinuousSensors) {
    const LearningCurve c = maze2("maze2-continuous", 10, planContinuously);
    const double late = windowMean(c.steps, 41, 51);
    std::printf("continuous maze2 with planning, trials 41-50: %.1f steps\n", late);
    EXPECT_LT(late, 3000.0);
    EXPECT_GE(windowMean(c.terminal, 41, 51), 0.99);  // every late trial reaches the goal
}

// A long horizon, -1 per step until the goal 39 steps away (10 runs, seed 1): plain RL learns the
// optimum (39.0 steps on trials 41-50, every run). Planning once froze the start region at the value
// floor (30% of late trials reached the goal); now it reaches the goal in every late trial, in the
// same 39.0 steps.
TEST(PlanningLearning, PlanningMatchesRlOnALongCorridor) {
    const LearningCurve planning = runExperiment(findTask("corridor-planning")->make, 10, 51, 1, {}, 2);
    const LearningCurve rl = runExperiment(findTask("corridor")->make, 10, 51, 1, {}, 2);
    const double planned = windowMean(planning.steps, 41, 51);
    const double plain = windowMean(rl.steps, 41, 51);
    std::printf("corridor trials 41-50: planning %.1f steps (%.0f%% at the goal), no planning %.1f\n", planned,
                100.0 * windowMean(planning.success, 41, 51), plain);
    EXPECT_GE(windowMean(planning.success, 41, 51), 0.99);  // every run, every late trial
    EXPECT_LE(planned, plain);
}

// The same corridor with the default plans (<= 10 steps), seeds 1-10, 10 runs each, trials 91-100:
// RL alone and planning both 39.0 steps, every late trial at the goal. Before plans trusted only ends
// the model is sure of (core/planner.cpp), planning drifted after trial 80 to 39.475 (39.28-39.63 on
// every seed): plans that ended a step early on the model's blurred terminal output raised the values
// of the last cells, and their negative real TD errors lowered the actor's preference for the step to
// the goal (docs/planning.md). Before the roulette kept underflowed preferences' proportions, 39.833.
TEST(PlanningLearning, PlanningNoSlowerThanRlLateOnALongCorridor) {
    const auto [planned, plain] = withAndWithoutPlans("corridor", 10, 100, 90, 100);
    std::printf("corridor, trials 91-100 over seeds 1-10: planning %.3f, no planning %.3f steps; worst seed at the goal %.3f\n",
                planned.steps, plain.steps, planned.worstReached);
    EXPECT_DOUBLE_EQ(planned.worstReached, 1.0);
    EXPECT_LE(planned.steps, plain.steps);
}

// The continuous 1-D hot plate, seeds 1-10, 300 runs each, the last 10 of 31 trials: planning 4.606
// steps against 4.615 for RL alone. A known gap (4.633) until the actor weighed every action the model
// is sure of after a plan (core/planner.hpp): the teaching plans end a cell short of the plate's edge,
// where the model's RBFs blur the terminal step into its neighbour, and the values they teach sit
// above what the optimal policy earns; the actor, which learned only the action each plan drew,
// took that bias as a preference (docs/experiments.md, "Plans that end a cell short", and
// docs/planning.md, "After a plan, the actor weighs every action").
TEST(PlanningLearning, ContinuousPlanningNoSlowerThanRlOnTheOneDimensionalHotPlate) {
    const auto [planned, plain] = withAndWithoutPlans("hot-plate-1d-continuous", 300, 31, 21, 31);
    std::printf("continuous 1-D hot plate, last 10 trials over seeds 1-10: planning %.3f, no planning %.3f steps\n",
                planned.steps, plain.steps);
    EXPECT_LE(planned.steps, plain.steps);
}

// The moved goal (maze #1's goal moves at trial 50; the task bounds the actor weights at 3): plans
// back the old path's new cost up through the known maze, so a planning agent leaves it sooner.
// Seeds 1-10, 20 runs each: trials 60-69 18.3 steps with planning against 38.0 without; every run
// finds the new goal from trial 60 on. (Without the actor bound, planning runs stayed on the old path,
// 1,439-1,871 steps with the worst seed at the goal in 79% of trials, until hopeless states explored:
// now 17.6; docs/experiments.md.)
TEST(PlanningLearning, PlanningFindsTheMovedGoalFasterThanRlAlone) {
    constexpr int kSeeds = 10;
    const TaskInfo* info = findTask("maze1-moving-goal");
    double planned = 0.0, plain = 0.0, worst = 1.0;
    for (std::uint64_t seed = 1; seed <= kSeeds; ++seed) {
        const LearningCurve p = runExperiment(info->make, 20, 100, seed, planByDefault, 2);
        const LearningCurve r = runExperiment(info->make, 20, 100, seed, {}, 2);
        planned += windowMean(p.steps, 60, 70) / kSeeds;
        plain += windowMean(r.steps, 60, 70) / kSeeds;
        worst = std::min({worst, windowMean(p.success, 60, 100), windowMean(r.success, 60, 100)});
    }
    std::printf("moved goal, trials 60-69 over 10 seeds: planning %.1f, no planning %.1f steps; worst success %.3f\n",
                planned, plain, worst);
    EXPECT_DOUBLE_EQ(worst, 1.0);
    EXPECT_LE(planned, plain);
}

// Continuous maze #1 (the experiments table's task, default plans <= 10 steps): seeds 1-10, 20 runs
// each (the table's 50 cost 2.5x as much under ASan), last 10 trials: planning 55.6 steps against 76.8
// for RL alone (54.4 before plans trusted only ends the model is sure of, core/planner.cpp; when first
// measured 53.4 / 80.3), every late trial at the goal (72.7 with 20 runs while imagined steps past
// the first also taught the actor; core/planner.hpp).
// Before the model predicted changes (core/predictive_model.hpp) planning took 100.4: plans through
// blurred positions slipped through walls and taught paths that do not exist.
TEST(PlanningLearning, ContinuousPlanningNoSlowerThanRlOnMaze1) {
    const auto [planned, plain] = withAndWithoutPlans("maze1-continuous", 20, 100, 90, 100);
    std::printf("continuous maze1, last 10 trials over 10 seeds: planning %.1f, no planning %.1f steps\n", planned.steps,
                plain.steps);
    EXPECT_LE(planned.steps, plain.steps);
    EXPECT_DOUBLE_EQ(planned.worstReached, 1.0);
}

// Continuous maze #2 with the default plans (<= 10 steps), seeds 101, 202, ..., 1010, 30 runs each,
// trials 41-50: planning 384.3 steps against 409.6 for RL alone, plans <= 50 steps 404.0 (373.7 and
// 404.0 before plans trusted only ends the model is sure of, core/planner.cpp); every late
// trial at the goal. Before hopeless states explored (core::hopelessValue), RL took 469.9 and default
// plans 461.6; with 10 runs each (the standard error of a mean ~20) this test read 472.4 / 498.6 /
// 505.5, and after that change 378.7 / 435.0 / 421.7: too few runs to order the long plans and RL,
// hence 30. While imagined steps past the first taught the actor, planning took 505.8 against 469.9
// (30 runs): the preference for "up" that plans taught beside the goal leaked through overlapping
// RBFs across the wall into the dead end on its other side, where planning agents spent 5-10x RL's
// time (docs/planning.md).
// Long plans (<= 50 steps, threshold 0.1, the original's maze #2 settings): before such plans looked
// only one discount time constant ahead (10 steps here) they took 540.6 (10 runs; seed 1: 453.2 against
// RL's 437.0): from far away, the rollouts that reach the goal are the policy's rare lucky ones
// (0.2-15% of dry runs from the maze's left seven columns), and teaching only those taught values the
// policy does not earn (docs/planning.md). A known gap until then.
TEST(PlanningLearning, ContinuousPlanningNoSlowerThanRlOnMaze2) {
    const std::vector<std::uint64_t> seeds{101, 202, 303, 404, 505, 606, 707, 808, 909, 1010};
    const Late plain = lateTrials("maze2-continuous", 30, 51, seeds, 41, 51, {});
    const Late planned = lateTrials("maze2-continuous", 30, 51, seeds, 41, 51, planByDefault);
    const Late longPlans = lateTrials("maze2-continuous", 30, 51, seeds, 41, 51, planContinuously);
    std::printf("continuous maze2, trials 41-50 over 10 seeds: planning %.1f, with plans <= 50 %.1f, no planning %.1f "
                "steps; at the goal %.3f, %.3f and %.3f\n", planned.steps, longPlans.steps, plain.steps, planned.reached,
                longPlans.reached, plain.reached);
    EXPECT_LE(planned.steps, plain.steps);
    EXPECT_LE(longPlans.steps, plain.steps);
    // Every late trial of all three reaches the goal (10,000-step cap): planning no less often.
    EXPECT_GE(planned.reached, plain.reached);
    EXPECT_GE(longPlans.reached, plain.reached);
}

// The bandit (one state, a lever's payoff ~N(its mean, 1) clamped to [-1, 1]): seeds 1-10, 200 runs
// each, pulls 900-999. While plans replayed imagined pulls (each lever's last payoff, often the
// clamped 1, as if certain), planning agents committed to a lever after a few lucky pulls: payoff
// 1.368 against RL's 1.497, best lever 63.7% against 81.4%. Now an imagined step that stays at the
// real state teaches nothing (core/planner.hpp), so in a one-state task plans learn nothing and the
// two differ only in their random draws: over seeds 1-40 the paired difference is -0.0001 in payoff
// (standard deviation 0.018 per seed) and +0.007 in the best lever's share (0.038). "No worse" is
// judged within two standard errors of a 10-seed mean (0.011 and 0.024); the old plans missed it by
// 11 and 7 times that margin. This run: 1.4948 against 1.4972, 82.1% against 81.4%.
TEST(PlanningLearning, PlanningNoWorseThanRlOnTheBandit) {
    constexpr int kSeeds = 10;
    const TaskInfo* info = findTask("bandit");
    double planned = 0.0, plain = 0.0, plannedBest = 0.0, plainBest = 0.0;
    for (std::uint64_t seed = 1; seed <= kSeeds; ++seed) {
        const LearningCurve p = runExperiment(info->make, 200, 1000, seed, planByDefault, 2);
        const LearningCurve r = runExperiment(info->make, 200, 1000, seed, {}, 2);
        planned += windowMean(p.reward, 900, 1000) / kSeeds;
        plain += windowMean(r.reward, 900, 1000) / kSeeds;
        plannedBest += windowMean(p.success, 900, 1000) / kSeeds;
        plainBest += windowMean(r.success, 900, 1000) / kSeeds;
    }
    std::printf("bandit pulls 900-999 over 10 seeds: payoff %.4f with planning, %.4f without; best lever %.3f and %.3f\n",
                planned, plain, plannedBest, plainBest);
    EXPECT_GE(planned, plain - 0.011);
    EXPECT_GE(plannedBest, plainBest - 0.024);
}

