// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/ode/OdeBodyState.h>

#include <ode/ode.h>

namespace crumple::ode
{

namespace
{

Vec3 ToVec3(const dReal* inV)
{
    return {static_cast<double>(inV[0]), static_cast<double>(inV[1]), static_cast<double>(inV[2])};
}

// ODE's dMatrix3 is 3 rows of 4 (the last column is padding).
Mat3 ToMat3(const dReal* inM)
{
    Mat3 m;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            m(r, c) = static_cast<double>(inM[r * 4 + c]);
    return m;
}

} // namespace

plugin::BodyState OdeBodyState(dBodyID inBody)
{
    plugin::BodyState state;
    const Mat3 rotation = ToMat3(dBodyGetRotation(inBody));
    state.mTransform.mRotation = Quat(rotation).normalized().toRotationMatrix();
    state.mTransform.mTranslation = ToVec3(dBodyGetPosition(inBody));
    state.mCenterOfMass = state.mTransform.mTranslation;
    state.mLinearVelocity = ToVec3(dBodyGetLinearVel(inBody));
    state.mAngularVelocity = ToVec3(dBodyGetAngularVel(inBody));
    if (dBodyIsKinematic(inBody) != 0)
    {
        state.mMotionType = plugin::EMotionType::Kinematic;
        return state;
    }
    dMass mass;
    dBodyGetMass(inBody, &mass);
    state.mMass = static_cast<double>(mass.mass);
    // World inverse inertia: R I^-1 R^T with I about the centre of mass in the body frame.
    const Mat3 inertia = ToMat3(mass.I);
    const Mat3 inverse_world = state.mTransform.mRotation * inertia.inverse() * state.mTransform.mRotation.transpose();
    state.mInverseInertiaWorld = 0.5 * (inverse_world + inverse_world.transpose());
    return state;
}

plugin::BodyState OdeStaticGeomState(dGeomID inGeom)
{
    plugin::BodyState state;
    state.mMotionType = plugin::EMotionType::Static;
    if (dGeomGetClass(inGeom) != dPlaneClass)
    {
        state.mTransform.mRotation = Quat(ToMat3(dGeomGetRotation(inGeom))).normalized().toRotationMatrix();
        state.mTransform.mTranslation = ToVec3(dGeomGetPosition(inGeom));
    }
    state.mCenterOfMass = state.mTransform.mTranslation;
    return state;
}

} // namespace crumple::ode
