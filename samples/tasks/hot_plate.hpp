// The hot plate family (thesis chapter 5): a robot on a 20-cell line or a 20x20 plate. Every step
// on the plate hurts (-1); reaching a safe zone ends the trial with +1.
//   plain:    every edge is safe (1D: both ends; 2D: all four borders).
//   signaled: one edge is safe, chosen at random each trial; a discrete signal sensor says which
//             (1D: 0 left, 1 right; 2D: 0 left, 1 right, 2 top, 3 bottom).
//   swapping: 1D, one safe end and no signal: the left end until trial swapTrial (counted on this
//             instance), the right end from then on, so an agent that knew the plate must relearn it.
// Protocol of the original library's own hot-plate tests (read from its source, 2008): the start
// is uniformly random over ALL cells, and a start inside the safe zone is a finished trial of 0
// steps; a trial is cut off after 200 steps. The optimum is then 4.5 (1D), 2.85 (2D) and 9.5
// (signaled) steps on average.
#pragma once
#include <cstdint>
#include <string>

#include "tasks/grid.hpp"
#include "tasks/task.hpp"

namespace verve::tasks {

struct HotPlateConfig {
    int dimensions = 1;  // 1 (actions: left, right, stay) or 2 (left, right, up, down, stay)
    bool signaled = false;
    Sensors sensors = Sensors::Discrete;
    int size = 20;  // cells per axis
    std::uint32_t maxSteps = 200;  // a trial is cut off here (the original experiments' cap)
    std::uint32_t swapTrial = 0;   // 1D only: > 0 makes it a swapping plate (above)
};

class HotPlate final : public Task {
public:
    explicit HotPlate(const HotPlateConfig& config);  // throws std::invalid_argument

    std::string name() const override;
    std::uint32_t maxStepsPerTrial() const override { return config_.maxSteps; }
    void beginTrial(std::uint64_t seed) override;
    void observe(Observation& out) const override;
    StepResult act(std::uint32_t action) override;

    std::uint32_t optimalSteps() const override { return optimal_; }
    bool succeeded() const override { return isSafe(position_); }
    bool finishedAtStart() const override { return optimal_ == 0; }

    // For tests and visualisation.
    Cell position() const { return position_; }
    int signal() const { return signal_; }
    bool isSafe(Cell c) const;
    // Starts a trial at a chosen cell and signal (beginTrial picks both at random).
    void place(Cell start, int signal);

private:
    std::uint32_t distanceToSafety(Cell c) const;
    bool oneSafeEdge() const { return config_.signaled || config_.swapTrial > 0; }

    HotPlateConfig config_;
    Grid grid_;
    Cell position_{};
    int signal_ = 0;
    std::uint32_t optimal_ = 0;
    std::uint64_t trialsBegun_ = 0;
};

}  // namespace verve::tasks
