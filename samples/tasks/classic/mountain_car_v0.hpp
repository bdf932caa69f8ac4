// MountainCar-v0: an underpowered car in a valley must rock back and forth to reach the flag at
// x >= 0.5. Push left, none or right; -1 per step (the last one too), cut off at 200 steps.
// Gymnasium's equations have no time unit; the car decides at 30 Hz here (its render rate).
// Sensors: the position over [-1.2, 0.6] and the velocity / 0.07, both into [-1, 1].
// Solved at a mean return of -110.
#pragma once
#include "tasks/classic/classic_task.hpp"

namespace verve::tasks {

struct MountainCarState {
    double position = 0, velocity = 0;
};

class MountainCarV0 final : public ClassicTask {
public:
    // `timeLimit` 200 is MountainCar-v0; a longer one gives a game's patience (the step cap of the
    // momentum task our issue measured is 2000).
    explicit MountainCarV0(std::uint32_t timeLimit = 200, float dt = 1.0f / 30.0f);
    std::string name() const override { return "MountainCar-v0"; }
    void beginTrial(std::uint64_t seed) override;
    void observe(Observation& out) const override;
    StepResult act(std::uint32_t action) override;

    double solvedReturn() const override { return -110.0; }
    std::uint64_t zooBudget() const override { return 120000; }
    const char* zooAgent() const override { return "DQN"; }

    static bool step(MountainCarState& s, std::uint32_t action);
    MountainCarState& state() { return state_; }

private:
    MountainCarState state_;
};

}  // namespace verve::tasks
