#include "tasks/classic/pendulum_v1.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace verve::tasks {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kMaxSpeed = 8, kMaxTorque = 2, kDt = 0.05, kG = 10, kM = 1, kL = 1;
constexpr double kTorques[] = {-kMaxTorque, 0.0, kMaxTorque};

}  // namespace

PendulumV1::PendulumV1(Torque torque) : ClassicTask(200, static_cast<float>(kDt)), torque_(torque) {
    descriptor_.addContinuousSensor(true);
    descriptor_.addContinuousSensor();
    descriptor_.numActions = torque == Torque::Continuous ? 1 : 3;
    descriptor_.continuousActions = torque == Torque::Continuous ? 1 : 0;
}

void PendulumV1::beginTrial(std::uint64_t seed) {
    rng_ = TaskRng(seed);
    state_.theta = -kPi + 2 * kPi * rng_.uniform();
    state_.thetaDot = -1.0 + 2.0 * rng_.uniform();
}

void PendulumV1::observe(Observation& out) const {
    out.setContinuous(0, static_cast<float>(wrapAngle(state_.theta) / kPi));
    out.setContinuous(1, static_cast<float>(state_.thetaDot / kMaxSpeed));
}

double PendulumV1::step(PendulumState& s, double torque) {
    const double u = std::clamp(torque, -kMaxTorque, kMaxTorque);
    const double angle = wrapAngle(s.theta);
    const double cost = angle * angle + 0.1 * s.thetaDot * s.thetaDot + 0.001 * u * u;
    double thetaDot = s.thetaDot + (3 * kG / (2 * kL) * std::sin(s.theta) + 3.0 / (kM * kL * kL) * u) * kDt;
    thetaDot = std::clamp(thetaDot, -kMaxSpeed, kMaxSpeed);
    s.theta += thetaDot * kDt;
    s.thetaDot = thetaDot;
    return -cost;
}

StepResult PendulumV1::act(std::uint32_t action) {
    if (torque_ == Torque::Continuous) throw std::invalid_argument("PendulumV1::act: the torque is continuous");
    if (action >= 3) throw std::invalid_argument("PendulumV1::act: no such action");
    return torqued(kTorques[action]);
}

StepResult PendulumV1::actContinuous(std::uint32_t action, const std::vector<float>& continuous) {
    if (torque_ == Torque::Discrete) return act(action);
    if (action != 0 || continuous.size() != 1) throw std::invalid_argument("PendulumV1::actContinuous: one torque");
    return torqued(kMaxTorque * static_cast<double>(continuous[0]));
}

StepResult PendulumV1::torqued(double torque) {
    gymnasiumReward_ = step(state_, torque);
    return StepResult{static_cast<float>(gymnasiumReward_ / kLargestCost), false};
}

}  // namespace verve::tasks
