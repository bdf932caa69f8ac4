// Gymnasium's classic control tasks follow its published equations: each step below was worked
// out from them by hand (CartPole-v1) or with a separate double-precision transcription of the
// equations (Acrobot-v1's RK4 step), not with this code.
#include <gtest/gtest.h>

#include <cmath>

#include "tasks/classic/acrobot_v1.hpp"
#include "tasks/classic/cart_pole_v1.hpp"
#include "tasks/classic/mountain_car_v0.hpp"
#include "tasks/classic/pendulum_v1.hpp"
#include "tasks/classic/solve_run.hpp"

using namespace verve::tasks;

namespace {
constexpr double kTol = 1e-12;
}

TEST(ClassicControl, CartPoleStepsByTheEulerEquations) {
    // From rest, pushed right: the cart accelerates by 9.7561 m/s^2, the pole by -14.634 rad/s^2.
    CartPoleState s;
    EXPECT_FALSE(CartPoleV1::step(s, 1));
    EXPECT_NEAR(s.x, 0.0, kTol);
    EXPECT_NEAR(s.xDot, 0.02 * (10.0 / 1.1 + 0.05 * (10.0 / 1.1) / (0.5 * (4.0 / 3.0 - 0.1 / 1.1)) / 1.1), kTol);
    EXPECT_NEAR(s.theta, 0.0, kTol);
    EXPECT_NEAR(s.thetaDot, -0.02 * (10.0 / 1.1) / (0.5 * (4.0 / 3.0 - 0.1 / 1.1)), kTol);

    CartPoleState t{0.01, -0.02, 0.03, -0.04};
    EXPECT_FALSE(CartPoleV1::step(t, 1));
    EXPECT_NEAR(t.x, 0.0096, kTol);
    EXPECT_NEAR(t.xDot, 0.174679195747555, 1e-14);
    EXPECT_NEAR(t.theta, 0.0292, kTol);
    EXPECT_NEAR(t.thetaDot, -0.323068717960008, 1e-14);
}

TEST(ClassicControl, CartPoleEndsPastTwelveDegreesOrTheTrackAndIsCutAt500) {
    CartPoleState leaning{0.0, 0.0, 0.2094, 0.1};  // 12 degrees is 0.20944 rad
    EXPECT_TRUE(CartPoleV1::step(leaning, 1));
    CartPoleState offTrack{2.399, 1.0, 0.0, 0.0};
    EXPECT_TRUE(CartPoleV1::step(offTrack, 1));
    CartPoleV1 task;
    EXPECT_EQ(task.maxStepsPerTrial(), 500u);
    EXPECT_FLOAT_EQ(task.agentStep(), 0.02f);
    EXPECT_EQ(task.act(0).reward, 1.0f);
}

TEST(ClassicControl, AcrobotTakesOneRk4StepOfTheBookDynamics) {
    AcrobotState s{0.1, -0.2, 0.3, -0.4};
    EXPECT_FALSE(AcrobotV1::step(s, 2));  // torque +1
    EXPECT_NEAR(s.theta1, 0.128211631289126, 1e-13);
    EXPECT_NEAR(s.theta2, -0.211840321026976, 1e-13);
    EXPECT_NEAR(s.dtheta1, -0.0234847315350014, 1e-13);
    EXPECT_NEAR(s.dtheta2, 0.28679521459777, 1e-13);

    AcrobotState rest;  // hanging still with no torque stays so
    EXPECT_FALSE(AcrobotV1::step(rest, 1));
    EXPECT_NEAR(rest.theta1, 0.0, kTol);
    EXPECT_NEAR(rest.dtheta2, 0.0, kTol);
}

TEST(ClassicControl, AcrobotEndsWithTheTipAboveTheBarAndRewardsMinusOneUntilThen) {
    AcrobotState up{3.14159, 0.0, 0.0, 0.0};  // both links upright: the tip is 2 above the pivot
    EXPECT_TRUE(AcrobotV1::step(up, 1));
    AcrobotV1 task;
    task.beginTrial(3);
    EXPECT_EQ(task.act(1).reward, -1.0f);
    EXPECT_EQ(task.maxStepsPerTrial(), 500u);
    task.state() = AcrobotState{3.14159, 0.0, 0.0, 0.0};
    const StepResult last = task.act(1);
    EXPECT_TRUE(last.terminal);
    EXPECT_EQ(last.reward, 0.0f);
}

TEST(ClassicControl, MountainCarFollowsTheHillAndStopsAtTheLeftWall) {
    MountainCarState s{-0.5, 0.0};
    EXPECT_FALSE(MountainCarV0::step(s, 2));
    EXPECT_NEAR(s.velocity, 0.001 - 0.0025 * std::cos(-1.5), kTol);
    EXPECT_NEAR(s.position, -0.499176843004169, 1e-14);

    MountainCarState wall{-1.19, -0.05};
    EXPECT_FALSE(MountainCarV0::step(wall, 0));
    EXPECT_EQ(wall.position, -1.2);
    EXPECT_EQ(wall.velocity, 0.0);

    MountainCarState goal{0.49, 0.02};
    EXPECT_TRUE(MountainCarV0::step(goal, 1));
    MountainCarV0 task;
    EXPECT_EQ(task.maxStepsPerTrial(), 200u);
    task.beginTrial(1);
    EXPECT_GE(task.state().position, -0.6);
    EXPECT_LE(task.state().position, -0.4);
    EXPECT_EQ(task.act(1).reward, -1.0f);
}

TEST(ClassicControl, PendulumCostsTheAngleFromUprightAndNeverEnds) {
    PendulumState s{2.0, 1.0};
    EXPECT_NEAR(PendulumV1::step(s, 2.0), -(4.0 + 0.1 + 0.004), kTol);
    EXPECT_NEAR(s.thetaDot, 1.0 + (15.0 * std::sin(2.0) + 6.0) * 0.05, kTol);
    EXPECT_NEAR(s.theta, 2.09909865350596, 1e-13);

    PendulumState wrapped{4.0, 0.0};  // 4 rad is 2.2832 rad the other way round from upright
    EXPECT_NEAR(PendulumV1::step(wrapped, 0.0), -5.21293514692074, 1e-12);
    PendulumState clipped{0.0, 0.0};
    PendulumV1::step(clipped, 50.0);  // clipped to 2
    EXPECT_NEAR(clipped.thetaDot, 0.3, kTol);

    PendulumV1 task;
    EXPECT_EQ(task.maxStepsPerTrial(), 200u);
    task.beginTrial(5);
    task.state() = PendulumState{3.14159265358979323846, 8.0};
    const StepResult worst = task.act(2);
    EXPECT_FALSE(worst.terminal);
    EXPECT_NEAR(worst.reward, -1.0f, 1e-6f);  // the largest cost, scaled into [-1, 1]
    EXPECT_NEAR(task.gymnasiumReward(), -PendulumV1::kLargestCost, 1e-6);
}

TEST(ClassicControl, TheRegistryNamesEveryTask) {
    for (const char* name : {"cart-pole-v1", "acrobot-v1", "mountain-car-v0", "pendulum-v1"}) {
        const ClassicInfo* info = findClassicTask(name);
        ASSERT_NE(info, nullptr) << name;
        EXPECT_GT(info->make()->zooBudget(), 0u);
    }
    EXPECT_EQ(findClassicTask("lunar-lander"), nullptr);
}
