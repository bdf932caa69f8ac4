// Acrobot-v1: two links hang from a pivot; torque -1, 0 or +1 at the joint between them swings the
// tip above the bar (-cos t1 - cos(t1 + t2) > 1), which ends the episode. -1 per step (0 on the
// step that ends it), cut off at 500 steps; the "book" dynamics, one RK4 step of dt = 0.2 s,
// velocities clipped to 4 pi and 9 pi. Sensors: both angles / pi (circular), the angular
// velocities / their limits. Solved at a mean return of -100.
#pragma once
#include "tasks/classic/classic_task.hpp"

namespace verve::tasks {

struct AcrobotState {
    double theta1 = 0, theta2 = 0, dtheta1 = 0, dtheta2 = 0;
};

class AcrobotV1 final : public ClassicTask {
public:
    AcrobotV1();
    std::string name() const override { return "Acrobot-v1"; }
    void beginTrial(std::uint64_t seed) override;
    void observe(Observation& out) const override;
    StepResult act(std::uint32_t action) override;

    double solvedReturn() const override { return -100.0; }
    std::uint64_t zooBudget() const override { return 150000; }
    const char* zooAgent() const override { return "DQN"; }

    // One step of Gymnasium's equations (action 0, 1, 2: torque -1, 0, +1); true when it terminates.
    static bool step(AcrobotState& s, std::uint32_t action);
    AcrobotState& state() { return state_; }

private:
    AcrobotState state_;
};

}  // namespace verve::tasks
