// A long continuous corridor (a long-horizon task for planning): the agent starts at the left end
// of `cells` cells and must walk to the right end; every step costs -1, reaching the end pays +1
// and ends the trial; cut off after 2000 steps. One continuous sensor (the position, resolution 10),
// actions left, right, stay, gamma 0.99. Optimum: cells - 1 steps.
#pragma once
#include <cstdint>
#include <string>

#include "tasks/grid.hpp"
#include "tasks/task.hpp"

namespace verve::tasks {

class Corridor final : public Task {
public:
    explicit Corridor(int cells = 40);  // throws std::invalid_argument unless cells >= 3

    std::string name() const override { return settings_.planning ? "corridor-planning" : "corridor"; }
    std::uint32_t maxStepsPerTrial() const override { return 2000; }
    void beginTrial(std::uint64_t seed) override;
    void observe(Observation& out) const override;
    StepResult act(std::uint32_t action) override;
    std::uint32_t optimalSteps() const override { return static_cast<std::uint32_t>(grid_.width() - 1); }
    bool succeeded() const override { return position_.x == grid_.width() - 1; }

private:
    Grid grid_;
    Cell position_{};
};

}  // namespace verve::tasks
