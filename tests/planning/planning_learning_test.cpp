// Planning on the shared maze #2 (thesis figs. 40-41; original, 10 runs: 1124 steps per trial
// over trials 41-50 without planning, 67 with plans of <= 50 steps; continuous runs hit the cap).
#include <gtest/gtest.h>

#include <algorithm>

#include "tasks/maze.hpp"
#include "tasks/registry.hpp"

using namespace verve;
using namespace verve::tasks;

namespace {

LearningCurve maze2(const char* task, std::uint32_t runs, const DescriptorOverride& overrides = {}) {
    return runExperiment(findTask(task)->make, runs, 51, 1, overrides, 2);
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
// steps). Now every late trial of every run does (10 runs, seed 1: 437.4 steps over trials 41-50; 452
// before the model predicted changes).
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

// The moved goal (maze #1's goal moves at trial 50; the task bounds the actor weights at 3): plans
// back the old path's new cost up through the known maze, so a planning agent leaves it sooner.
// Seeds 1-10, 20 runs each: trials 60-69 17.8-18.8 steps with planning against 38.3-38.4 without;
// every run finds the new goal from trial 60 on. (Without the actor bound, planning runs stay on the
// old path: 1,439-1,871 steps, the worst seed at the goal in 79% of trials; docs/experiments.md.)
TEST(PlanningLearning, PlanningFindsTheMovedGoalFasterThanRlAlone) {
    constexpr int kSeeds = 10;
    const TaskInfo* info = findTask("maze1-moving-goal");
    auto plan = [](AgentDescriptor& d) { d.planning = true; };
    double planned = 0.0, plain = 0.0, worst = 1.0;
    for (std::uint64_t seed = 1; seed <= kSeeds; ++seed) {
        const LearningCurve p = runExperiment(info->make, 20, 100, seed, plan, 2);
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
// each (the table's 50 cost 2.5x as much under ASan), last 10 trials: planning 72.7 steps against 80.3
// for RL alone (50 runs each: 73.0 / 80.3), faster on 9 of the 10 seeds, every late trial at the goal.
// Before the model predicted changes (core/predictive_model.hpp) planning took 100.4: plans through
// blurred positions slipped through walls and taught paths that do not exist.
TEST(PlanningLearning, ContinuousPlanningNoSlowerThanRlOnMaze1) {
    constexpr int kSeeds = 10;
    const TaskInfo* maze1 = findTask("maze1-continuous");
    auto plan = [](AgentDescriptor& d) { d.planning = true; };
    double planned = 0.0, plain = 0.0, reached = 1.0;
    for (std::uint64_t seed = 1; seed <= kSeeds; ++seed) {
        const LearningCurve p = runExperiment(maze1->make, 20, maze1->trials, seed, plan, 2);
        planned += windowMean(p.steps, 90, 100) / kSeeds;
        plain += windowMean(runExperiment(maze1->make, 20, maze1->trials, seed, {}, 2).steps, 90, 100) / kSeeds;
        reached = std::min(reached, windowMean(p.terminal, 90, 100));
    }
    std::printf("continuous maze1, last 10 trials over 10 seeds: planning %.1f, no planning %.1f steps\n", planned,
                plain);
    EXPECT_LE(planned, plain);
    EXPECT_DOUBLE_EQ(reached, 1.0);
}

// Known gap (the KnownGap convention: tests/learning/hot_plate_learning_test.cpp; docs/planning.md):
// on continuous maze #2 planning reaches the goal every time but is not faster than RL alone.
// Plans <= 50 with threshold 0.1 (this test, seed 1, 10 runs): 437.4 against 437.0 steps on trials
// 41-50. With the default plans over seeds 101, 202, ..., 1010 (30 runs each): 505.8 against 469.9
// (standard error of each mean ~20). The bar is "no slower than RL alone".
TEST(KnownGapPlanningLearning, ContinuousPlanningNoSlowerThanRl) {
    const double planned = windowMean(maze2("maze2-continuous", 10, planContinuously).steps, 41, 51);
    const double plain = windowMean(maze2("maze2-continuous", 10).steps, 41, 51);
    std::printf("continuous maze2 trials 41-50: planning %.1f, no planning %.1f steps\n", planned, plain);
    EXPECT_LE(planned, plain);
}
