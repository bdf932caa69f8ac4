#include "tasks/classic/mountain_car_v0.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace verve::tasks {
namespace {

constexpr double kMinPosition = -1.2, kMaxPosition = 0.6, kMaxSpeed = 0.07, kGoal = 0.5;
constexpr double kForce = 0.001, kGravity = 0.0025;

}  // namespace

MountainCarV0::MountainCarV0(std::uint32_t timeLimit, float dt) : ClassicTask(timeLimit, dt) {
    descriptor_.addContinuousSensor();
    descriptor_.addContinuousSensor();
    descriptor_.numActions = 3;
}

void MountainCarV0::beginTrial(std::uint64_t seed) {
    rng_ = TaskRng(seed);
    state_.position = -0.6 + 0.2 * rng_.uniform();
    state_.velocity = 0.0;
}

void MountainCarV0::observe(Observation& out) const {
    const double middle = (kMinPosition + kMaxPosition) / 2, half = (kMaxPosition - kMinPosition) / 2;
    out.setContinuous(0, static_cast<float>((state_.position - middle) / half));
    out.setContinuous(1, static_cast<float>(state_.velocity / kMaxSpeed));
}

bool MountainCarV0::step(MountainCarState& s, std::uint32_t action) {
    s.velocity += (static_cast<double>(action) - 1.0) * kForce + std::cos(3 * s.position) * -kGravity;
    s.velocity = std::clamp(s.velocity, -kMaxSpeed, kMaxSpeed);
    s.position = std::clamp(s.position + s.velocity, kMinPosition, kMaxPosition);
    if (s.position == kMinPosition && s.velocity < 0) s.velocity = 0;
    return s.position >= kGoal && s.velocity >= 0;
}

StepResult MountainCarV0::act(std::uint32_t action) {
    if (action >= 3) throw std::invalid_argument("MountainCarV0::act: no such action");
    const bool terminal = step(state_, action);
    gymnasiumReward_ = -1.0;
    return StepResult{-1.0f, terminal};
}

}  // namespace verve::tasks
