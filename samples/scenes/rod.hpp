// A thin rod swinging in the x-y plane about a pivot at one end (the pendulum, the cart's pole).
// Angle 0 is upright; positive angles lean the free end toward +x.
#pragma once
#include <cmath>

#include <btBulletDynamicsCommon.h>

namespace verve::scenes {

// The rod's lean from upright in radians, in [-pi, pi], from its body orientation.
inline double rodAngle(const btRigidBody& rod) {
    const btVector3 up = rod.getWorldTransform().getBasis().getColumn(1);  // pivot -> free end
    return std::atan2(static_cast<double>(up.x()), static_cast<double>(up.y()));
}

// Angular velocity in the lean direction (rad/s).
inline double rodAngularVelocity(const btRigidBody& rod) {
    return -static_cast<double>(rod.getAngularVelocity().z());
}

// Places the rod at `angle` about `pivot`, turning at `angularVelocity`, while the pivot moves
// at `pivotVelocity`: a consistent rigid-body state for the hinge to keep.
inline void placeRod(btRigidBody& rod, const btVector3& pivot, btScalar halfLength, double angle,
                     double angularVelocity, const btVector3& pivotVelocity) {
    const btScalar a = static_cast<btScalar>(angle);
    const btVector3 axis(btSin(a), btCos(a), 0);  // pivot -> free end
    btTransform t;
    t.setIdentity();
    t.setRotation(btQuaternion(btVector3(0, 0, 1), -a));
    t.setOrigin(pivot + axis * halfLength);
    rod.setWorldTransform(t);
    rod.getMotionState()->setWorldTransform(t);
    const btVector3 omega(0, 0, -static_cast<btScalar>(angularVelocity));
    rod.setAngularVelocity(omega);
    rod.setLinearVelocity(pivotVelocity + omega.cross(axis * halfLength));
    rod.clearForces();
}

}  // namespace verve::scenes
