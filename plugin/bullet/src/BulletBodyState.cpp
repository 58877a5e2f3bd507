// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/bullet/BulletBodyState.h>

#include <btBulletDynamicsCommon.h>

namespace crumple::bullet
{

namespace
{

Vec3 ToVec3(const btVector3& inV)
{
    return {static_cast<double>(inV.x()), static_cast<double>(inV.y()), static_cast<double>(inV.z())};
}

Mat3 ToMat3(const btMatrix3x3& inM)
{
    Mat3 m;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            m(r, c) = static_cast<double>(inM[r][c]);
    return m;
}

} // namespace

plugin::BodyState BulletBodyState(const btCollisionObject& inObject)
{
    plugin::BodyState state;
    const btTransform& transform = inObject.getWorldTransform();
    // Bullet is single precision here: re-orthonormalize so the state passes the rotation check exactly.
    state.mTransform.mRotation = Quat(ToMat3(transform.getBasis())).normalized().toRotationMatrix();
    state.mTransform.mTranslation = ToVec3(transform.getOrigin());
    state.mCenterOfMass = state.mTransform.mTranslation;

    const btRigidBody* body = btRigidBody::upcast(&inObject);
    if (body == nullptr || inObject.isStaticObject())
    {
        state.mMotionType = plugin::EMotionType::Static;
        return state;
    }
    state.mLinearVelocity = ToVec3(body->getLinearVelocity());
    state.mAngularVelocity = ToVec3(body->getAngularVelocity());
    if (inObject.isKinematicObject() || body->getInvMass() == btScalar(0))
    {
        state.mMotionType = plugin::EMotionType::Kinematic;
        return state;
    }
    state.mMass = 1.0 / static_cast<double>(body->getInvMass());
    const Mat3 inverse_inertia = ToMat3(body->getInvInertiaTensorWorld());
    state.mInverseInertiaWorld = 0.5 * (inverse_inertia + inverse_inertia.transpose());
    state.mCenterOfMass = ToVec3(body->getCenterOfMassPosition());
    return state;
}

} // namespace crumple::bullet
