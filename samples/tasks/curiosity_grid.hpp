// The curiosity grid (thesis fig. 43; layout as in the original experiments): a 10x10 open grid,
// start (1, 1). Standing on (4, 4), (4, 1) or (1, 4) after a step earns 0.1, on (8, 8) 1.0,
// anywhere else 0 (the original code's value, whose numbers we compare against; the thesis
// figure says -1). No terminal state: every trial is exactly 100 steps. Discrete x, y sensors.
// Agent settings (original): planning up to 50 steps, model time constant 0, policy multiplier 2.
#pragma once
#include <cstdint>
#include <string>

#include "tasks/grid.hpp"
#include "tasks/task.hpp"

namespace verve::tasks {

enum class CuriosityAgent : std::uint8_t {
    Rl,        // plain reinforcement learning, no model
    Planning,  // planning from the learned model
    Curious,   // planning plus curiosity (novelty) rewards
};

class CuriosityGrid final : public Task {
public:
    static constexpr float kSmallReward = 0.1f;
    static constexpr float kLargeReward = 1.0f;

    explicit CuriosityGrid(CuriosityAgent agent);

    std::string name() const override;
    std::uint32_t maxStepsPerTrial() const override { return 100; }
    void beginTrial(std::uint64_t seed) override;
    void observe(Observation& out) const override;
    StepResult act(std::uint32_t action) override;

    // Success: the trial visited the large reward at least once.
    bool succeeded() const override { return foundLarge_; }

    static float rewardAt(Cell c);
    Cell position() const { return position_; }

private:
    CuriosityAgent agent_;
    Grid grid_{10, 10};
    Cell position_{1, 1};
    bool foundLarge_ = false;
};

}  // namespace verve::tasks
