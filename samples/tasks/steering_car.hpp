// A car that steers and throttles to targets (docs/experiments.md, "Continuous actions"): a
// kinematic car in a 12 x 12 m walled yard must reach a target placed at random, then the trial
// ends (+1). Every step earns its progress towards the target (a quarter of the most a step can
// make, so within [-0.25, 0.25]), as a game programmer would reward it. Sensors: the target's
// bearing from the car's heading (circular), its distance and the car's speed. The car is driven
// by a steering angle and a throttle, each in [-1, 1]: two continuous actions, or the same car with
// three choices of each as two action branches (full left, straight, full right x reverse, coast,
// full ahead) for the comparison. A scripted driver (steer towards the target, slow down for sharp
// turns) is the baseline every learner is measured beside.
#pragma once
#include <cstdint>
#include <string>

#include "tasks/task.hpp"

namespace verve::tasks {

struct CarState {
    double x = 0, y = 0, heading = 0, speed = 0;
};

class SteeringCar final : public Task {
public:
    enum class Controls : std::uint8_t { Continuous, Branches };
    static constexpr std::uint32_t kMaxSteps = 400;  // 20 s
    static constexpr double kDt = 0.05;
    explicit SteeringCar(Controls controls);

    std::string name() const override;
    float agentStep() const override { return static_cast<float>(kDt); }
    std::uint32_t maxStepsPerTrial() const override { return kMaxSteps; }
    void beginTrial(std::uint64_t seed) override;
    void observe(Observation& out) const override;
    // Branches: action = steer + 3 * throttle, each 0, 1, 2 for -1, 0, +1.
    StepResult act(std::uint32_t action) override;
    StepResult actContinuous(std::uint32_t action, const std::vector<float>& continuous) override;
    bool succeeded() const override { return reached_; }

    // The scripted driver's steering and throttle for the car as it is now.
    void scriptedControls(double& steer, double& throttle) const;
    StepResult drive(double steer, double throttle);  // both clipped to [-1, 1]
    const CarState& car() const { return car_; }
    double targetDistance() const;
    double targetBearing() const;  // radians in [-pi, pi), positive to the left

private:
    Controls controls_;
    CarState car_;
    double targetX_ = 0, targetY_ = 0;
    bool reached_ = false;
};

}  // namespace verve::tasks
