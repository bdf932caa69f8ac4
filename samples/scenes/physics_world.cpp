#include "physics_world.hpp"

namespace verve::scenes {

PhysicsWorld::PhysicsWorld(const btVector3& gravity)
    : config_(std::make_unique<btDefaultCollisionConfiguration>()),
      dispatcher_(std::make_unique<btCollisionDispatcher>(config_.get())),
      broadphase_(std::make_unique<btDbvtBroadphase>()),
      solver_(std::make_unique<btSequentialImpulseConstraintSolver>()),
      world_(std::make_unique<btDiscreteDynamicsWorld>(dispatcher_.get(), broadphase_.get(),
                                                       solver_.get(), config_.get())) {
    world_->setGravity(gravity);
    // Like the thesis's ODE "quickstep with 20 iterations".
    world_->getSolverInfo().m_numIterations = 20;
    // Stiff joint error correction: at the default 0.2 a free pendulum at 0.01 s steps loses 15%
    // of its energy in 20 s (the hinge's drift correction eats it); at 0.8 it keeps it within 3%.
    world_->getSolverInfo().m_erp = 0.8f;
}

PhysicsWorld::~PhysicsWorld() {
    // Constraints and bodies leave the world before their memory goes.
    for (auto& c : constraints_) world_->removeConstraint(c.get());
    for (auto& b : bodies_) world_->removeRigidBody(b.get());
}

btRigidBody* PhysicsWorld::addBody(std::unique_ptr<btCollisionShape> shape, btScalar mass,
                                   const btTransform& transform) {
    btVector3 inertia(0, 0, 0);
    if (mass > 0) shape->calculateLocalInertia(mass, inertia);
    auto motion = std::make_unique<btDefaultMotionState>(transform);
    btRigidBody::btRigidBodyConstructionInfo info(mass, motion.get(), shape.get(), inertia);
    info.m_linearDamping = 0;
    info.m_angularDamping = 0;
    info.m_friction = 0;
    auto body = std::make_unique<btRigidBody>(info);
    body->setActivationState(DISABLE_DEACTIVATION);
    world_->addRigidBody(body.get());
    btRigidBody* raw = body.get();
    shapes_.push_back(std::move(shape));
    motionStates_.push_back(std::move(motion));
    bodies_.push_back(std::move(body));
    return raw;
}

void PhysicsWorld::step(btScalar subStep) {
    // timeStep == fixedTimeStep with maxSubSteps 1: exactly one internal step, no interpolation.
    world_->stepSimulation(subStep, 1, subStep);
}

}  // namespace verve::scenes
