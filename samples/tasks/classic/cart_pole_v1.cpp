#include "tasks/classic/cart_pole_v1.hpp"

#include <cmath>
#include <stdexcept>

namespace verve::tasks {
namespace {

constexpr double kGravity = 9.8, kCartMass = 1.0, kPoleMass = 0.1, kHalfLength = 0.5, kForce = 10.0, kTau = 0.02;
constexpr double kTotalMass = kCartMass + kPoleMass, kPoleMassLength = kPoleMass * kHalfLength;
constexpr double kThetaLimit = 12 * 2 * 3.14159265358979323846 / 360, kXLimit = 2.4;

}  // namespace

CartPoleV1::CartPoleV1() : ClassicTask(500, static_cast<float>(kTau)) {
    for (int i = 0; i < 4; ++i) descriptor_.addContinuousSensor();
    descriptor_.numActions = 2;
}

void CartPoleV1::beginTrial(std::uint64_t seed) {
    rng_ = TaskRng(seed);
    for (double* v : {&state_.x, &state_.xDot, &state_.theta, &state_.thetaDot}) *v = -0.05 + 0.1 * rng_.uniform();
}

void CartPoleV1::observe(Observation& out) const {
    out.setContinuous(0, static_cast<float>(state_.x / kXLimit));
    out.setContinuous(1, static_cast<float>(state_.xDot / 3.0));
    out.setContinuous(2, static_cast<float>(state_.theta / kThetaLimit));
    out.setContinuous(3, static_cast<float>(state_.thetaDot / 3.5));
}

bool CartPoleV1::step(CartPoleState& s, std::uint32_t action) {
    const double force = action == 1 ? kForce : -kForce;
    const double cosTheta = std::cos(s.theta), sinTheta = std::sin(s.theta);
    const double temp = (force + kPoleMassLength * s.thetaDot * s.thetaDot * sinTheta) / kTotalMass;
    const double thetaAcc = (kGravity * sinTheta - cosTheta * temp) /
                            (kHalfLength * (4.0 / 3.0 - kPoleMass * cosTheta * cosTheta / kTotalMass));
    const double xAcc = temp - kPoleMassLength * thetaAcc * cosTheta / kTotalMass;
    s.x += kTau * s.xDot;
    s.xDot += kTau * xAcc;
    s.theta += kTau * s.thetaDot;
    s.thetaDot += kTau * thetaAcc;
    return s.x < -kXLimit || s.x > kXLimit || s.theta < -kThetaLimit || s.theta > kThetaLimit;
}

StepResult CartPoleV1::act(std::uint32_t action) {
    if (action >= 2) throw std::invalid_argument("CartPoleV1::act: no such action");
    const bool terminal = step(state_, action);
    gymnasiumReward_ = 1.0;
    return StepResult{1.0f, terminal};
}

}  // namespace verve::tasks
