// 10-armed bandit (thesis fig. 16). Payoffs depend on the luck of each run's lever means, so we judge
// the regret: the best lever's mean (about 1.54 on average, the expected maximum of ten N(0,1)
// draws) minus the mean payoff, on pulls 900-999 of the same runs.
#include <gtest/gtest.h>

#include <algorithm>

#include "learning_window.hpp"
#include "tasks/bandit.hpp"
#include "tasks/task_rng.hpp"

using namespace verve::tasks;
using namespace verve::tasks::testing;

namespace {

constexpr std::uint32_t kRuns = 1000;

// The mean over runs of the best lever's mean: the payoff of an agent that always knew it.
double bestPossiblePayoff() {
    double sum = 0.0;
    for (std::uint32_t r = 0; r < kRuns; ++r) {
        const Bandit bandit(mixSeed(kSeed, r));  // the run seeds runExperiment gives the same runs
        sum += *std::max_element(bandit.means().begin(), bandit.means().end());
    }
    return sum / kRuns;
}

struct Result {
    Window first, last;
    double regret;
};

Result runBandit() {
    const LearningCurve c = learn("bandit", kRuns, 1000);
    Result r{windowOf(c, 0, 1), windowOf(c, 900, 1000), 0.0};
    r.regret = bestPossiblePayoff() - r.last.reward;
    print("bandit first pull", r.first);
    print("bandit pulls 900-999", r.last);
    std::printf("[ measured ] bandit regret on pulls 900-999: %.4f\n", r.regret);
    return r;
}

// Both tests judge the same experiment: run it once.
const Result& learnBandit() {
    static const Result result = runBandit();
    return result;
}

}  // namespace

// The bar: reward and best-lever rate far above chance (chance: 10% and a payoff near 0,
// a regret near 1.54).
TEST(BanditLearning, RewardAndBestLeverFarAboveChance) {
    const Result& r = learnBandit();
    EXPECT_NEAR(r.first.success, 0.1, 0.05);  // a fresh agent picks at chance
    EXPECT_GE(r.last.success, 0.5);           // best lever at least 5x chance
    EXPECT_LE(r.regret, 0.1);                 // within 0.1 of always pulling the best lever
}

// The original library, run over 10 seeds of 2000 runs (docs/experiments.md, "Measuring the
// original"): regret 0.056 (standard error 0.001), best lever 82.6%. Ours: 0.059 and 81.0%. Its test
// fed the raw payoffs (up to about +-4) to an agent that only asserts [-1, 1] in debug builds; ours
// clamps them, as the thesis specifies.
TEST(KnownGapBanditLearning, RegretNoWorseThanTheOriginal) {
    EXPECT_LE(learnBandit().regret, 0.056);
}
