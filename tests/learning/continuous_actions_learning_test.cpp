// Continuous actions (docs/experiments.md, "Continuous actions"): a car that steers and throttles
// to targets, at the library's defaults, beside the same car driven by 3 x 3 action branches and a
// scripted driver; Pendulum-v1 with Gymnasium's continuous torque. Thresholds come from
// measurements over these seeds (the defaults table's: base seed 1, 20 runs).
#include <gtest/gtest.h>

#include <cstdio>

#include "learning_window.hpp"
#include "tasks/classic/solve_run.hpp"
#include "tasks/steering_car.hpp"
#include "tasks/task_rng.hpp"

using namespace verve::tasks;
using namespace verve::tasks::testing;

namespace {

constexpr std::uint32_t kRuns = 20, kTrials = 301, kFirst = 271;

// The scripted driver's steps per trial over the learners' trials (their seeds: runExperiment's).
double scriptedSteps() {
    SteeringCar car(SteeringCar::Controls::Continuous);
    double steps = 0.0;
    for (std::uint32_t t = 0; t < 300; ++t) {
        car.beginTrial(mixSeed(1, t));
        std::uint32_t n = 0;
        while (n < SteeringCar::kMaxSteps) {
            double steer = 0, throttle = 0;
            car.scriptedControls(steer, throttle);
            ++n;
            if (car.drive(steer, throttle).terminal) break;
        }
        steps += n;
    }
    return steps / 300.0;
}

}  // namespace

TEST(ContinuousActionsLearning, TheCarLearnsToReachItsTargetsSteeringAndThrottlingContinuously) {
    const Window continuous = lateAtDefaults("steering-car", kRuns, kTrials, kFirst);
    const Window branches = lateAtDefaults("steering-car-branches", kRuns, kTrials, kFirst);
    print("continuous steering and throttle at defaults", continuous);
    print("3 x 3 branches at defaults", branches);
    // Measured: 69.8 steps late, the branches 76.2. Before the pairs beside the car's lattice of 3
    // sensors (core/pairs_beside.hpp): 82.8 (99.8% of targets reached) and 96.5; before the horizon
    // followed the rewards (core/reward_stretch.hpp): 182 and 184, with a 15 s horizon under which
    // driving slowly earned the same progress.
    EXPECT_LE(continuous.steps, 80.0);
    EXPECT_GE(continuous.success, 0.98);
}

// A known gap until the pairs beside the lattice (core/pairs_beside.hpp): the car stayed above the
// scripted driver's 73 steps (82.8).
TEST(ContinuousActionsLearning, TheCarBeatsTheScriptedDriver) {
    const Window continuous = lateAtDefaults("steering-car", kRuns, kTrials, kFirst);
    const double scripted = scriptedSteps();
    std::printf("[ measured ] scripted driver: %.1f steps per trial\n", scripted);
    EXPECT_LE(continuous.steps, scripted);
}

namespace {

// Seeds solved within `budget` steps on seeds 1..seeds, with `resolution` (0: the default).
int pendulumSolved(std::uint64_t seeds, std::uint64_t budget, std::uint32_t resolution) {
    int solved = 0;
    for (std::uint64_t seed = 1; seed <= seeds; ++seed) {
        auto task = findClassicTask("pendulum-v1-continuous")->make();
        verve::AgentDescriptor d = task->agentDescriptor();
        if (resolution != 0) d.resolution = resolution;
        const SolveRun run = trainOnClassicTask(*task, d, budget, seed, true);
        std::printf("[ measured ] pendulum-v1-continuous seed %llu: %s (last 100 mean %.1f)\n",
                    static_cast<unsigned long long>(seed), run.stepsToSolve > 0 ? "solved" : "not solved", run.lastMean());
        solved += run.stepsToSolve > 0;
    }
    return solved;
}

}  // namespace

// Gymnasium's continuous torque swung up and held at the defaults on every seed within the Zoo's
// PPO budget. Before the horizon followed the rewards: 2 of 10 within 300k (its 10 s trials had set
// a 15 s horizon for a reward that says on every step how high the pendulum is); before the fine
// lattice (core/fine_lattice.hpp) 10 of 10 within 300k (median 142k), 3 of 10 within 100k.
TEST(ContinuousActionsLearning, PendulumWithContinuousTorqueAtDefaultsOnEverySeedWithinTheZooBudget) {
    // Measured: 10 of 10 within 100k steps, median 66,600, worst 96,200.
    EXPECT_EQ(pendulumSolved(10, 100000, 0), 10);
}

// With the setting the discrete torque was documented with: within the Zoo's 100k steps.
TEST(ContinuousActionsLearning, PendulumWithContinuousTorqueAtResolution16) {
    // Measured: 11 of 12 (12 of 16 before the horizon followed the rewards).
    EXPECT_GE(pendulumSolved(12, 100000, 16), 10);
}

