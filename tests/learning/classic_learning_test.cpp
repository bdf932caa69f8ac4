// Gymnasium's classic control at the library's defaults (docs/experiments.md, "Classic control at
// defaults"): environment steps until the mean return of the last 100 episodes reaches the task's
// threshold, on seeds 1-10, beside the budget RL Baselines3 Zoo trains its tuned agent for. The
// task gives only sensors, actions, dt and rewards. Bars come from the measured steps.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <vector>

#include "tasks/classic/solve_run.hpp"

using namespace verve::tasks;

namespace {

// Steps to solve on seeds 1-10, an unsolved run counted as one step over the budget.
std::vector<std::uint64_t> stepsToSolve(const char* name, std::uint64_t budget) {
    std::vector<std::uint64_t> steps;
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
        auto task = findClassicTask(name)->make();
        const SolveRun run = trainOnClassicTask(*task, task->agentDescriptor(), budget, seed, true);
        steps.push_back(run.stepsToSolve > 0 ? run.stepsToSolve : budget + 1);
        std::printf("[ measured ] %s seed %llu: %s after %llu steps (last 100 mean %.1f)\n", name,
                    static_cast<unsigned long long>(seed), run.stepsToSolve > 0 ? "solved" : "not solved",
                    static_cast<unsigned long long>(steps.back()), run.lastMean());
    }
    return steps;
}

std::uint64_t median(std::vector<std::uint64_t> v) {
    std::sort(v.begin(), v.end());
    return (v[4] + v[5]) / 2;
}

std::uint64_t zooBudget(const char* name) { return findClassicTask(name)->make()->zooBudget(); }

}  // namespace

// Before the horizon followed the trials (tau_discount 1 s), no seed solved it in 450k steps.
TEST(ClassicControlLearning, AcrobotIsSolvedAtDefaultsInAThirdOfTheZooBudget) {
    const auto steps = stepsToSolve("acrobot-v1", 3 * zooBudget("acrobot-v1"));
    // Measured: worst 36,025, median 19,598; the Zoo's DQN trains for 150,000.
    EXPECT_LE(*std::max_element(steps.begin(), steps.end()), zooBudget("acrobot-v1") / 3);
    EXPECT_LE(median(steps), 25000u);
}

// Before the horizon followed the trials: no seed in 360k steps (the goal lay beyond the 1 s
// horizon); before updates learned as 0.1 s decisions: 10 of 10, median 145,565, worst 227,691.
TEST(ClassicControlLearning, MountainCarIsSolvedAtDefaultsOnNineSeedsInTen) {
    const auto steps = stepsToSolve("mountain-car-v0", 3 * zooBudget("mountain-car-v0"));
    // Measured: 9 of 10 within 360k (seed 3 settles at -130), median 77,459; the Zoo's DQN trains
    // for 120,000.
    EXPECT_GE(std::count_if(steps.begin(), steps.end(), [](std::uint64_t s) { return s <= 3 * zooBudget("mountain-car-v0"); }), 9);
    EXPECT_LE(median(steps), 100000u);
}

// Before updates learned as 0.1 s decisions (core/decision_rate.hpp): no seed in 300k steps (the
// last 100 episodes averaged 343-385).
TEST(ClassicControlLearning, CartPoleIsSolvedAtDefaultsOnEverySeed) {
    const auto steps = stepsToSolve("cart-pole-v1", 3 * zooBudget("cart-pole-v1"));
    // Measured: worst 129,219, median 103,448; the Zoo's PPO trains for 100,000.
    EXPECT_LE(*std::max_element(steps.begin(), steps.end()), 200000u);
    EXPECT_LE(median(steps), 125000u);
}

// Known gaps (not gating; docs/experiments.md): the goal, every seed within the Zoo's budget.
TEST(KnownGapClassicControlLearning, MountainCarWithinTheZooBudgetOnEverySeed) {
    const auto steps = stepsToSolve("mountain-car-v0", zooBudget("mountain-car-v0"));
    EXPECT_LE(*std::max_element(steps.begin(), steps.end()), zooBudget("mountain-car-v0"));  // 2 of 10 over
}

// Every seed within 3x the Zoo's budget, as before the 0.1 s decisions (seed 3 now settles at -130
// for at least 1M steps: its actor's habit is too firm for the small TD errors left).
TEST(KnownGapClassicControlLearning, MountainCarOnEverySeed) {
    const auto steps = stepsToSolve("mountain-car-v0", 3 * zooBudget("mountain-car-v0"));
    EXPECT_LE(*std::max_element(steps.begin(), steps.end()), 300000u);
}

// Measured: median 103,448, 2 of 10 within 100k.
TEST(KnownGapClassicControlLearning, CartPoleWithinTheZooBudgetOnEverySeed) {
    const auto steps = stepsToSolve("cart-pole-v1", zooBudget("cart-pole-v1"));
    EXPECT_LE(*std::max_element(steps.begin(), steps.end()), zooBudget("cart-pole-v1"));
}

// At defaults 2 of 10 seeds reach -200 within 300k steps (none before the 0.1 s decisions); resolution
// 16 with tau_value 0.01 solves 9 of 10 (median 55k).
TEST(KnownGapClassicControlLearning, PendulumWithinTheZooBudgetOnEverySeed) {
    const auto steps = stepsToSolve("pendulum-v1", zooBudget("pendulum-v1"));
    EXPECT_LE(*std::max_element(steps.begin(), steps.end()), zooBudget("pendulum-v1"));
}
