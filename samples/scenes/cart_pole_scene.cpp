#include "cart_pole_scene.hpp"

#include "physics_world.hpp"
#include "rod.hpp"
#include "scene_random.hpp"
#include "scene_util.hpp"

namespace verve::scenes {

namespace {
const btVector3 kCartHalfExtents(0.25f, 0.1f, 0.15f);
constexpr btScalar kPoleRadius = 0.02f;
}  // namespace

CartPoleScene::CartPoleScene(const CartPoleConfig& config) : config_(config) { beginTrial(0); }
CartPoleScene::~CartPoleScene() = default;

AgentDescriptor CartPoleScene::agentDescriptor() const {
    AgentDescriptor d;
    d.adaptation = 0;  // the thesis's settings, as its experiment ran
    for (int i = 0; i < 4; ++i) d.addContinuousSensor(false);  // x, x', angle, angle'
    d.numActions = 3;
    d.resolution = 8;  // thesis settings for figure 39
    d.tauValue = 0.001f;
    d.policyMultiplier = 50.0f;
    return d;
}

std::uint32_t CartPoleScene::maxStepsPerTrial() const {
    return stepsIn(config_.maxTrialSeconds, config_.agentStep);
}

void CartPoleScene::beginTrial(std::uint64_t seed) {
    const btScalar half = config_.poleLength / 2;
    cart_ = pole_ = nullptr;
    world_ = std::make_unique<PhysicsWorld>();
    btTransform at;
    at.setIdentity();
    cart_ = world_->addBody(std::make_unique<btBoxShape>(kCartHalfExtents), config_.cartMass, at);
    at.setOrigin(btVector3(0, half, 0));
    pole_ = world_->addBody(std::make_unique<btBoxShape>(btVector3(kPoleRadius, half, kPoleRadius)),
                            config_.poleMass, at);
    // The track: the cart slides along world x only (a slider frame's axis is its x axis; with
    // lower > upper linear limits it is free), and cannot turn (angular limits 0).
    btTransform frame;
    frame.setIdentity();
    auto slider = std::make_unique<btSliderConstraint>(*cart_, frame, true);
    slider->setLowerLinLimit(1);
    slider->setUpperLinLimit(-1);
    world_->addConstraint(std::move(slider));
    // The pole turns about z around the cart's centre.
    world_->addConstraint(std::make_unique<btHingeConstraint>(
        *cart_, *pole_, btVector3(0, 0, 0), btVector3(0, -half, 0), btVector3(0, 0, 1),
        btVector3(0, 0, 1)));

    SceneRandom random(seed);
    const double s = config_.startSpread;
    const double x = random.uniform(-s, s) * config_.trackLimit;
    const double v = random.uniform(-s, s) * config_.speedRange;
    const double a = random.uniform(-s, s) * radians(config_.angleLimitDegrees);
    const double w = random.uniform(-s, s) * radians(config_.angularSpeedRangeDegrees);
    setState(x, v, a, w);
}

void CartPoleScene::setState(double x, double velocity, double angle, double angularVelocity) {
    btTransform t;
    t.setIdentity();
    t.setOrigin(btVector3(static_cast<btScalar>(x), 0, 0));
    cart_->setWorldTransform(t);
    cart_->getMotionState()->setWorldTransform(t);
    const btVector3 cartVelocity(static_cast<btScalar>(velocity), 0, 0);
    cart_->setLinearVelocity(cartVelocity);
    cart_->setAngularVelocity(btVector3(0, 0, 0));
    cart_->clearForces();
    placeRod(*pole_, t.getOrigin(), config_.poleLength / 2, angle, angularVelocity, cartVelocity);
}

double CartPoleScene::position() const { return cart_->getCenterOfMassPosition().x(); }
double CartPoleScene::velocity() const { return cart_->getLinearVelocity().x(); }
double CartPoleScene::angle() const { return rodAngle(*pole_); }
double CartPoleScene::angularVelocity() const { return rodAngularVelocity(*pole_); }

bool CartPoleScene::failed() const {
    return std::abs(position()) > config_.trackLimit ||
           std::abs(angle()) > radians(config_.angleLimitDegrees);
}

void CartPoleScene::observe(Observation& out) const {
    out.discrete.clear();
    out.continuous.assign({toSensor(position(), config_.trackLimit),
                           toSensor(velocity(), config_.speedRange),
                           toSensor(angle(), radians(config_.angleLimitDegrees)),
                           toSensor(angularVelocity(), radians(config_.angularSpeedRangeDegrees))});
}

tasks::StepResult CartPoleScene::act(std::uint32_t action) {
    checkAction(name(), action, 3);
    const btScalar force = config_.maxForce * (static_cast<btScalar>(action) - 1);
    advance(*world_, config_.agentStep, config_.physicsStep,
            [&] { cart_->applyCentralForce(btVector3(force, 0, 0)); });
    if (failed()) return tasks::StepResult{-1.0f, true};
    return tasks::StepResult{1.0f, false};
}

}  // namespace verve::scenes
