#include "tasks/distractors.hpp"

#include <algorithm>

namespace verve::tasks {

HotPlateAmongDistractors::HotPlateAmongDistractors(std::uint32_t distractors)
    : plate_(HotPlateConfig{1, true, Sensors::Continuous}), distractors_(distractors), wander_(distractors, 0.0f) {
    // The plate's settings, with its discrete signal as a continuous sensor next to the position.
    settings_ = plate_.agentDescriptor();
    settings_.discreteSensors.clear();
    settings_.addContinuousSensor(false);
    for (std::uint32_t i = 0; i < distractors; ++i) settings_.addContinuousSensor(false);
}

std::string HotPlateAmongDistractors::name() const {
    return "signaled-hot-plate-1d-" + std::to_string(distractors_) + "-distractors";
}

void HotPlateAmongDistractors::beginTrial(std::uint64_t seed) {
    plate_.beginTrial(seed);
    rng_ = TaskRng(mixSeed(seed, 0xD157));
    for (auto& w : wander_) w = static_cast<float>(2.0 * rng_.uniform() - 1.0);
}

void HotPlateAmongDistractors::observe(Observation& out) const {
    out.continuous[0] = cellToSensor(plate_.position().x, 20);
    out.continuous[1] = plate_.signal() == 0 ? -1.0f : 1.0f;
    std::copy(wander_.begin(), wander_.end(), out.continuous.begin() + 2);
}

StepResult HotPlateAmongDistractors::act(std::uint32_t action) {
    // Each distractor takes a random step of up to a tenth of its range, reflected at the ends.
    for (auto& w : wander_) {
        w += static_cast<float>(0.2 * rng_.uniform() - 0.1);
        if (w > 1.0f) w = 2.0f - w;
        if (w < -1.0f) w = -2.0f - w;
    }
    return plate_.act(action);
}

}  // namespace verve::tasks
