// The values TD errors may bootstrap from: what discounted sums of the rewards seen can reach.
#include <gtest/gtest.h>

#include <cmath>

#include "core/td_learner.hpp"

using namespace verve::core;

TEST(ValueBounds, FollowTheRewardsSeenWithZeroIncluded) {
    RewardRange r;
    ValueBounds b = valueBounds(r, 0.0f, 0.0f, 0.9f);
    EXPECT_EQ(b.low, 0.0f);  // nothing seen yet: every value is 0
    EXPECT_EQ(b.high, 0.0f);
    r.see(-1.0f);
    r.see(-0.5f);
    b = valueBounds(r, 0.0f, 0.0f, 0.9f);
    EXPECT_NEAR(b.low, -10.0f, 1e-4f);
    EXPECT_EQ(b.high, 0.0f);  // only costs: no policy earns more than 0
    r.see(0.25f);
    b = valueBounds(r, 0.0f, 0.0f, 0.9f);
    EXPECT_NEAR(b.high, 2.5f, 1e-4f);
    EXPECT_EQ(bounded(7.0f, b), b.high);
    EXPECT_EQ(bounded(-70.0f, b), b.low);
    EXPECT_EQ(bounded(1.0f, b), 1.0f);
}

// A reward that ends the trial is earned once: -1 per step until a goal's +1 allows no value above
// +1 (at gamma 0.9, not the +10 of +1 for ever), and a final -1 after steps of 0 none below -1.
TEST(ValueBounds, AFinalRewardCountsOnce) {
    RewardRange r;
    r.see(-1.0f);
    r.seeFinal(1.0f);
    ValueBounds b = valueBounds(r, 0.0f, 0.0f, 0.9f);
    EXPECT_NEAR(b.low, -10.0f, 1e-4f);
    EXPECT_EQ(b.high, 1.0f);
    EXPECT_EQ(r.anyLow(), -1.0f);  // what a predicted reward is clamped to
    EXPECT_EQ(r.anyHigh(), 1.0f);

    RewardRange fall;
    fall.see(0.5f);
    fall.seeFinal(-1.0f);
    b = valueBounds(fall, 0.0f, 0.0f, 0.9f);
    EXPECT_EQ(b.low, -1.0f);
    EXPECT_NEAR(b.high, 5.0f, 1e-4f);
    // Step rewards above the final one: earning them for ever is the most.
    fall.seeFinal(0.25f);
    EXPECT_NEAR(valueBounds(fall, 0.0f, 0.0f, 0.9f).high, 5.0f, 1e-4f);
}

TEST(ValueBounds, CuriosityWidensThemByItsBonus) {
    RewardRange r;
    r.see(0.5f);
    const ValueBounds b = valueBounds(r, -0.25f, 0.25f, 0.5f);  // progress: a bonus of either sign
    EXPECT_NEAR(b.low, -0.5f, 1e-6f);
    EXPECT_NEAR(b.high, 1.5f, 1e-6f);
}

TEST(ValueBounds, NoDiscountMeansNoFiniteBoundAndNoNaN) {
    RewardRange r;
    r.see(-1.0f);
    const ValueBounds b = valueBounds(r, 0.0f, 0.0f, 1.0f);
    EXPECT_TRUE(std::isinf(b.low) && b.low < 0.0f);
    EXPECT_EQ(b.high, 0.0f);  // 0 stays 0 (not 0 * infinity)
    EXPECT_EQ(bounded(-1e30f, b), -1e30f);
}
