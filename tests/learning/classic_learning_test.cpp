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

// Before: no seed in 360k steps (the goal lay beyond the 1 s horizon).
TEST(ClassicControlLearning, MountainCarIsSolvedAtDefaultsOnEverySeed) {
    const auto steps = stepsToSolve("mountain-car-v0", 3 * zooBudget("mountain-car-v0"));
    // Measured: worst 227,691, median 145,565; the Zoo's DQN trains for 120,000.
    EXPECT_LE(*std::max_element(steps.begin(), steps.end()), 300000u);
    EXPECT_LE(median(steps), 160000u);
}

// Known gaps (not gating; docs/experiments.md): the goal, every seed within the Zoo's budget.
TEST(KnownGapClassicControlLearning, MountainCarWithinTheZooBudgetOnEverySeed) {
    const auto steps = stepsToSolve("mountain-car-v0", zooBudget("mountain-car-v0"));
    EXPECT_LE(*std::max_element(steps.begin(), steps.end()), zooBudget("mountain-car-v0"));  // 5 of 10 over
}

// At defaults the last 100 episodes average 343-385 after 300k steps; tau_value 0.01 solves every
// seed (median 196k), but as a default it costs the thesis tasks (the continuous maze #2 1875 steps).
TEST(KnownGapClassicControlLearning, CartPoleWithinTheZooBudgetOnEverySeed) {
    const auto steps = stepsToSolve("cart-pole-v1", zooBudget("cart-pole-v1"));
    EXPECT_LE(*std::max_element(steps.begin(), steps.end()), zooBudget("cart-pole-v1"));
}

// At defaults no seed gets near -200 (about -1500: the 5-per-dimension lattice is too coarse to
// hold the pendulum up); resolution 16 with tau_value 0.01 solves 9 of 10 (median 55k).
TEST(KnownGapClassicControlLearning, PendulumWithinTheZooBudgetOnEverySeed) {
    const auto steps = stepsToSolve("pendulum-v1", zooBudget("pendulum-v1"));
    EXPECT_LE(*std::max_element(steps.begin(), steps.end()), zooBudget("pendulum-v1"));
}
