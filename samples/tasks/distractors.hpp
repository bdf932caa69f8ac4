// The signaled 1D hot plate among distractors: a task that needs two sensors together, read among
// many. The position and the signal (which end is safe: -1 left, +1 right, now a continuous sensor)
// must be combined: neither alone says which way to go. Beside them, `distractors` continuous
// sensors wander at random and mean nothing, as most of an NPC's sensors mean nothing for a given
// decision. 2, 6 and 14 distractors make 4, 8 and 16 continuous sensors (docs/experiments.md,
// "Many sensors"): one lattice over all of them must cover every wandering combination, while
// groups of neighbouring sensors (SensorGrouping::Auto beyond 4) keep position and signal together
// and learn apart from the rest.
#pragma once
#include <cstdint>
#include <string>

#include "tasks/hot_plate.hpp"
#include "tasks/task_rng.hpp"

namespace verve::tasks {

class HotPlateAmongDistractors final : public Task {
public:
    explicit HotPlateAmongDistractors(std::uint32_t distractors);

    std::string name() const override;
    std::uint32_t maxStepsPerTrial() const override { return plate_.maxStepsPerTrial(); }
    void beginTrial(std::uint64_t seed) override;
    void observe(Observation& out) const override;
    StepResult act(std::uint32_t action) override;
    std::uint32_t optimalSteps() const override { return plate_.optimalSteps(); }
    bool succeeded() const override { return plate_.succeeded(); }
    bool finishedAtStart() const override { return plate_.finishedAtStart(); }

private:
    HotPlate plate_;
    std::uint32_t distractors_;
    std::vector<float> wander_;  // the distractors' readings
    TaskRng rng_{1};
};

}  // namespace verve::tasks
