// The signaled 2D hot plate driven as a game NPC is: on every step it chooses a horizontal move
// (left, none, right), a vertical move (up, none, down) and a pace (walk one cell, run two) at once,
// three action branches of 3 x 3 x 2 (docs/experiments.md, "Action branches"). The signal says
// which edge is safe; every step on the plate hurts (-1), reaching the safe edge ends the trial
// with +1. The heads must each learn their own part (the horizontal head the side for signals 0 and
// 1, the vertical one for 2 and 3, the pace to run) from the one TD error they share. The same
// task with the 18 combined moves as one action set is the comparison: same combined index, the
// same rewards, one neuron per combination.
#pragma once
#include <cstdint>
#include <string>

#include "tasks/grid.hpp"
#include "tasks/task.hpp"

namespace verve::tasks {

class BranchedPlate final : public Task {
public:
    static constexpr int kSize = 20;
    static constexpr std::uint32_t kMaxSteps = 200;
    explicit BranchedPlate(bool branches);  // false: the 18 combined moves as one action set

    std::string name() const override;
    std::uint32_t maxStepsPerTrial() const override { return kMaxSteps; }
    void beginTrial(std::uint64_t seed) override;
    void observe(Observation& out) const override;
    // action = horizontal + 3 * (vertical + 3 * pace) (AgentDescriptor::actionOf's order).
    StepResult act(std::uint32_t action) override;
    std::uint32_t optimalSteps() const override { return optimal_; }
    bool succeeded() const override { return isSafe(position_); }
    bool finishedAtStart() const override { return optimal_ == 0; }

private:
    bool isSafe(Cell c) const;

    bool branches_;
    Grid grid_{kSize, kSize};
    Cell position_{};
    int signal_ = 0;  // the safe edge: 0 left, 1 right, 2 top, 3 bottom
    std::uint32_t optimal_ = 0;
};

}  // namespace verve::tasks
