#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>

#include "tasks/bandit.hpp"
#include "tasks/curiosity_grid.hpp"
#include "tasks/driver.hpp"
#include "tasks/hot_plate.hpp"
#include "tasks/maze.hpp"
#include "tasks/registry.hpp"

using namespace verve::tasks;

TEST(RunTrial, TerminalTrialCountsEveryStepAndReward) {
    Maze maze(maze1Layout(), Sensors::Discrete);
    verve::Agent agent(maze.agentDescriptor());
    const TrialResult r = runTrial(agent, maze, 1);
    ASSERT_TRUE(r.terminal);
    EXPECT_TRUE(r.succeeded);
    EXPECT_GE(r.steps, 22u);
    EXPECT_EQ(r.optimalSteps, 22u);
    EXPECT_DOUBLE_EQ(r.rewardSum, -static_cast<double>(r.steps - 1) + 1.0);  // -1 per step, +1 at the goal
    EXPECT_EQ(agent.stats().steps, r.steps);  // one real update per step, none extra
}

TEST(RunTrial, CappedTrialIsNotTerminal) {
    CuriosityGrid grid(CuriosityAgent::Rl);
    verve::Agent agent(grid.agentDescriptor());
    const TrialResult r = runTrial(agent, grid, 1);
    EXPECT_FALSE(r.terminal);
    EXPECT_EQ(r.steps, 100u);
    EXPECT_EQ(agent.stats().steps, 100u);
    EXPECT_EQ(agent.stats().liveTraces, 0u);  // truncated: the last reward learned, the trial forgotten
}

TEST(RunTrial, ContinuingTaskCarriesTheRewardAndTheShortTermMemory) {
    Bandit bandit(3);
    verve::Agent agent(bandit.agentDescriptor());
    const TrialResult first = runTrial(agent, bandit, 1);
    EXPECT_FALSE(first.terminal);
    EXPECT_EQ(agent.stats().liveTraces, 1u);  // not reset: the next pull bootstraps from this one
    const float paid = bandit.carriedReward();
    EXPECT_EQ(static_cast<float>(first.rewardSum), paid);
    runTrial(agent, bandit, 2);
    // The second update received the first pull's payoff: delta = r + gamma V - V with V = 0.
    EXPECT_FLOAT_EQ(agent.tdError(), std::clamp(paid, -1.0f, 1.0f));
}

TEST(RunTrial, StartInsideTheSafeZoneTakesNoSteps) {
    HotPlate plate({1, false, Sensors::Discrete});
    verve::Agent agent(plate.agentDescriptor());
    std::uint64_t seed = 0;
    for (;; ++seed) {  // find a seed whose start is on an edge
        plate.beginTrial(seed);
        if (plate.finishedAtStart()) break;
    }
    const TrialResult r = runTrial(agent, plate, seed);
    EXPECT_EQ(r.steps, 0u);
    EXPECT_TRUE(r.terminal);
    EXPECT_TRUE(r.succeeded);
    EXPECT_EQ(agent.stats().steps, 0u);
}

TEST(RunExperiment, SameCurveWhateverTheThreadCount) {
    const TaskInfo* info = findTask("hot-plate-1d-continuous");
    ASSERT_NE(info, nullptr);
    const LearningCurve one = runExperiment(info->make, 6, 8, 99, {}, 1);
    const LearningCurve two = runExperiment(info->make, 6, 8, 99, {}, 2);
    EXPECT_EQ(one.steps, two.steps);
    EXPECT_EQ(one.reward, two.reward);
    EXPECT_EQ(one.runs, 6u);
    EXPECT_EQ(one.trials(), 8u);
    const LearningCurve other = runExperiment(info->make, 6, 8, 100, {}, 2);
    EXPECT_NE(one.steps, other.steps);
}

TEST(RunExperiment, OverridesReachTheAgent) {
    // Fixing the agent's seed on a task without randomness makes every run identical, so the
    // mean curve holds whole numbers.
    const TaskInfo* info = findTask("maze1");
    const LearningCurve curve =
        runExperiment(info->make, 4, 3, 5, [](verve::AgentDescriptor& d) { d.seed = 1234; }, 2);
    for (double s : curve.steps) EXPECT_DOUBLE_EQ(s, static_cast<double>(static_cast<long>(s)));
    const LearningCurve free = runExperiment(info->make, 4, 3, 5, {}, 2);
    bool fractional = false;
    for (double s : free.steps) fractional |= s != static_cast<double>(static_cast<long>(s));
    EXPECT_TRUE(fractional);
}

TEST(RunExperiment, BadArgumentsThrow) {
    const TaskInfo* info = findTask("maze1");
    EXPECT_THROW(runExperiment(info->make, 0, 3, 1), std::invalid_argument);
    EXPECT_THROW(runExperiment(info->make, 3, 0, 1), std::invalid_argument);
    EXPECT_THROW(runExperiment(TaskFactory{}, 3, 3, 1), std::invalid_argument);
    EXPECT_THROW(runExperiment([](std::uint64_t) { return std::unique_ptr<Environment>(); }, 2, 1, 1),
                 std::invalid_argument);
    // An override that breaks the descriptor surfaces the agent's error.
    EXPECT_THROW(runExperiment(info->make, 2, 1, 1, [](verve::AgentDescriptor& d) { d.numActions = 0; }),
                 verve::Error);
}

TEST(WindowMean, AveragesAndRejectsEmptyWindows) {
    const std::vector<double> v{1, 2, 3, 4};
    EXPECT_DOUBLE_EQ(windowMean(v, 1, 3), 2.5);
    EXPECT_DOUBLE_EQ(windowMean(v, 2, 99), 3.5);
    EXPECT_THROW(windowMean(v, 4, 9), std::out_of_range);
}
