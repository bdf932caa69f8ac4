// Physics sanity and determinism of the Bullet scenes, with no agent involved.
#include <gtest/gtest.h>

#include <cmath>

#include "cart_pole_scene.hpp"
#include "pendulum_scene.hpp"
#include "scene_util.hpp"
#include "verve/error.hpp"

using namespace verve;
using namespace verve::scenes;

TEST(PendulumPhysics, FreePendulumConservesEnergy) {
    PendulumScene scene;
    scene.setState(radians(90.0), 0.0);  // horizontal, at rest
    const double start = scene.energy();
    const double swing = 1.0 * 9.81 * 0.5;  // m g L/2: energy exchanged in each swing (J)
    double worst = 0.0, highest = 0.0;
    for (int i = 0; i < 200; ++i) {  // 20 s of free swinging
        scene.act(PendulumScene::NoTorque);
        worst = std::max(worst, std::abs(scene.energy() - start));
        highest = std::max(highest, std::abs(scene.angle()));
    }
    // Semi-implicit Euler with a hinge at 0.01 s: bounded wobble within a swing, no lasting drift.
    EXPECT_LT(worst, 0.03 * swing) << "energy wobbled by " << worst << " J";
    EXPECT_LT(std::abs(scene.energy() - start), 0.015 * swing) << "energy drifted";
    EXPECT_GT(highest, radians(170.0));  // it really swings down through the bottom
}

TEST(PendulumPhysics, HingeKeepsThePivotFixedAndAngleConsistent) {
    PendulumScene scene;
    scene.setState(radians(30.0), 2.0);
    EXPECT_NEAR(scene.angle(), radians(30.0), 1e-5);
    EXPECT_NEAR(scene.angularVelocity(), 2.0, 1e-5);
    // Gravity pulls a rod leaning toward +x further toward +x.
    scene.setState(radians(10.0), 0.0);
    scene.act(PendulumScene::NoTorque);
    EXPECT_GT(scene.angle(), radians(10.0));
    EXPECT_GT(scene.angularVelocity(), 0.0);
}

TEST(PendulumPhysics, TorqueAloneCannotLiftItButSwingingCan) {
    // Underactuated: 2 N·m against up to 4.9 N·m of gravity torque.
    PendulumScene scene;
    scene.setState(kPi, 0.0);  // hanging down, at rest
    for (int i = 0; i < 50; ++i) scene.act(PendulumScene::TorquePositive);
    EXPECT_GT(std::abs(scene.angle()), radians(90.0)) << "pushing one way never gets it past level";
}

TEST(PendulumScene, SameSeedSameTrajectory) {
    PendulumScene a, b;
    a.beginTrial(42);
    b.beginTrial(42);
    Observation oa, ob;
    for (std::uint32_t i = 0; i < 200; ++i) {
        const auto ra = a.act(i % 3);
        const auto rb = b.act(i % 3);
        a.observe(oa);
        b.observe(ob);
        ASSERT_EQ(oa.continuous, ob.continuous) << "step " << i;
        ASSERT_EQ(ra.reward, rb.reward);
    }
    PendulumScene c;
    c.beginTrial(43);
    c.observe(ob);
    a.beginTrial(42);
    a.observe(oa);
    EXPECT_NE(oa.continuous, ob.continuous);
}

TEST(PendulumScene, SensorsAndRewardFollowTheThesis) {
    PendulumScene scene;
    const AgentDescriptor d = scene.agentDescriptor();
    ASSERT_EQ(d.continuousSensors.size(), 2u);
    EXPECT_TRUE(d.continuousSensors[0].circular);
    EXPECT_FALSE(d.continuousSensors[1].circular);
    EXPECT_EQ(d.numActions, 3u);
    EXPECT_EQ(scene.maxStepsPerTrial(), 200u);
    scene.setState(radians(-90.0), radians(250.0));
    Observation obs;
    scene.observe(obs);
    EXPECT_NEAR(obs.continuous[0], -0.5f, 1e-5f);
    EXPECT_NEAR(obs.continuous[1], 0.5f, 1e-5f);
    scene.setState(radians(40.0), 0.0);
    EXPECT_EQ(scene.act(PendulumScene::TorqueNegative).reward, 1.0f);
    scene.setState(radians(100.0), 0.0);
    EXPECT_EQ(scene.act(PendulumScene::NoTorque).reward, -1.0f);
}

TEST(PendulumScene, BadActionIsRejectedAndChangesNothing) {
    PendulumScene scene;
    scene.setState(0.5, 0.0);
    EXPECT_THROW(scene.act(3), verve::Error);
    EXPECT_NEAR(scene.angle(), 0.5, 1e-6);
}

TEST(CartPolePhysics, UnpushedPoleFallsAndFails) {
    CartPoleScene scene;
    scene.setState(0, 0, radians(2.0), 0);
    int steps = 0;
    bool terminal = false;
    while (!terminal && steps < 200) {
        terminal = scene.act(CartPoleScene::NoPush).terminal;
        ++steps;
    }
    EXPECT_TRUE(terminal);
    EXPECT_GT(scene.angle(), radians(12.0));  // fell the way it leaned
    EXPECT_LT(scene.position(), 0.0);         // the cart recoils the other way
    EXPECT_GT(steps, 5);
}

TEST(CartPolePhysics, PushMovesCartAsNewtonSays) {
    // With the pole held upright for a moment, 10 N on 1.1 kg gives about 9.1 m/s^2.
    CartPoleScene scene;
    scene.setState(0, 0, 0, 0);
    scene.act(CartPoleScene::PushPositive);  // 0.05 s
    EXPECT_NEAR(scene.velocity(), 10.0 / 1.1 * 0.05, 0.1);
    EXPECT_LT(scene.angle(), 0.0);  // the pole lags behind the accelerating cart
}

TEST(CartPolePhysics, TrackIsFrictionlessAndStraight) {
    CartPoleScene scene;
    scene.setState(0, 1.0, 0, 0);  // coasting, pole upright and still
    for (int i = 0; i < 10; ++i) scene.act(CartPoleScene::NoPush);
    EXPECT_NEAR(scene.velocity(), 1.0, 0.02);
    EXPECT_NEAR(scene.position(), 0.5, 0.02);
}

TEST(CartPoleScene, SameSeedSameTrajectory) {
    CartPoleScene a, b;
    a.beginTrial(7);
    b.beginTrial(7);
    Observation oa, ob;
    for (std::uint32_t i = 0; i < 100; ++i) {
        const auto ra = a.act((i / 3) % 3);
        const auto rb = b.act((i / 3) % 3);
        a.observe(oa);
        b.observe(ob);
        ASSERT_EQ(oa.continuous, ob.continuous) << "step " << i;
        ASSERT_EQ(ra.terminal, rb.terminal);
        if (ra.terminal) break;
    }
}

TEST(CartPoleScene, SensorsFollowTheThesis) {
    CartPoleScene scene;
    EXPECT_EQ(scene.agentDescriptor().continuousSensors.size(), 4u);
    EXPECT_EQ(scene.maxStepsPerTrial(), 36000u);
    scene.setState(1.2, -1.2, radians(6.0), radians(-50.0));
    Observation obs;
    scene.observe(obs);
    ASSERT_EQ(obs.continuous.size(), 4u);
    EXPECT_NEAR(obs.continuous[0], 0.5f, 1e-5f);
    EXPECT_NEAR(obs.continuous[1], -0.5f, 1e-5f);
    EXPECT_NEAR(obs.continuous[2], 0.5f, 1e-5f);
    EXPECT_NEAR(obs.continuous[3], -0.5f, 1e-5f);
    EXPECT_THROW(scene.act(7), verve::Error);
}
