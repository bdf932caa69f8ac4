#include "pendulum_scene.hpp"

#include "physics_world.hpp"
#include "rod.hpp"
#include "scene_random.hpp"
#include "scene_util.hpp"

namespace verve::scenes {

namespace {
constexpr btScalar kRodRadius = 0.025f;  // thin: its inertia is close to m L^2 / 3 about the pivot
}

PendulumScene::PendulumScene(const PendulumConfig& config) : config_(config) { beginTrial(0); }
PendulumScene::~PendulumScene() = default;

AgentDescriptor PendulumScene::agentDescriptor() const {
    AgentDescriptor d;
    d.adaptation = 0;  // the thesis's settings, as its experiment ran
    d.addContinuousSensor(true);   // angle, circular: -180 and 180 degrees are the same
    d.addContinuousSensor(false);  // angular velocity
    d.numActions = 3;
    d.resolution = 16;  // thesis settings for figure 35
    d.tauValue = 0.01f;
    d.policyMultiplier = 2.0f;
    return d;
}

std::uint32_t PendulumScene::maxStepsPerTrial() const {
    return stepsIn(config_.trialSeconds, config_.agentStep);
}

void PendulumScene::beginTrial(std::uint64_t seed) {
    const btScalar half = config_.length / 2;
    rod_ = nullptr;
    world_ = std::make_unique<PhysicsWorld>();
    btTransform upright;
    upright.setIdentity();
    upright.setOrigin(btVector3(0, half, 0));
    rod_ = world_->addBody(std::make_unique<btBoxShape>(btVector3(kRodRadius, half, kRodRadius)),
                           config_.mass, upright);
    // Single-body hinge: the rod's lower end is pinned to the world origin, turning about z.
    world_->addConstraint(
        std::make_unique<btHingeConstraint>(*rod_, btVector3(0, -half, 0), btVector3(0, 0, 1)));

    SceneRandom random(seed);
    const double angle = random.uniform(-kPi, kPi);
    const double speed = radians(config_.startSpeedDegrees);
    setState(angle, random.uniform(-speed, speed));
}

void PendulumScene::setState(double angle, double angularVelocity) {
    placeRod(*rod_, btVector3(0, 0, 0), config_.length / 2, angle, angularVelocity,
             btVector3(0, 0, 0));
}

double PendulumScene::angle() const { return rodAngle(*rod_); }
double PendulumScene::angularVelocity() const { return rodAngularVelocity(*rod_); }

double PendulumScene::energy() const {
    const btVector3 v = rod_->getLinearVelocity();
    const btVector3 w = rod_->getAngularVelocity();
    const btVector3 inertia = rod_->getInvInertiaDiagLocal();
    const double iz = inertia.z() > 0 ? 1.0 / static_cast<double>(inertia.z()) : 0.0;
    const double height = rod_->getCenterOfMassPosition().y();
    return 0.5 * config_.mass * static_cast<double>(v.length2()) +
           0.5 * iz * static_cast<double>(w.z()) * static_cast<double>(w.z()) +
           config_.mass * 9.81 * height;
}

void PendulumScene::observe(Observation& out) const {
    out.discrete.clear();
    out.continuous.assign({toSensor(angle(), kPi),
                           toSensor(angularVelocity(), radians(config_.speedRangeDegrees))});
}

tasks::StepResult PendulumScene::act(std::uint32_t action) {
    checkAction(name(), action, 3);
    const btScalar torque = config_.maxTorque * (static_cast<btScalar>(action) - 1);
    // A positive torque leans the rod toward +x, which is a negative turn about z.
    advance(*world_, config_.agentStep, config_.physicsStep,
            [&] { rod_->applyTorque(btVector3(0, 0, -torque)); });
    const bool upright = std::abs(angle()) <= radians(config_.uprightDegrees);
    return tasks::StepResult{upright ? 1.0f : -1.0f, false};
}

}  // namespace verve::scenes
