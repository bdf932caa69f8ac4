// Short learning checks, one per scene, sized for CI (seconds each). The full thesis-sized runs
// are in docs/experiments.md (verve-demo). Deterministic: a seed fixes every number below.
#include <gtest/gtest.h>

#include <algorithm>

#include "cart_pole_scene.hpp"
#include "npc_arena.hpp"
#include "pendulum_scene.hpp"
#include "tasks/driver.hpp"

using namespace verve;
using namespace verve::scenes;

namespace {

template <class Scene>
tasks::TaskFactory factory() {
    return [](std::uint64_t) { return std::make_unique<Scene>(); };
}

std::vector<double> perStep(const tasks::LearningCurve& c) {
    std::vector<double> out;
    for (std::size_t t = 0; t < c.trials(); ++t) out.push_back(c.reward[t] / c.steps[t]);
    return out;
}

}  // namespace

TEST(PendulumLearning, SwingsUpAndHoldsWithinSixtyTrials) {
    const auto curve = tasks::runExperiment(factory<PendulumScene>(), 4, 60, 11, {}, 2);
    const std::vector<double> r = perStep(curve);
    const double first = tasks::windowMean(r, 0, 10);
    const double last = tasks::windowMean(r, 50, 60);
    // Random torques keep it down most of the time; a good policy spends most of 20 s upright.
    EXPECT_LT(first, -0.2);
    EXPECT_GT(last, 0.5) << "mean reward per step in trials 51-60 (first 10: " << first << ")";
}

TEST(PendulumLearning, SameSeedSameLearningCurve) {
    const auto a = tasks::runExperiment(factory<PendulumScene>(), 2, 5, 3, {}, 2);
    const auto b = tasks::runExperiment(factory<PendulumScene>(), 2, 5, 3, {}, 1);
    EXPECT_EQ(a.reward, b.reward);
    EXPECT_EQ(a.steps, b.steps);
}

TEST(CartPoleLearning, BalanceTimeGrowsOverTheFirstTrials) {
    const auto curve = tasks::runExperiment(factory<CartPoleScene>(), 2, 250, 5, {}, 2);
    const double first = tasks::windowMean(curve.steps, 0, 20) * 0.05;
    const double last = tasks::windowMean(curve.steps, 230, 250) * 0.05;
    EXPECT_GT(last, 4 * first) << "seconds balanced: first 20 trials " << first << ", trials 231-250 " << last;
    EXPECT_GT(last, 2.0);
    EXPECT_EQ(curve.terminal[0], 1.0);  // early trials end by failing, as they must
}

TEST(NpcArenaLearning, MoreFoodLessHazardAfterAFewMinutes) {
    NpcArena arena(NpcArenaConfig{}, 1);
    ArenaStats early = arena.run(120.0);
    arena.run(360.0);
    ArenaStats late = arena.run(120.0);
    EXPECT_GT(late.foodPerNpcMinute(), 2.0 * early.foodPerNpcMinute())
        << "food per NPC-minute: minutes 1-2 " << early.foodPerNpcMinute() << ", minutes 9-10 "
        << late.foodPerNpcMinute();
    EXPECT_LT(late.hazardFraction(), early.hazardFraction())
        << "hazard share: minutes 1-2 " << early.hazardFraction() << ", minutes 9-10 " << late.hazardFraction();
}

TEST(NpcArena, SameSeedSameRun) {
    NpcArenaConfig config;
    config.npcs = 3;
    NpcArena a(config, 9), b(config, 9);
    const ArenaStats sa = a.run(30.0), sb = b.run(30.0);
    EXPECT_EQ(sa.foodEaten, sb.foodEaten);
    EXPECT_EQ(sa.hazardSeconds, sb.hazardSeconds);
    Observation oa, ob;
    for (std::size_t i = 0; i < a.npcCount(); ++i) {
        a.observe(i, oa);
        b.observe(i, ob);
        EXPECT_EQ(oa.continuous, ob.continuous);
        EXPECT_EQ(oa.discrete, ob.discrete);
    }
}

TEST(NpcArena, SensorsAreEgocentricAndInRange) {
    NpcArena arena(NpcArenaConfig{}, 2);
    Observation obs;
    for (int s = 0; s < 50; ++s) {
        arena.step();
        for (std::size_t i = 0; i < arena.npcCount(); ++i) {
            arena.observe(i, obs);
            ASSERT_EQ(obs.discrete.size(), 1u);
            ASSERT_EQ(obs.continuous.size(), 2u);
            EXPECT_GE(obs.discrete[0], NpcArena::Clear);
            EXPECT_LE(obs.discrete[0], NpcArena::Inside);
            EXPECT_GE(obs.continuous[0], -1.0f);
            EXPECT_LE(obs.continuous[0], 1.0f);
            EXPECT_GE(obs.continuous[1], -1.0f);
            EXPECT_LE(obs.continuous[1], 1.0f);
        }
    }
}

TEST(NpcArena, RejectsBadConfigurationsAndAgents) {
    NpcArenaConfig none;
    none.npcs = 0;
    EXPECT_THROW(NpcArena(none, 1), Error);
    AgentDescriptor wrong = NpcArena::defaultDescriptor();
    wrong.numActions = 5;
    EXPECT_THROW(NpcArena(NpcArenaConfig{}, 1, wrong), Error);
}

// One brain for 8 bodies against one brain each, on the same seeds (the same starts and food
// draws): shared experience must pay per NPC-minute. Whether a shared brain's run stops eating is
// chaotic (about half of them do, which ones changes with any change to learning), so 10 seeds.
// Measured, minutes 1-4, seeds 1-10: food per NPC-minute 1.18 with one brain each, 3.62 with one
// shared brain (3.1x; 1.07 vs 4.67 before the fine lattice, when seeds 1-3 alone read 1.03 vs 4.99
// and after it 1.36 vs 2.27); 30 seeds: 1.14 vs 3.52 (1.10 vs 3.51 before). The threshold asks for 2x.
TEST(NpcArenaLearning, OneSharedBrainLearnsFasterThanOneBrainEach) {
    constexpr std::uint64_t kSeeds = 10;
    double food[2] = {0.0, 0.0};
    for (int shared = 0; shared < 2; ++shared) {
        for (std::uint64_t seed = 1; seed <= kSeeds; ++seed) {
            NpcArenaConfig config;
            config.sharedBrain = shared == 1;
            NpcArena arena(config, seed);
            food[shared] += arena.run(240.0).foodPerNpcMinute() / kSeeds;
        }
    }
    EXPECT_GT(food[1], 2.0 * food[0]) << "food per NPC-minute over minutes 1-4, mean of seeds 1-10: one brain each "
                                      << food[0] << ", one shared brain " << food[1];
}

// The same shared brain stepped by one verve::Batch call per agent step, its bodies in the batch's
// phases (docs/crowds.md): shared experience must pay there too. Seeds 1-10, minutes 1-4 (verve-demo
// compare-brains --seeds 10 --minutes 4): 2.77 food per NPC-minute against 1.08 with one brain each
// (2.6x) and 4.67 with single updates of the shared brain. The arena's shared brain is chaotic
// (some seeds' NPCs stop eating for good, either way): over 30 seeds and 10 minutes the batch's
// 3.37 and single updates' 3.76 lie within their noise (standard deviations 2.6). Ten seeds, as
// three flip with any change to the arithmetic; the threshold asks for 2x one brain each, as above.
TEST(NpcArenaLearning, OneSharedBrainInABatchLearnsFasterThanOneBrainEach) {
    constexpr int kSeeds = 10;
    double food[2] = {0.0, 0.0};
    for (int shared = 0; shared < 2; ++shared) {
        for (std::uint64_t seed = 1; seed <= kSeeds; ++seed) {
            NpcArenaConfig config;
            config.sharedBrain = shared == 1;
            config.batch = true;
            NpcArena arena(config, seed);
            food[shared] += arena.run(240.0).foodPerNpcMinute() / kSeeds;
        }
    }
    EXPECT_GT(food[1], 2.0 * food[0]) << "food per NPC-minute over minutes 1-4, mean of seeds 1-10, in a batch: one brain each "
                                      << food[0] << ", one shared brain " << food[1];
}

TEST(NpcArena, SharedBrainBodiesShareWeights) {
    NpcArenaConfig config;
    config.npcs = 3;
    config.sharedBrain = true;
    NpcArena arena(config, 4);
    arena.run(20.0);
    for (std::size_t i = 1; i < arena.npcCount(); ++i) {
        EXPECT_EQ(arena.agent(i).rbfCount(), arena.agent(0).rbfCount());
        EXPECT_EQ(arena.agent(i).snapshot().weights, arena.agent(0).snapshot().weights);
    }
}

// Bootstrapping from a designer's AI (docs/teaching.md): the script chases the nearest food and
// ignores the hazard, as a designer's first AI would. NPCs that watch it for 2 minutes
// (demonstrated steps), then act on their own, are measured on minutes 6-10 against the script and
// against NPCs that learned from scratch for as long. Score: the game's reward per NPC-minute
// (+1 a food, -1 every 0.1 s in the hazard).
namespace {
struct BootstrapResult {
    double script = 0, scriptFood = 0, boot = 0, bootFood = 0, scratch = 0, scratchFood = 0;
    double worstMargin = 0;  // the bootstrapped NPCs' reward minus the script's, on the worst seed
};
double score(const ArenaStats& s) { return s.foodPerNpcMinute() - 600.0 * s.hazardFraction(); }
BootstrapResult bootstrapRuns(std::uint64_t seeds) {
    BootstrapResult r;
    r.worstMargin = 1e9;
    for (std::uint64_t seed = 1; seed <= seeds; ++seed) {
        NpcArena script(NpcArenaConfig{}, seed);
        script.setDriver(NpcArena::Driver::Script);
        const ArenaStats s = script.run(300.0);
        NpcArena boot(NpcArenaConfig{}, seed);
        boot.setDriver(NpcArena::Driver::ScriptDemonstrates);
        boot.run(120.0);
        boot.setDriver(NpcArena::Driver::Agents);
        boot.run(180.0);
        const ArenaStats b = boot.run(300.0);
        NpcArena scratch(NpcArenaConfig{}, seed);
        scratch.run(300.0);
        const ArenaStats a = scratch.run(300.0);
        const double n = static_cast<double>(seeds);
        r.script += score(s) / n;
        r.scriptFood += s.foodPerNpcMinute() / n;
        r.boot += score(b) / n;
        r.bootFood += b.foodPerNpcMinute() / n;
        r.scratch += score(a) / n;
        r.scratchFood += a.foodPerNpcMinute() / n;
        r.worstMargin = std::min(r.worstMargin, score(b) - score(s));
        std::printf("seed %llu: script %.2f (food %.2f), bootstrapped %.2f (food %.2f), scratch %.2f (food %.2f)\n",
                    static_cast<unsigned long long>(seed), score(s), s.foodPerNpcMinute(), score(b), b.foodPerNpcMinute(),
                    score(a), a.foodPerNpcMinute());
    }
    return r;
}
}  // namespace

// Measured (seeds 1-6): reward per NPC-minute, script -26.30, bootstrapped -9.24 (better on every
// seed, by 5.8 to 26.4), from scratch -11.51; food per NPC-minute 8.19, 7.43 and 2.60.
TEST(NpcArenaLearning, BootstrappedFromTheScriptNpcsBeatIt) {
    const BootstrapResult r = bootstrapRuns(6);
    EXPECT_GT(r.boot, r.script + 8.0);
    EXPECT_GT(r.bootFood, 2.0 * r.scratchFood);
    EXPECT_GT(r.worstMargin, 0.0);
    std::printf("reward per NPC-minute, minutes 6-10, seeds 1-6: script %.2f, bootstrapped %.2f, from scratch %.2f\n"
                "food per NPC-minute: script %.2f, bootstrapped %.2f, from scratch %.2f\n",
                r.script, r.boot, r.scratch, r.scriptFood, r.bootFood, r.scratchFood);
}
