// Action branches (docs/experiments.md, "Action branches"): the signaled 2D hot plate driven by
// three branches at once (horizontal move x vertical move x pace, 3 x 3 x 2), at the library's
// defaults, beside the same 18 combined moves as one action set. Thresholds come from measurements
// over these seeds (the defaults table's: base seed 1, 20 runs).
#include <gtest/gtest.h>

#include "learning_window.hpp"

using namespace verve::tasks;
using namespace verve::tasks::testing;

namespace {

constexpr std::uint32_t kRuns = 20, kTrials = 301, kFirst = 271;

}  // namespace

TEST(ActionBranchesLearning, BranchesLearnTheirPartsFromOneTdErrorFasterThanTheCombinedSet) {
    const Window branches = lateAtDefaults("signaled-hot-plate-2d-branches", kRuns, kTrials, kFirst);
    const Window combined = lateAtDefaults("signaled-hot-plate-2d-18-moves", kRuns, kTrials, kFirst);
    print("branches (3 x 3 x 2) at defaults", branches);
    print("18 combined moves at defaults", combined);
    // Measured: 5.54 steps late (optimum 4.89), every trial a success; the combined set 7.34
    // (5.32 and 9.08 before the fine lattice: core/fine_lattice.hpp).
    EXPECT_LE(branches.steps, 6.5);
    EXPECT_GE(branches.success, 0.99);
    EXPECT_LT(branches.steps, combined.steps);
}

// Branches 25% faster than the combined set, measured on 80 runs. On 20 the ratio is too noisy to
// hold a bar at 0.75: over 24 independent sets of 20 runs (base seeds 1-24) it is 0.716 +- 0.020 at
// defaults, and the set of base seed 1 above is one of the two of 24 above 0.75 (5.54 / 7.34 =
// 0.755). The first 80 runs of base seed 1 (the 20 above and 60 more): 5.555 / 7.557 = 0.735. The
// fine lattice (core/fine_lattice.hpp) helped the 18 combined moves more (8.43 -> 7.61 over the 24
// sets) than the branches (5.61 -> 5.44): its features raise every learning rate, which the 18
// moves, each neuron trained on about 1/18 of steps, are shorter of.
TEST(ActionBranchesLearning, BranchesTakeAQuarterFewerStepsThanTheCombinedSetOver80Runs) {
    constexpr std::uint32_t kManyRuns = 80;
    const Window branches = lateAtDefaults("signaled-hot-plate-2d-branches", kManyRuns, kTrials, kFirst);
    const Window combined = lateAtDefaults("signaled-hot-plate-2d-18-moves", kManyRuns, kTrials, kFirst);
    print("branches (3 x 3 x 2) at defaults, 80 runs", branches);
    print("18 combined moves at defaults, 80 runs", combined);
    EXPECT_LT(branches.steps, 0.75 * combined.steps);
}
