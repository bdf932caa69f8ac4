#include "tasks/steering_car.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "tasks/task_rng.hpp"

namespace verve::tasks {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kYard = 12.0;         // metres, walls all round
constexpr double kReach = 0.75;        // a target within this is reached
constexpr double kMaxSpeed = 4.0, kMinSpeed = -1.5;  // m/s ahead, in reverse
constexpr double kAccel = 4.0, kDrag = 0.5;          // m/s^2 at full throttle, 1/s
constexpr double kMaxSteer = 0.6, kWheelbase = 1.0;  // radians at full lock, metres
constexpr double kFarthest = 17.0;     // the yard's diagonal, about
constexpr double kProgressReward = 0.25;

double wrap(double a) { return std::remainder(a, 2 * kPi); }

}  // namespace

SteeringCar::SteeringCar(Controls controls) : controls_(controls) {
    settings_ = AgentDescriptor{};  // no thesis settings to keep: the library's defaults
    settings_.addContinuousSensor(true);  // bearing
    settings_.addContinuousSensor();      // distance
    settings_.addContinuousSensor();      // speed
    if (controls == Controls::Continuous) {
        settings_.numActions = 1;
        settings_.continuousActions = 2;
    } else {
        settings_.setActionBranches({3, 3});
    }
}

std::string SteeringCar::name() const {
    return controls_ == Controls::Continuous ? "steering-car" : "steering-car-branches";
}

void SteeringCar::beginTrial(std::uint64_t seed) {
    TaskRng rng(seed);
    const double margin = 1.0;
    auto coordinate = [&] { return margin + (kYard - 2 * margin) * rng.uniform(); };
    car_ = CarState{coordinate(), coordinate(), wrap(2 * kPi * rng.uniform()), 0.0};
    do {
        targetX_ = coordinate();
        targetY_ = coordinate();
    } while (targetDistance() < 4.0);
    reached_ = false;
}

double SteeringCar::targetDistance() const { return std::hypot(targetX_ - car_.x, targetY_ - car_.y); }

double SteeringCar::targetBearing() const {
    return wrap(std::atan2(targetY_ - car_.y, targetX_ - car_.x) - car_.heading);
}

void SteeringCar::observe(Observation& out) const {
    out.setContinuous(0, static_cast<float>(std::clamp(targetBearing() / kPi, -1.0, 1.0)));
    out.setContinuous(1, static_cast<float>(2.0 * std::min(targetDistance() / kFarthest, 1.0) - 1.0));
    out.setContinuous(2, static_cast<float>(car_.speed / kMaxSpeed));
}

StepResult SteeringCar::act(std::uint32_t action) {
    if (controls_ != Controls::Branches || action >= 9) throw std::invalid_argument("SteeringCar::act: no such action");
    return drive(static_cast<double>(action % 3) - 1.0, static_cast<double>(action / 3) - 1.0);
}

StepResult SteeringCar::actContinuous(std::uint32_t action, const std::vector<float>& continuous) {
    if (controls_ == Controls::Branches) return act(action);
    if (action != 0 || continuous.size() != 2) throw std::invalid_argument("SteeringCar::actContinuous: steer, throttle");
    return drive(continuous[0], continuous[1]);
}

StepResult SteeringCar::drive(double steer, double throttle) {
    steer = std::clamp(steer, -1.0, 1.0);
    throttle = std::clamp(throttle, -1.0, 1.0);
    const double before = targetDistance();
    car_.speed = std::clamp(car_.speed + (kAccel * throttle - kDrag * car_.speed) * kDt, kMinSpeed, kMaxSpeed);
    car_.heading = wrap(car_.heading + car_.speed * std::tan(kMaxSteer * steer) / kWheelbase * kDt);
    double x = car_.x + car_.speed * std::cos(car_.heading) * kDt;
    double y = car_.y + car_.speed * std::sin(car_.heading) * kDt;
    if (x < 0 || x > kYard || y < 0 || y > kYard) {  // a wall stops the car
        x = std::clamp(x, 0.0, kYard);
        y = std::clamp(y, 0.0, kYard);
        car_.speed = 0.0;
    }
    car_.x = x;
    car_.y = y;
    if (targetDistance() < kReach) {
        reached_ = true;
        return StepResult{1.0f, true};
    }
    const double progress = (before - targetDistance()) / (kMaxSpeed * kDt);
    return StepResult{static_cast<float>(kProgressReward * std::clamp(progress, -1.0, 1.0)), false};
}

void SteeringCar::scriptedControls(double& steer, double& throttle) const {
    const double bearing = targetBearing();
    steer = std::clamp(2.0 * bearing, -1.0, 1.0) * (car_.speed >= 0.0 ? 1.0 : -1.0);
    throttle = std::fabs(bearing) < kPi / 3 ? 1.0 : 0.3;
}

}  // namespace verve::tasks
