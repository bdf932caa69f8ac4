// Cart-pole (thesis chapter 5, figure 39): a 1 kg cart slides without friction on a track, a
// 0.1 kg, 1 m pole is hinged on top. The agent pushes -10 N, 0 or +10 N; every step balanced earns
// +1, leaving the track (±2.4 m) or the pole leaning past 12 degrees ends the trial with -1.
#pragma once
#include <memory>

#include "tasks/environment.hpp"

class btRigidBody;

namespace verve::scenes {

class PhysicsWorld;

struct CartPoleConfig {
    float cartMass = 1.0f;        // kg
    float poleMass = 0.1f;        // kg
    float poleLength = 1.0f;      // m
    float maxForce = 10.0f;       // N
    float trackLimit = 2.4f;      // m; also the position sensor's range
    float speedRange = 2.4f;      // m/s, cart velocity sensor range
    float angleLimitDegrees = 12.0f;         // failure beyond; also the angle sensor's range
    float angularSpeedRangeDegrees = 100.0f;  // deg/s, pole angular velocity sensor range
    float physicsStep = 0.01f;    // s
    float agentStep = 0.05f;      // s
    float maxTrialSeconds = 1800.0f;  // 30 simulated minutes: the classic "balanced" goal
    float startSpread = 0.05f;    // a trial starts within this fraction of each sensor range
};

class CartPoleScene : public tasks::Environment {
public:
    enum Action : std::uint32_t { PushNegative = 0, NoPush = 1, PushPositive = 2 };

    explicit CartPoleScene(const CartPoleConfig& config = {});
    ~CartPoleScene() override;

    std::string name() const override { return "cart-pole"; }
    AgentDescriptor agentDescriptor() const override;
    float agentStep() const override { return config_.agentStep; }
    std::uint32_t maxStepsPerTrial() const override;
    void beginTrial(std::uint64_t seed) override;
    void observe(Observation& out) const override;
    tasks::StepResult act(std::uint32_t action) override;

    // Physical state (m, m/s, rad, rad/s); angle 0 is upright, positive leans toward +x.
    void setState(double x, double velocity, double angle, double angularVelocity);
    double position() const;
    double velocity() const;
    double angle() const;
    double angularVelocity() const;
    bool failed() const;

private:
    CartPoleConfig config_;
    std::unique_ptr<PhysicsWorld> world_;
    btRigidBody* cart_ = nullptr;  // owned by world_
    btRigidBody* pole_ = nullptr;
};

}  // namespace verve::scenes
