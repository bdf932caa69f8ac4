// The raycast NPC scene (samples/scenes/ray_npc.hpp): determinism, a fair layout for every seed,
// rays that read Bullet's geometry, the scripted baseline, and the learning bar it sets.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "ray_npc.hpp"
#include "ray_npc_steering.hpp"

using namespace verve;
using namespace verve::scenes;

TEST(RayNpc, SameSeedSameRun) {
    RayNpcScene a(RayNpcConfig{}, 9), b(RayNpcConfig{}, 9);
    const RayNpcStats sa = a.run(30.0), sb = b.run(30.0);
    EXPECT_EQ(sa.targets, sb.targets);
    EXPECT_EQ(sa.collisions, sb.collisions);
    EXPECT_EQ(sa.hazardSeconds, sb.hazardSeconds);
    EXPECT_EQ(sa.reward, sb.reward);
    Observation oa, ob;
    for (std::size_t i = 0; i < a.npcCount(); ++i) {
        a.observe(i, oa);
        b.observe(i, ob);
        EXPECT_EQ(oa.continuous, ob.continuous);
        EXPECT_EQ(oa.discrete, ob.discrete);
        EXPECT_EQ(a.position(i).x, b.position(i).x);
        EXPECT_EQ(a.position(i).z, b.position(i).z);
    }
    RayNpcScene c(RayNpcConfig{}, 10);
    EXPECT_NE(c.layout().hazardCentre().x, a.layout().hazardCentre().x) << "another seed, another arena";
}

// Every seed's arena leaves passages between boxes, and nothing starts or appears inside a box, a
// wall or the hazard.
TEST(RayNpc, LayoutIsFairForEverySeed) {
    for (std::uint64_t seed = 1; seed <= 40; ++seed) {
        RayNpcScene scene(RayNpcConfig{}, seed);
        const RayNpcLayout& layout = scene.layout();
        const auto& boxes = layout.obstacles();
        ASSERT_EQ(boxes.size(), scene.config().layout.obstacles);
        for (std::size_t i = 0; i < boxes.size(); ++i) {
            for (std::size_t j = i + 1; j < boxes.size(); ++j) {
                const double gap = std::max(std::abs(boxes[i].centre.x - boxes[j].centre.x),
                                            std::abs(boxes[i].centre.z - boxes[j].centre.z)) -
                                   boxes[i].half - boxes[j].half;
                EXPECT_GE(gap, scene.config().layout.passage) << "seed " << seed;
            }
            EXPECT_GE(layout.halfSize() - std::max(std::abs(boxes[i].centre.x), std::abs(boxes[i].centre.z)) -
                          boxes[i].half,
                      scene.config().layout.passage - 1e-9)
                << "seed " << seed;
        }
        for (std::size_t n = 0; n < scene.npcCount(); ++n) {
            EXPECT_GE(layout.clearance(scene.position(n)), 0.3) << "seed " << seed << ": NPC " << n << " starts in a box";
            EXPECT_FALSE(layout.inHazard(scene.position(n))) << "seed " << seed;
            EXPECT_GE(layout.clearance(scene.target(n)), 0.5) << "seed " << seed;
            EXPECT_FALSE(layout.inHazard(scene.target(n))) << "seed " << seed;
        }
    }
}

TEST(RayNpc, SensorsAreEgocentricAndInRange) {
    RayNpcScene scene(RayNpcConfig{}, 2);
    Observation obs;
    for (int s = 0; s < 100; ++s) {
        scene.step();
        for (std::size_t i = 0; i < scene.npcCount(); ++i) {
            scene.observe(i, obs);
            ASSERT_EQ(obs.discrete.size(), 1u);
            ASSERT_EQ(obs.continuous.size(), 12u);
            EXPECT_GE(obs.discrete[0], RayNpcScene::Clear);
            EXPECT_LE(obs.discrete[0], RayNpcScene::Inside);
            EXPECT_EQ(obs.discrete[0] == RayNpcScene::Inside, scene.layout().inHazard(scene.position(i)));
            for (float c : obs.continuous) {
                EXPECT_GE(c, -1.0f);
                EXPECT_LE(c, 1.0f);
            }
            // Bearing: the target's direction is the heading turned by the bearing (left positive).
            const Vec2 p = scene.position(i), f = scene.heading(i), t = scene.target(i);
            const double b = obs.continuous[8] * 3.14159265358979;
            const Vec2 d{f.x * std::cos(b) - f.z * std::sin(b), f.z * std::cos(b) + f.x * std::sin(b)};
            const double len = std::hypot(t.x - p.x, t.z - p.z);
            EXPECT_NEAR(d.x, (t.x - p.x) / len, 1e-4);
            EXPECT_NEAR(d.z, (t.z - p.z) / len, 1e-4);
        }
    }
}

// With no boxes, every ray reads the distance from the NPC's surface to the wall it points at
// (or other NPCs: one NPC here), as Bullet's ray test finds it.
TEST(RayNpc, RaysReadTheWallsDistance) {
    RayNpcConfig config;
    config.npcs = 1;
    config.layout.obstacles = 0;
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
        RayNpcScene scene(config, seed);
        scene.run(1.0 + static_cast<double>(seed));  // somewhere, facing somewhere, after some agent steps
        Observation obs;
        scene.observe(0, obs);
        const Vec2 p = scene.position(0), f = scene.heading(0);
        const double h = scene.layout().halfSize();
        for (std::uint32_t i = 0; i < config.rays; ++i) {
            const double a = RayNpcScene::rayAngle(config, i);
            const Vec2 d{f.x * std::cos(a) - f.z * std::sin(a), f.z * std::cos(a) + f.x * std::sin(a)};
            double wall = 1e9;
            if (d.x > 1e-9) wall = std::min(wall, (h - p.x) / d.x);
            if (d.x < -1e-9) wall = std::min(wall, (-h - p.x) / d.x);
            if (d.z > 1e-9) wall = std::min(wall, (h - p.z) / d.z);
            if (d.z < -1e-9) wall = std::min(wall, (-h - p.z) / d.z);
            const double expected = std::clamp(wall - 0.3, 0.0, static_cast<double>(config.rayRange));
            EXPECT_NEAR((obs.continuous[i] + 1.0) / 2.0 * config.rayRange, expected, 2e-3)
                << "seed " << seed << ", ray " << i;
        }
    }
}

TEST(RayNpc, RejectsBadConfigurationsAndAgents) {
    RayNpcConfig few;
    few.rays = 7;
    EXPECT_THROW(RayNpcScene(few, 1), Error);
    RayNpcConfig none;
    none.npcs = 0;
    EXPECT_THROW(RayNpcScene(none, 1), Error);
    AgentDescriptor wrong = RayNpcScene::defaultDescriptor();
    wrong.numActions = 3;
    EXPECT_THROW(RayNpcScene(RayNpcConfig{}, 1, wrong), Error);
    RayNpcConfig more;
    more.rays = 10;
    EXPECT_THROW(RayNpcScene(more, 1, RayNpcScene::defaultDescriptor()), Error) << "10 rays want 14 sensors";
    for (float progress : {-1.0f, std::nanf(""), INFINITY}) {
        RayNpcConfig bad;
        bad.progressReward = progress;
        EXPECT_THROW(RayNpcScene(bad, 1), Error) << progress;
    }
}

// The progress reward pays the metres an NPC closed on its target in the step, and nothing on the
// step a target is reached beyond that walk (the new target starts from where the NPC stands).
// The script drives, so the reward changes nothing of what happens.
TEST(RayNpc, ProgressRewardPaysTheMetresClosedOnTheTarget) {
    RayNpcConfig plain, shaped;
    plain.npcs = shaped.npcs = 1;
    shaped.progressReward = 2.0f;
    RayNpcScene a(plain, 4), b(shaped, 4);
    a.setDriver(RayNpcScene::Driver::Script);
    b.setDriver(RayNpcScene::Driver::Script);
    int checked = 0, reached = 0;
    for (int step = 0; step < 600; ++step) {
        const Vec2 target = b.target(0);  // the one the step pays for, even if it is reached
        const double before = distance(b.position(0), target);
        const RayNpcStats sa = a.run(plain.agentStep), sb = b.run(shaped.agentStep);
        ASSERT_EQ(sa.targets, sb.targets);
        const double closed = before - distance(b.position(0), target);
        if (sb.targets > 0) ++reached;
        if (std::abs(sb.reward) >= 1.0) continue;  // clamped to [-1, 1]
        EXPECT_NEAR(sb.reward - sa.reward, 2.0 * closed, 1e-5) << "step " << step;
        ++checked;
    }
    EXPECT_GT(checked, 500);
    EXPECT_GT(reached, 0) << "the run should reach a target";
}

// The agents' descriptor is the library's defaults with the scene's sensors and actions only.
TEST(RayNpc, AgentsLearnAtLibraryDefaults) {
    const AgentDescriptor d = RayNpcScene::defaultDescriptor();
    const AgentDescriptor defaults;
    EXPECT_EQ(d.resolution, defaults.resolution);
    EXPECT_EQ(d.tauValue, defaults.tauValue);
    EXPECT_EQ(d.tauDiscount, defaults.tauDiscount);
    EXPECT_EQ(d.tauEligibility, defaults.tauEligibility);
    EXPECT_EQ(d.policyMultiplier, defaults.policyMultiplier);
    EXPECT_EQ(d.adaptation, defaults.adaptation);
    EXPECT_EQ(d.continuousSensors.size(), 12u);
    EXPECT_TRUE(d.continuousSensors[8].circular);
    EXPECT_EQ(d.numActions, 5u);
}

// The baseline works: measured on seeds 1-5, minutes 1-5, 14.0-16.5 targets per NPC-minute, 1-7.7%
// of the time in the hazard, 5-10 collisions per NPC-minute (agents acting at random: about 0.4
// targets and 8 collisions).
TEST(RayNpc, ScriptedSteeringReachesTargets) {
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
        RayNpcScene scene(RayNpcConfig{}, seed);
        scene.setDriver(RayNpcScene::Driver::Script);
        const RayNpcStats s = scene.run(300.0);
        EXPECT_GT(s.targetsPerNpcMinute(), 12.0) << "seed " << seed;
        EXPECT_LT(s.hazardFraction(), 0.08) << "seed " << seed;
        EXPECT_LT(s.collisionsPerNpcMinute(), 12.0) << "seed " << seed;
        EXPECT_GT(s.collisions, 0u) << "seed " << seed << ": contacts are counted";
    }
}

// What the agents do learn at the library's defaults within 20 simulated minutes, on every seed: to
// keep off walls and out of the hazard. Measured on seeds 1-5 (with a rate per sensor group):
// reward per NPC-minute -38.5 to -47.3 in minutes 1-5 (acting near random), -4.3 to -8.6 in minutes
// 16-20 (a gain of 30-43; one rate for all: 26-42), with 0-0.5% of the time in the hazard late (the
// script 3.8-4.8%); fetching is the known gap below.
TEST(RayNpcLearning, AgentsAtDefaultsLearnToKeepOffWallsAndOutOfTheHazard) {
    constexpr int kMinutes = 20, kWindow = 5;
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
        RayNpcScene agents(RayNpcConfig{}, seed);
        const RayNpcStats first = agents.run(60.0 * kWindow);
        agents.run(60.0 * (kMinutes - 2 * kWindow));
        const RayNpcStats last = agents.run(60.0 * kWindow);
        std::printf("[ measured ] seed %llu: reward per NPC-minute, minutes 1-%d %.2f, minutes %d-%d %.2f (hazard %.1f%% "
                    "-> %.1f%%, collisions %.2f -> %.2f)\n",
                    static_cast<unsigned long long>(seed), kWindow, first.rewardPerNpcMinute(), kMinutes - kWindow + 1,
                    kMinutes, last.rewardPerNpcMinute(), 100 * first.hazardFraction(), 100 * last.hazardFraction(),
                    first.collisionsPerNpcMinute(), last.collisionsPerNpcMinute());
        EXPECT_GT(last.rewardPerNpcMinute(), first.rewardPerNpcMinute() + 20.0) << "seed " << seed;
        EXPECT_LT(last.hazardFraction(), 0.01) << "seed " << seed;
    }
}

// With a reward for progress (2 per metre closed on the target: docs/scenes.md, "A reward for
// progress"), the same agents at the library's defaults learn to fetch: at least half the script's
// targets per NPC-minute in minutes 16-20, on every seed. Measured on seeds 1-5: 10.30-12.25 targets
// against the script's 14.0-15.4 (0.73-0.80 of it; seeds 6-10: 0.74-0.90), from 2.4-4.7 in minutes
// 1-5; reward 89-104 against the script's 107-132 per NPC-minute, which the agents do not yet beat.
TEST(RayNpcLearning, WithAProgressRewardAgentsAtDefaultsFetchHalfTheScriptsTargetsWithinTwentyMinutes) {
    constexpr int kMinutes = 20, kWindow = 5;
    RayNpcConfig config;
    config.progressReward = 2.0f;
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
        RayNpcScene script(config, seed);
        script.setDriver(RayNpcScene::Driver::Script);
        const RayNpcStats scripted = script.run(60.0 * kMinutes);
        RayNpcScene agents(config, seed);
        const RayNpcStats first = agents.run(60.0 * kWindow);
        agents.run(60.0 * (kMinutes - 2 * kWindow));
        const RayNpcStats last = agents.run(60.0 * kWindow);
        std::printf("[ measured ] seed %llu: targets per NPC-minute, script %.2f; agents minutes 1-%d %.2f, minutes "
                    "%d-%d %.2f (reward %.2f against the script's %.2f, hazard %.1f%%)\n",
                    static_cast<unsigned long long>(seed), scripted.targetsPerNpcMinute(), kWindow,
                    first.targetsPerNpcMinute(), kMinutes - kWindow + 1, kMinutes, last.targetsPerNpcMinute(),
                    last.rewardPerNpcMinute(), scripted.rewardPerNpcMinute(), 100 * last.hazardFraction());
        EXPECT_GT(last.targetsPerNpcMinute(), 0.5 * scripted.targetsPerNpcMinute()) << "seed " << seed;
    }
}

// Known gap (not gating; tests/CMakeLists.txt): the bar, NPCs learning at the library's
// defaults earn more reward per NPC-minute than the designer's script within 20 simulated minutes,
// on every seed, and by fetching: at least half the script's targets (keeping off walls and out of
// the hazard alone beats the script's reward on seeds 1, 3, 4 and 5). Measured with sensor groups:
// minutes 16-20 -3.7 to -7.8 against the script's -7.3 to -28.3 (seed 2: -7.83 against -7.61), but
// 0.05-1.1 targets per NPC-minute against the script's 14-15; with a rate per group -4.3 to -8.6
// (seed 2 short of the script's, -8.63 against -7.61), 0.35-1.4 targets. Before them (one RBF lattice over the
// 12 continuous sensors) the agents stayed near their random-policy level, about -45, through
// minute 60 (docs/scenes.md, "ray-npc").
TEST(KnownGapRayNpcLearning, AgentsAtDefaultsBeatTheScriptWithinTwentyMinutesOnEverySeed) {
    constexpr int kMinutes = 20, kWindow = 5;
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
        RayNpcScene script(RayNpcConfig{}, seed);
        script.setDriver(RayNpcScene::Driver::Script);
        const RayNpcStats scripted = script.run(60.0 * kMinutes);
        const double scriptReward = scripted.rewardPerNpcMinute(), scriptTargets = scripted.targetsPerNpcMinute();
        RayNpcScene agents(RayNpcConfig{}, seed);
        const double first = agents.run(60.0 * kWindow).rewardPerNpcMinute();
        agents.run(60.0 * (kMinutes - 2 * kWindow));
        const RayNpcStats last = agents.run(60.0 * kWindow);
        std::printf("[ measured ] seed %llu: reward per NPC-minute, script %.2f; agents minutes 1-%d %.2f, "
                    "minutes %d-%d %.2f (targets %.2f, hazard %.1f%%, collisions %.2f)\n",
                    static_cast<unsigned long long>(seed), scriptReward, kWindow, first, kMinutes - kWindow + 1,
                    kMinutes, last.rewardPerNpcMinute(), last.targetsPerNpcMinute(), 100 * last.hazardFraction(),
                    last.collisionsPerNpcMinute());
        EXPECT_GT(last.rewardPerNpcMinute(), scriptReward) << "seed " << seed;
        // ... by fetching, not by standing still: at least half the script's targets.
        EXPECT_GT(last.targetsPerNpcMinute(), 0.5 * scriptTargets) << "seed " << seed;
    }
}
