// The thesis's 2D mazes (layouts as in the original experiments): a fixed start and goal on a 10x10
// grid with walls. Reward +1 at the goal (terminal), -1 on every other step; 10,000-step cap.
// Actions: left, right, up, down, stay. Sensors: x, y (discrete 10 each, or continuous at
// resolution 15).
#pragma once
#include <cstdint>
#include <string>

#include "tasks/grid.hpp"
#include "tasks/task.hpp"

namespace verve::tasks {

struct MazeLayout {
    std::string name;
    Grid grid;
    Cell start;
    Cell goal;
};

MazeLayout maze1Layout();  // wall between columns 6|7 on rows 0-8; shortest path 22
MazeLayout maze2Layout();  // walls 3|4 rows 1-9, 5|6 rows 0-8, 7|8 rows 0-8; shortest path 25

class Maze final : public Task {
public:
    // Policy multiplier: maze #1 uses 1 (thesis fig. 28); maze #2 uses 1 as in the planning
    // experiment (fig. 40) and the original's measured runs (figs. 31/32 vary it: 5 and 0.5).
    Maze(MazeLayout layout, Sensors sensors);

    std::string name() const override;
    std::uint32_t maxStepsPerTrial() const override { return 10000; }
    void beginTrial(std::uint64_t seed) override;
    void observe(Observation& out) const override;
    StepResult act(std::uint32_t action) override;

    std::uint32_t optimalSteps() const override { return optimal_; }
    bool succeeded() const override { return position_ == layout_.goal; }

    const MazeLayout& layout() const { return layout_; }
    Cell position() const { return position_; }

private:
    MazeLayout layout_;
    Sensors sensors_;
    Cell position_{};
    std::uint32_t optimal_ = 0;
};

}  // namespace verve::tasks
