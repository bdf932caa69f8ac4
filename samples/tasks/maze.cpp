#include "tasks/maze.hpp"

#include <stdexcept>
#include <utility>

namespace verve::tasks {

MazeLayout maze1Layout() {
    Grid grid(10, 10);
    grid.addWallRightOf(6, 0, 8);
    return MazeLayout{"maze1", std::move(grid), Cell{1, 1}, Cell{7, 1}, 0, Cell{}};
}

MazeLayout maze2Layout() {
    Grid grid(10, 10);
    grid.addWallRightOf(3, 1, 9);
    grid.addWallRightOf(5, 0, 8);
    grid.addWallRightOf(7, 0, 8);
    return MazeLayout{"maze2", std::move(grid), Cell{1, 1}, Cell{8, 1}, 0, Cell{}};
}

MazeLayout maze1MovingGoalLayout() {
    MazeLayout layout = maze1Layout();
    layout.name = "maze1-moving-goal";
    layout.goalMoveTrial = 50;
    layout.movedGoal = Cell{0, 9};
    return layout;
}

Maze::Maze(MazeLayout layout, Sensors sensors) : layout_(std::move(layout)), sensors_(sensors) {
    optimal_ = layout_.grid.shortestPath(layout_.start, layout_.goal);
    const std::uint32_t movedOptimal =
        layout_.goalMoveTrial > 0 ? layout_.grid.shortestPath(layout_.start, layout_.movedGoal) : optimal_;
    if (optimal_ == Grid::kUnreachable || optimal_ == 0 || movedOptimal == Grid::kUnreachable || movedOptimal == 0) {
        throw std::invalid_argument("Maze " + layout_.name + ": the goal must be reachable and not the start");
    }
    layout_.grid.addPositionSensors(settings_, sensors);
    settings_.numActions = 5;
    settings_.policyMultiplier = 1.0f;
    settings_.tauValue = 0.1f;
    settings_.resolution = 15;
    position_ = layout_.start;
}

std::string Maze::name() const {
    return layout_.name + (sensors_ == Sensors::Continuous ? "-continuous" : "") +
           (settings_.planning ? "-planning" : "");
}

void Maze::beginTrial(std::uint64_t /*seed: the start is fixed*/) {
    const bool moved = layout_.goalMoveTrial > 0 && trialsBegun_ >= layout_.goalMoveTrial;
    ++trialsBegun_;
    if (moved != moved_) {
        moved_ = moved;
        optimal_ = layout_.grid.shortestPath(layout_.start, goal());
    }
    position_ = layout_.start;
}

void Maze::observe(Observation& out) const { layout_.grid.writePosition(position_, sensors_, out); }

StepResult Maze::act(std::uint32_t action) {
    if (action >= settings_.numActions) throw std::invalid_argument("Maze::act: no such action");
    position_ = layout_.grid.move(position_, static_cast<Move>(action));
    if (position_ == goal()) return StepResult{1.0f, true};
    return StepResult{-1.0f, false};
}

}  // namespace verve::tasks
