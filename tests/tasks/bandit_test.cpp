#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "tasks/bandit.hpp"

using namespace verve::tasks;

TEST(Bandit, MeansArePerRunAndTheBestIsTheirMaximum) {
    Bandit a(1), b(1), c(2);
    EXPECT_EQ(a.means(), b.means());
    EXPECT_NE(a.means(), c.means());
    const auto& m = a.means();
    EXPECT_EQ(m.size(), 10u);
    EXPECT_EQ(a.bestArm(), static_cast<std::uint32_t>(std::max_element(m.begin(), m.end()) - m.begin()));
    EXPECT_EQ(a.agentDescriptor().numActions, 10u);
    EXPECT_TRUE(a.agentDescriptor().discreteSensors.empty());
    EXPECT_FLOAT_EQ(a.agentDescriptor().policyMultiplier, 100.0f);
    EXPECT_FLOAT_EQ(a.agentDescriptor().tauDiscount, 0.3f);
}

TEST(Bandit, PayoffsAreNoisyAroundTheLeverMean) {
    double meanSum = 0.0, meanSq = 0.0;
    const int runs = 4000;
    for (int r = 0; r < runs; ++r) {
        Bandit bandit(static_cast<std::uint64_t>(r));
        bandit.beginTrial(static_cast<std::uint64_t>(r) * 7 + 3);
        const StepResult s = bandit.act(0);
        EXPECT_FALSE(s.terminal);  // continuing: pulls never end the stream
        EXPECT_EQ(bandit.carriedReward(), s.reward);
        const double noise = s.reward - bandit.means()[0];
        meanSum += noise;
        meanSq += noise * noise;
    }
    EXPECT_NEAR(meanSum / runs, 0.0, 0.06);
    EXPECT_NEAR(meanSq / runs, 1.0, 0.08);
}

TEST(Bandit, SuccessMeansTheBestLeverAndBadLeversThrow) {
    Bandit bandit(5);
    bandit.beginTrial(1);
    bandit.act(bandit.bestArm());
    EXPECT_TRUE(bandit.succeeded());
    bandit.beginTrial(2);
    bandit.act((bandit.bestArm() + 1) % 10);
    EXPECT_FALSE(bandit.succeeded());
    EXPECT_THROW(bandit.act(10), std::invalid_argument);
    EXPECT_THROW(Bandit(1, 1), std::invalid_argument);
}
