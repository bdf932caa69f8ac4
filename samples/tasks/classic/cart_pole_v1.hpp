// CartPole-v1: push a cart left or right to keep a pole upright. +1 per step (the falling step
// too), ends when the pole leans past 12 degrees or the cart leaves +-2.4 m, cut off at 500 steps;
// Euler integration at tau = 0.02 s. Sensors: x / 2.4, x' / 3, angle / 12 degrees, angle' / 3.5
// (the ranges a balanced run stays within). Solved at a mean return of 475.
#pragma once
#include "tasks/classic/classic_task.hpp"

namespace verve::tasks {

struct CartPoleState {
    double x = 0, xDot = 0, theta = 0, thetaDot = 0;
};

class CartPoleV1 final : public ClassicTask {
public:
    CartPoleV1();
    std::string name() const override { return "CartPole-v1"; }
    void beginTrial(std::uint64_t seed) override;
    void observe(Observation& out) const override;
    StepResult act(std::uint32_t action) override;

    double solvedReturn() const override { return 475.0; }
    std::uint64_t zooBudget() const override { return 100000; }
    const char* zooAgent() const override { return "PPO"; }

    // One step of Gymnasium's equations (action 1 pushes right); true when it terminates.
    static bool step(CartPoleState& s, std::uint32_t action);
    CartPoleState& state() { return state_; }

private:
    CartPoleState state_;
};

}  // namespace verve::tasks
