#include <gtest/gtest.h>

#include "tasks/curiosity_grid.hpp"

using namespace verve::tasks;

TEST(CuriosityGrid, RewardsSitWhereTheOriginalPutThem) {
    EXPECT_FLOAT_EQ(CuriosityGrid::rewardAt({4, 4}), 0.1f);
    EXPECT_FLOAT_EQ(CuriosityGrid::rewardAt({4, 1}), 0.1f);
    EXPECT_FLOAT_EQ(CuriosityGrid::rewardAt({1, 4}), 0.1f);
    EXPECT_FLOAT_EQ(CuriosityGrid::rewardAt({8, 8}), 1.0f);
    EXPECT_FLOAT_EQ(CuriosityGrid::rewardAt({1, 1}), 0.0f);
    EXPECT_FLOAT_EQ(CuriosityGrid::rewardAt({9, 9}), 0.0f);
}

TEST(CuriosityGrid, NoTerminalStateAndStayingKeepsPaying) {
    CuriosityGrid grid(CuriosityAgent::Planning);
    grid.beginTrial(0);
    EXPECT_EQ(grid.position(), (Cell{1, 1}));
    for (int i = 0; i < 3; ++i) EXPECT_FALSE(grid.act(1).terminal);  // right to (4, 1)
    EXPECT_EQ(grid.position(), (Cell{4, 1}));
    const StepResult r = grid.act(4);  // stay
    EXPECT_FLOAT_EQ(r.reward, 0.1f);
    EXPECT_FALSE(r.terminal);
    EXPECT_FALSE(grid.succeeded());
    EXPECT_EQ(grid.maxStepsPerTrial(), 100u);
}

TEST(CuriosityGrid, AgentVariants) {
    const auto rl = CuriosityGrid(CuriosityAgent::Rl).agentDescriptor();
    const auto plan = CuriosityGrid(CuriosityAgent::Planning).agentDescriptor();
    const auto curious = CuriosityGrid(CuriosityAgent::Curious).agentDescriptor();
    EXPECT_FALSE(rl.planning);
    EXPECT_TRUE(plan.planning);
    EXPECT_EQ(plan.curiosity, verve::CuriosityMode::None);
    EXPECT_EQ(curious.curiosity, verve::CuriosityMode::Novelty);
    EXPECT_EQ(curious.maxPlanningSteps, 50u);
    EXPECT_FLOAT_EQ(curious.tauModel, 0.0f);
    EXPECT_FLOAT_EQ(curious.policyMultiplier, 2.0f);
}
