// Pendulum swing-up (thesis chapter 5, figure 35): a 1 kg, 1 m rod hinged at one end in midair.
// The agent picks torque -max, 0 or +max; reward +1 within 45 degrees of upright, else -1.
#pragma once
#include <memory>

class btRigidBody;

#include "tasks/environment.hpp"

namespace verve::scenes {

class PhysicsWorld;

struct PendulumConfig {
    float mass = 1.0f;               // kg
    float length = 1.0f;             // m; a thin uniform rod
    float maxTorque = 2.0f;          // N·m
    float physicsStep = 0.01f;       // s
    float agentStep = 0.1f;          // s
    float trialSeconds = 20.0f;
    float uprightDegrees = 45.0f;    // reward +1 within this angle of upright
    float speedRangeDegrees = 500.0f;  // angular velocity sensor range, deg/s
    float startSpeedDegrees = 180.0f;  // a trial starts at a uniform random speed within this
};

class PendulumScene : public tasks::Environment {
public:
    enum Action : std::uint32_t { TorqueNegative = 0, NoTorque = 1, TorquePositive = 2 };

    explicit PendulumScene(const PendulumConfig& config = {});
    ~PendulumScene() override;

    std::string name() const override { return "pendulum"; }
    AgentDescriptor agentDescriptor() const override;
    float agentStep() const override { return config_.agentStep; }
    std::uint32_t maxStepsPerTrial() const override;
    void beginTrial(std::uint64_t seed) override;
    void observe(Observation& out) const override;
    tasks::StepResult act(std::uint32_t action) override;

    // Physical state, for tests and plots. Angle 0 is upright, in radians within [-pi, pi].
    void setState(double angle, double angularVelocity);
    double angle() const;
    double angularVelocity() const;
    double energy() const;  // kinetic + potential (J), zero potential at the pivot height

private:
    PendulumConfig config_;
    std::unique_ptr<PhysicsWorld> world_;
    btRigidBody* rod_ = nullptr;  // owned by world_
};

}  // namespace verve::scenes
