// Many sensors (docs/experiments.md, "Many sensors"): the signaled hot plate whose position and
// signal must be read together among 6, 14 or 30 wandering distractors, at the library's defaults.
// Sensor groups (Auto beyond 4 continuous sensors) learn it; one lattice over all sensors does not
// (and over 32 sensors is refused: one lattice spans at most 16).
// Thresholds come from measurements over these seeds (the defaults table's: base seed 1, 20 runs).
#include <gtest/gtest.h>

#include "learning_window.hpp"

using namespace verve::tasks;
using namespace verve::tasks::testing;

namespace {

constexpr std::uint32_t kRuns = 20, kTrials = 301, kFirst = 271;

Window lateWithOneLattice(const std::string& task) {
    const LearningCurve c = runExperiment(findTask(task)->make, kRuns, kTrials, 1, [](verve::AgentDescriptor& d) {
        d = atLibraryDefaults(d);
        d.grouping = verve::SensorGrouping::Joint;
    });
    return windowOf(c, kFirst, kTrials);
}

}  // namespace

TEST(ManySensorsLearning, SensorGroupsReadTwoSensorsTogetherAmongDistractors) {
    for (const char* task : {"signaled-hot-plate-1d-6-distractors", "signaled-hot-plate-1d-14-distractors"}) {
        const Window groups = lateAtDefaults(task, kRuns, kTrials, kFirst);
        const Window joint = lateWithOneLattice(task);
        print(std::string(task) + " at defaults (groups)", groups);
        print(std::string(task) + " with one lattice", joint);
        // Measured: 18.5 (8 sensors) and 18.1 (16) steps late, the optimum ~9.5, the signaled plate
        // without distractors 22.2 at defaults; one lattice 133.9 and 133.1 (most trials at the cap).
        EXPECT_LE(groups.steps, 25.0) << task;
        EXPECT_LT(groups.steps * 4.0, joint.steps) << task;
    }
    // 32 sensors (30 distractors): 63 lattices. Measured 17.0 steps late (16 sensors: 18.1).
    const Window groups32 = lateAtDefaults("signaled-hot-plate-1d-30-distractors", kRuns, kTrials, kFirst);
    print("signaled-hot-plate-1d-30-distractors at defaults (groups)", groups32);
    EXPECT_LE(groups32.steps, 25.0);
}
