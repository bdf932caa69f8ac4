// Pendulum-v1: swing a pendulum up from any angle and hold it upright with a torque of at most 2.
// Reward -(angle^2 + 0.1 angle'^2 + 0.001 torque^2) per step (angle from upright), never ends, cut
// off at 200 steps of dt = 0.05 s. The torque is discretised to three actions: -2, 0, +2 (the
// extremes and none: a bang-bang controller with a rest, which can swing up and hold), or, as
// Gymnasium has it, continuous: one continuous action times 2 (Torque::Continuous). The agent
// is handed the reward divided by its largest size, 16.27 (rewards are expected in [-1, 1]).
// Sensors: the angle / pi (circular), the angular velocity / 8 (its limit). Solved at a mean
// return of -200 (docs/experiments.md says why).
#pragma once
#include "tasks/classic/classic_task.hpp"

namespace verve::tasks {

struct PendulumState {
    double theta = 0, thetaDot = 0;
};

class PendulumV1 final : public ClassicTask {
public:
    enum class Torque : std::uint8_t { Discrete, Continuous };
    explicit PendulumV1(Torque torque = Torque::Discrete);
    std::string name() const override { return torque_ == Torque::Continuous ? "Pendulum-v1 (continuous)" : "Pendulum-v1"; }
    void beginTrial(std::uint64_t seed) override;
    void observe(Observation& out) const override;
    StepResult act(std::uint32_t action) override;
    StepResult actContinuous(std::uint32_t action, const std::vector<float>& continuous) override;

    double solvedReturn() const override { return -200.0; }
    std::uint64_t zooBudget() const override { return 100000; }
    const char* zooAgent() const override { return "PPO (continuous torque)"; }
    Torque torque() const { return torque_; }

    static constexpr double kLargestCost = 16.2736044;  // pi^2 + 0.1 * 8^2 + 0.001 * 2^2
    // One step with `torque` (clipped to +-2); returns Gymnasium's reward.
    static double step(PendulumState& s, double torque);
    PendulumState& state() { return state_; }

private:
    StepResult torqued(double torque);
    Torque torque_;
    PendulumState state_;
};

}  // namespace verve::tasks
