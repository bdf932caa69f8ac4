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
// horizon); before updates learned as 0.1 s decisions: 10 of 10, median 145,565, worst 227,691;
// before habits were bounded (core/habit_bound.hpp): 9 of 10 within 360k (seed 3 settled at -130
// for at least 1M steps, its habit too firm for the small TD errors left), median 77,459.
TEST(ClassicControlLearning, MountainCarIsSolvedAtDefaultsOnEverySeedWithinTheZooBudget) {
    const auto steps = stepsToSolve("mountain-car-v0", zooBudget("mountain-car-v0"));
    // Measured: worst 64,344, median 45,613 (worst 113,895, median 69,703 before the fine lattice,
    // core/fine_lattice.hpp); the Zoo's DQN trains for 120,000.
    EXPECT_LE(*std::max_element(steps.begin(), steps.end()), zooBudget("mountain-car-v0"));
    EXPECT_LE(median(steps), 80000u);
}

// Before updates learned as 0.1 s decisions (core/decision_rate.hpp): no seed in 300k steps (the
// last 100 episodes averaged 343-385); before habits were bounded: worst 129,219, median 103,448.
TEST(ClassicControlLearning, CartPoleIsSolvedAtDefaultsOnEverySeedWithinTheZooBudget) {
    const auto steps = stepsToSolve("cart-pole-v1", zooBudget("cart-pole-v1"));
    // Measured: worst 97,369, median 76,170; the Zoo's PPO trains for 100,000.
    EXPECT_LE(*std::max_element(steps.begin(), steps.end()), zooBudget("cart-pole-v1"));
    EXPECT_LE(median(steps), 90000u);
}

// Before the fine lattice (core/fine_lattice.hpp) 5 of 10 seeds reached -200 within 300k steps
// (since the horizon followed the rewards; none before that), the balance near the top too fine
// for resolution 10's RBFs; resolution 16 with tau_value 0.01 solved 9 of 10 (median 55k).
TEST(ClassicControlLearning, PendulumIsSolvedAtDefaultsOnEverySeedWithinTheZooBudget) {
    const auto steps = stepsToSolve("pendulum-v1", zooBudget("pendulum-v1"));
    // Measured: worst 75,400, median 49,200; the Zoo's PPO (continuous torque) trains for 100,000.
    EXPECT_LE(*std::max_element(steps.begin(), steps.end()), zooBudget("pendulum-v1"));
    EXPECT_LE(median(steps), 60000u);
}
