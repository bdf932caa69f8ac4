#include <gtest/gtest.h>

#include <set>

#include "tasks/sequential_actions.hpp"

using namespace verve::tasks;

TEST(SequentialActions, BlocksTrainBackwards) {
    SequentialActions task(3);
    for (std::uint32_t t = 0; t < 750; ++t) {
        task.beginTrial(t);
        const std::uint32_t block = std::min(t / 100u, 6u);
        EXPECT_EQ(task.firstStimulus(), 6u - block) << "trial " << t;
        EXPECT_EQ(task.optimalSteps(), block + 1);
    }
}

TEST(SequentialActions, CorrectChainPaysOneWrongActionEndsWithZero) {
    SequentialActions task(11);
    for (int t = 0; t < 200; ++t) task.beginTrial(0);  // skip to block 2
    task.beginTrial(0);
    EXPECT_EQ(task.firstStimulus(), 4u);
    verve::Observation obs(task.agentDescriptor());
    for (std::uint32_t s = 4; s < 6; ++s) {
        task.observe(obs);
        EXPECT_EQ(obs.discrete[0], static_cast<int>(s));
        const StepResult r = task.act(task.correctAction(s));
        EXPECT_FLOAT_EQ(r.reward, 0.0f);
        EXPECT_FALSE(r.terminal);
    }
    const StepResult last = task.act(task.correctAction(6));
    EXPECT_FLOAT_EQ(last.reward, 1.0f);
    EXPECT_TRUE(last.terminal);
    EXPECT_TRUE(task.succeeded());

    task.beginTrial(0);
    const StepResult wrong = task.act((task.correctAction(4) + 1) % 7);
    EXPECT_FLOAT_EQ(wrong.reward, 0.0f);
    EXPECT_TRUE(wrong.terminal);
    EXPECT_FALSE(task.succeeded());
}

TEST(SequentialActions, CorrectActionsArePermutationAndSettingsAreTheThesis) {
    SequentialActions task(42);
    std::set<std::uint32_t> actions;
    for (std::uint32_t s = 0; s < 7; ++s) actions.insert(task.correctAction(s));
    EXPECT_EQ(actions.size(), 7u);
    const auto d = task.agentDescriptor();
    EXPECT_EQ(d.discreteSensors, (std::vector<std::uint32_t>{7}));
    EXPECT_EQ(d.numActions, 7u);
    EXPECT_FLOAT_EQ(d.policyMultiplier, 1000.0f);
    EXPECT_FLOAT_EQ(d.tauEligibility, 0.2f);
    EXPECT_FLOAT_EQ(d.tauDiscount, 5.0f);
    EXPECT_THROW(task.act(7), std::invalid_argument);
}
