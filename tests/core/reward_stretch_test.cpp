// The horizon's measure of how far the rewards that matter lie (core/reward_stretch.hpp).
#include "core/reward_stretch.hpp"

#include <gtest/gtest.h>

using verve::core::RewardStretch;

TEST(RewardStretch, AConstantRewardMakesTheWholeTrialOneStretch) {
    RewardStretch s;
    s.see(false, 0.0f, 0.1f);  // the trial's first update learns no reward
    for (int t = 0; t < 9; ++t) s.see(true, -1.0f, 0.1f);
    EXPECT_FLOAT_EQ(s.trialLongest(), 1.0f);  // as long as the trial: the horizon follows the trials
}

TEST(RewardStretch, ARewardThatChangesEveryStepMakesStretchesOfAStep) {
    RewardStretch s;
    s.see(false, 0.0f, 0.05f);
    for (int t = 0; t < 100; ++t) s.see(true, t % 2 == 0 ? 0.1f : 0.2f, 0.05f);
    EXPECT_FLOAT_EQ(s.trialLongest(), 0.1f);  // the first update's dt and the first reward's
}

TEST(RewardStretch, TheLongestStretchCountsAndAResetStartsAfresh) {
    RewardStretch s;
    s.see(true, 0.0f, 0.1f);
    for (int t = 0; t < 30; ++t) s.see(true, 0.0f, 0.1f);  // 3 s of nothing
    s.see(true, 1.0f, 0.1f);
    for (int t = 0; t < 5; ++t) s.see(true, -0.5f + 0.1f * t, 0.1f);
    EXPECT_NEAR(s.trialLongest(), 3.1f, 1e-5f);
    s.reset();
    EXPECT_EQ(s.trialLongest(), 0.0f);
    EXPECT_FALSE(s.seen);
}
