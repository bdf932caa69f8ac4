#include "tasks/corridor.hpp"

#include <stdexcept>

namespace verve::tasks {
namespace {

constexpr Move kMoves[] = {Move::Left, Move::Right, Move::Stay};

}  // namespace

Corridor::Corridor(int cells) : grid_(cells, 1) {
    if (cells < 3) throw std::invalid_argument("Corridor: needs >= 3 cells");
    grid_.addPositionSensors(settings_, Sensors::Continuous);
    settings_.numActions = 3;
    settings_.tauValue = 0.1f;
    settings_.policyMultiplier = 10.0f;
    // A horizon the goal lies within: gamma 0.99 per 0.1 s step, so the end 39 steps away is worth
    // 0.68 at the start. With the default 1 s (gamma 0.905, 0.02) no learner can tell the way to
    // the goal from any other walk, and the task would measure nothing.
    settings_.tauDiscount = 10.0f;
}

void Corridor::beginTrial(std::uint64_t /*seed: the start is fixed*/) { position_ = Cell{0, 0}; }

void Corridor::observe(Observation& out) const { grid_.writePosition(position_, Sensors::Continuous, out); }

StepResult Corridor::act(std::uint32_t action) {
    if (action >= settings_.numActions) throw std::invalid_argument("Corridor::act: no such action");
    position_ = grid_.move(position_, kMoves[action]);
    if (succeeded()) return StepResult{1.0f, true};
    return StepResult{-1.0f, false};
}

}  // namespace verve::tasks
