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

// Known gap (not gating; docs/experiments.md): branches 25% faster than the combined set, as they
// were before the fine lattice (5.32 vs 9.08). The fine lattice helped the 18 combined moves more
// (9.08 -> 7.34) than it cost the branches (5.32 -> 5.54): 0.755 of the combined set's steps.
TEST(KnownGapActionBranchesLearning, BranchesTakeAQuarterFewerStepsThanTheCombinedSet) {
    const Window branches = lateAtDefaults("signaled-hot-plate-2d-branches", kRuns, kTrials, kFirst);
    const Window combined = lateAtDefaults("signaled-hot-plate-2d-18-moves", kRuns, kTrials, kFirst);
    EXPECT_LT(branches.steps, 0.75 * combined.steps);
}
