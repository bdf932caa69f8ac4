// A Bullet dynamics world stepped in fixed sub-steps. Scenes rebuild one per trial, so a trial
// depends only on its seed (no solver caches or warm-start impulses carried over).
#pragma once
#include <memory>
#include <vector>

#include <btBulletDynamicsCommon.h>

namespace verve::scenes {

class PhysicsWorld {
public:
    explicit PhysicsWorld(const btVector3& gravity = btVector3(0, -9.81f, 0));
    ~PhysicsWorld();
    PhysicsWorld(const PhysicsWorld&) = delete;
    PhysicsWorld& operator=(const PhysicsWorld&) = delete;

    // A body the world owns. mass 0 makes it static. Never sleeps, no damping: the tasks are
    // defined without friction, and a sleeping pendulum would stop sensing.
    btRigidBody* addBody(std::unique_ptr<btCollisionShape> shape, btScalar mass,
                         const btTransform& transform);
    // The constraint is owned by the world; its bodies do not collide with each other.
    template <class C>
    C* addConstraint(std::unique_ptr<C> constraint) {
        C* raw = constraint.get();
        world_->addConstraint(raw, true);
        constraints_.push_back(std::move(constraint));
        return raw;
    }

    // Exactly one fixed sub-step of `subStep` seconds. Forces applied before it act during it.
    void step(btScalar subStep);

    btDiscreteDynamicsWorld& world() { return *world_; }

private:
    std::unique_ptr<btDefaultCollisionConfiguration> config_;
    std::unique_ptr<btCollisionDispatcher> dispatcher_;
    std::unique_ptr<btDbvtBroadphase> broadphase_;
    std::unique_ptr<btSequentialImpulseConstraintSolver> solver_;
    std::unique_ptr<btDiscreteDynamicsWorld> world_;
    std::vector<std::unique_ptr<btCollisionShape>> shapes_;
    std::vector<std::unique_ptr<btDefaultMotionState>> motionStates_;
    std::vector<std::unique_ptr<btRigidBody>> bodies_;
    std::vector<std::unique_ptr<btTypedConstraint>> constraints_;
};

// Advances `world` by `duration` in sub-steps of `subStep`, calling `applyForces()` before each
// sub-step (Bullet clears forces after every stepSimulation call).
template <class ApplyForces>
void advance(PhysicsWorld& world, btScalar duration, btScalar subStep, ApplyForces&& applyForces) {
    const int steps = static_cast<int>(duration / subStep + btScalar(0.5));
    for (int i = 0; i < steps; ++i) {
        applyForces();
        world.step(subStep);
    }
}

}  // namespace verve::scenes
