// Hot plates (thesis figs. 18, 20, 22, 26) against the original library. Its own test programs
// (2008 source) start a trial on a uniformly random cell and cut it off after 200 steps, as ours do
// (hot_plate.hpp). A final number depends on how far the sampled starts happened to be from safety,
// so we compare the *excess* steps over the optimum of the very same trials, with the original's
// excess measured the same way: by running its own test code over many seeds (docs/experiments.md,
// "Measuring the original"). The original's single-run numbers (4.8, 4.7, 9.6, ...) are one
// draw each; the original's own raw finals range e.g. 4.60-5.09 (1D) over seeds.
#include <gtest/gtest.h>

#include "learning_window.hpp"

using namespace verve::tasks;
using namespace verve::tasks::testing;

namespace {

struct Bar {
    const char* task;
    std::uint32_t runs;
    std::uint32_t trials;  // the original's trial count
    double originalExcess;  // original library: mean excess over the last 10% of trials, over seeds
};

void expectAtLeastTheOriginal(const Bar& bar) {
    const LearningCurve c = learn(bar.task, bar.runs, bar.trials);
    const Window w = lastTenth(c);
    print(std::string(bar.task) + " last 10%", w);
    EXPECT_LE(w.excess(), bar.originalExcess)
        << bar.task << ": " << w.steps << " steps where " << w.optimal << " were possible; the original takes "
        << bar.originalExcess << " steps more than possible";
}

// Thesis: "The value functions at the end of trial 30 are nearly optimal." Steps over trials
// 28-30 within 10% of the optimum of the same trials.
void expectNearOptimalByTrial30(const char* task) {
    const LearningCurve c = learn(task, 2000, 31);
    const Window w = windowOf(c, 28, 31);
    print(std::string(task) + " trials 28-30", w);
    EXPECT_LE(w.steps, 1.10 * w.optimal) << task;
}

}  // namespace

// Known gaps: suites named KnownGap* hold bars we do not meet yet. scripts/test.sh runs them in
// every CI run and prints their results, but does not fail on them.
// Original excess: mean (standard error) over seeds of its own test program, 200-step cap.

TEST(HotPlateLearning, OneDimensionalDiscreteNearOptimalByTrial30) { expectNearOptimalByTrial30("hot-plate-1d"); }

TEST(HotPlateLearning, OneDimensionalContinuousNearOptimalByTrial30) {
    expectNearOptimalByTrial30("hot-plate-1d-continuous");
}

// Original: 0.367 (0.011) over 40 seeds of 300 runs.
TEST(HotPlateLearning, OneDimensionalDiscreteMatchesTheOriginal) {
    expectAtLeastTheOriginal({"hot-plate-1d", 2000, 31, 0.367});
}

// Original: 0.110 (0.008) over 30 seeds.
TEST(HotPlateLearning, OneDimensionalContinuousMatchesTheOriginal) {
    expectAtLeastTheOriginal({"hot-plate-1d-continuous", 2000, 31, 0.110});
}

// Original: 2.025 (0.014) over 10 seeds.
TEST(HotPlateLearning, TwoDimensionalDiscreteMatchesTheOriginal) {
    expectAtLeastTheOriginal({"hot-plate-2d", 600, 301, 2.025});
}

// Original: 0.199 (0.002) over 10 seeds.
TEST(HotPlateLearning, TwoDimensionalContinuousMatchesTheOriginal) {
    expectAtLeastTheOriginal({"hot-plate-2d-continuous", 600, 301, 0.199});
}

// Original: 0.190 (0.004) over 40 seeds of 500 runs; ours 0.205 (0.003) over 80. A real gap of
// 0.015 steps: the original chooses its action before the step's TD update, we after it. Its order
// gives 0.189 here but is worse on every 2D hot plate (docs/experiments.md, "Known gaps").
TEST(KnownGapSignaledHotPlateLearning, OneDimensionalDiscreteMatchesTheOriginal) {
    expectAtLeastTheOriginal({"signaled-hot-plate-1d", 2000, 81, 0.190});
}

// Original: 2.19 (0.09) over 10 seeds; 1.1% of its late trials stall at the wrong wall until the
// cap, 0.4% of ours (docs/experiments.md, "Known gaps").
TEST(SignaledHotPlateLearning, OneDimensionalContinuousMatchesTheOriginal) {
    expectAtLeastTheOriginal({"signaled-hot-plate-1d-continuous", 1000, 81, 2.19});
}

// Original: 3.739 (0.006) over 10 seeds.
TEST(SignaledHotPlateLearning, TwoDimensionalDiscreteMatchesTheOriginal) {
    expectAtLeastTheOriginal({"signaled-hot-plate-2d", 300, 1601, 3.739});
}

// Original: 1.190 (0.020) over 10 seeds.
TEST(SignaledHotPlateLearning, TwoDimensionalContinuousMatchesTheOriginal) {
    expectAtLeastTheOriginal({"signaled-hot-plate-2d-continuous", 100, 1601, 1.190});
}

// At the library's defaults the bounded habits (core/habit_bound.hpp) nearly doubled the continuous
// 1D signaled plate's late trials (trials 73-80 over the defaults table's 100 runs: 12.11 steps
// before, 22.16 with them). Weights may rise only to +10 but fall without end, so they drift far
// below zero, where the sigmoids' ratios are those of exponentials: near a wrong wall one action is
// then chosen almost surely and a trial stalls until the cap. A floor (-20) brought it to 10.27 but
// MountainCar-v0 to 1 of 10; the fine lattice (core/fine_lattice.hpp) to 10.39, MountainCar-v0
// kept on every seed.
TEST(SignaledHotPlateLearning, OneDimensionalContinuousAtDefaultsNoSlowerThanWithUnboundedHabits) {
    const Window w = lateAtDefaults("signaled-hot-plate-1d-continuous", 100, 81, 73);
    print("signaled-hot-plate-1d-continuous at defaults, trials 73-80, 100 runs", w);
    EXPECT_LE(w.steps, 12.11);
}
