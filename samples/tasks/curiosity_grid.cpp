#include "tasks/curiosity_grid.hpp"

#include <stdexcept>

namespace verve::tasks {

CuriosityGrid::CuriosityGrid(CuriosityAgent agent) : agent_(agent) {
    grid_.addPositionSensors(settings_, Sensors::Discrete);
    settings_.numActions = 5;
    settings_.policyMultiplier = 2.0f;
    settings_.tauValue = 0.1f;
    settings_.planning = agent != CuriosityAgent::Rl;
    settings_.tauModel = 0.0f;
    settings_.maxPlanningSteps = 50;
    settings_.curiosity = agent == CuriosityAgent::Curious ? CuriosityMode::Novelty : CuriosityMode::None;
}

std::string CuriosityGrid::name() const {
    switch (agent_) {
        case CuriosityAgent::Rl: return "curiosity-grid-rl";
        case CuriosityAgent::Planning: return "curiosity-grid-planning";
        default: return "curiosity-grid-curious";
    }
}

float CuriosityGrid::rewardAt(Cell c) {
    if (c == Cell{8, 8}) return kLargeReward;
    if (c == Cell{4, 4} || c == Cell{4, 1} || c == Cell{1, 4}) return kSmallReward;
    return 0.0f;
}

void CuriosityGrid::beginTrial(std::uint64_t /*seed: the start is fixed*/) {
    position_ = Cell{1, 1};
    foundLarge_ = false;
}

void CuriosityGrid::observe(Observation& out) const { grid_.writePosition(position_, Sensors::Discrete, out); }

StepResult CuriosityGrid::act(std::uint32_t action) {
    if (action >= settings_.numActions) throw std::invalid_argument("CuriosityGrid::act: no such action");
    position_ = grid_.move(position_, static_cast<Move>(action));
    const float reward = rewardAt(position_);
    if (reward == kLargeReward) foundLarge_ = true;
    return StepResult{reward, false};
}

}  // namespace verve::tasks
