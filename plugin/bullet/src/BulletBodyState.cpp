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

// The object's collision shape's bounding box in its own frame (Bullet's margin included); an unbounded
// shape (a static plane) is stated out to the body state's range.
void SetShapeBounds(const btCollisionObject& inObject, plugin::BodyState& ioState)
{
    const btCollisionShape* shape = inObject.getCollisionShape();
    if (shape == nullptr)
        return;
    btTransform identity;
    identity.setIdentity();
    btVector3 low, high;
    shape->getAabb(identity, low, high);
    const Vec3 bound = Vec3::Constant(plugin::cMaxBodyPosition);
    ioState.mShapeMin = ToVec3(low).cwiseMax(-bound).cwiseMin(bound);
    ioState.mShapeMax = ToVec3(high).cwiseMax(-bound).cwiseMin(bound);
    ioState.mHasShapeBounds = IsFinite(ioState.mShapeMin) && IsFinite(ioState.mShapeMax) &&
                              (ioState.mShapeMin.array() <= ioState.mShapeMax.array()).all();
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
    SetShapeBounds(inObject, state);

    const btRigidBody* body = btRigidBody::upcast(&inObject);
    // intent: a kinematic body made the usual Bullet way (mass 0, then CF_KINEMATIC_OBJECT added) keeps the
    // CF_STATIC_OBJECT that btRigidBody gave its zero mass: kinematic wins, as it does in Bullet's own step
    if (body == nullptr || (inObject.isStaticObject() && !inObject.isKinematicObject()))
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
