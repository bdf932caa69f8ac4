#include "tasks/branched_plate.hpp"

#include <stdexcept>

#include "tasks/task_rng.hpp"

namespace verve::tasks {

BranchedPlate::BranchedPlate(bool branches) : branches_(branches) {
    // The signaled plate's settings (hot_plate.cpp): continuous position, resolution 25.
    grid_.addPositionSensors(settings_, Sensors::Continuous);
    settings_.addDiscreteSensor(4);
    if (branches) settings_.setActionBranches({3, 3, 2});
    else settings_.numActions = 18;
    settings_.policyMultiplier = 10.0f;
    settings_.tauValue = 0.1f;
    settings_.resolution = 25;
}

std::string BranchedPlate::name() const {
    return branches_ ? "signaled-hot-plate-2d-branches" : "signaled-hot-plate-2d-18-moves";
}

bool BranchedPlate::isSafe(Cell c) const {
    const int last = kSize - 1;
    const bool safe[4] = {c.x == 0, c.x == last, c.y == 0, c.y == last};
    return safe[signal_];
}

void BranchedPlate::beginTrial(std::uint64_t seed) {
    TaskRng rng(seed);
    position_ = Cell{static_cast<int>(rng.below(kSize)), static_cast<int>(rng.below(kSize))};
    signal_ = static_cast<int>(rng.below(4));
    const int last = kSize - 1;
    const int distance[4] = {position_.x, last - position_.x, position_.y, last - position_.y};
    optimal_ = static_cast<std::uint32_t>((distance[signal_] + 1) / 2);  // running: two cells a step
}

void BranchedPlate::observe(Observation& out) const {
    grid_.writePosition(position_, Sensors::Continuous, out);
    out.setDiscrete(0, signal_);
}

StepResult BranchedPlate::act(std::uint32_t action) {
    if (action >= 18) throw std::invalid_argument("BranchedPlate::act: no such action");
    constexpr Move kHorizontal[3] = {Move::Left, Move::Stay, Move::Right};
    constexpr Move kVertical[3] = {Move::Up, Move::Stay, Move::Down};
    const std::uint32_t cells = 1 + action / 9;
    for (std::uint32_t i = 0; i < cells && !isSafe(position_); ++i) {
        position_ = grid_.move(position_, kHorizontal[action % 3]);
        position_ = grid_.move(position_, kVertical[(action / 3) % 3]);
    }
    if (isSafe(position_)) return StepResult{1.0f, true};
    return StepResult{-1.0f, false};
}

}  // namespace verve::tasks
