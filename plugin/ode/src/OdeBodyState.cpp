// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/ode/OdeBodyState.h>

#include <ode/ode.h>

#include <limits>

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

// Widens the box [ioLow, ioHigh] in inFrame by inGeom: exactly by a box geom's corners, by the corners of
// ODE's world bounding box for other classes (a plane's is infinite: stated out to the body state's range).
void AddGeomBounds(dGeomID inGeom, const Transform& inFrame, Vec3& ioLow, Vec3& ioHigh)
{
    const Vec3 bound = Vec3::Constant(plugin::cMaxBodyPosition);
    auto add = [&](const Vec3& inWorld) {
        const Vec3 local = inFrame.ToBody(inWorld.cwiseMax(-bound).cwiseMin(bound)).cwiseMax(-bound).cwiseMin(bound);
        ioLow = ioLow.cwiseMin(local);
        ioHigh = ioHigh.cwiseMax(local);
    };
    if (dGeomGetClass(inGeom) == dBoxClass)
    {
        dVector3 lengths;
        dGeomBoxGetLengths(inGeom, lengths);
        const Vec3 half = 0.5 * ToVec3(lengths);
        const Mat3 rotation = ToMat3(dGeomGetRotation(inGeom));
        const Vec3 centre = ToVec3(dGeomGetPosition(inGeom));
        for (int k = 0; k < 8; ++k)
            add(centre + rotation * Vec3((k & 1) ? half.x() : -half.x(), (k & 2) ? half.y() : -half.y(), (k & 4) ? half.z() : -half.z()));
        return;
    }
    dReal box[6];
    dGeomGetAABB(inGeom, box);
    for (int k = 0; k < 8; ++k)
        add(Vec3((k & 1) ? box[1] : box[0], (k & 2) ? box[3] : box[2], (k & 4) ? box[5] : box[4]));
}

void SetBounds(const Vec3& inLow, const Vec3& inHigh, plugin::BodyState& ioState)
{
    ioState.mHasShapeBounds = IsFinite(inLow) && IsFinite(inHigh) && (inLow.array() <= inHigh.array()).all();
    if (ioState.mHasShapeBounds)
    {
        ioState.mShapeMin = inLow;
        ioState.mShapeMax = inHigh;
    }
}

constexpr double cInf = std::numeric_limits<double>::infinity();

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
    Vec3 low = Vec3::Constant(cInf), high = Vec3::Constant(-cInf);
    for (dGeomID geom = dBodyGetFirstGeom(inBody); geom != nullptr; geom = dBodyGetNextGeom(geom))
        AddGeomBounds(geom, state.mTransform, low, high);
    SetBounds(low, high, state);
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
    Vec3 low = Vec3::Constant(cInf), high = Vec3::Constant(-cInf);
    AddGeomBounds(inGeom, state.mTransform, low, high);
    SetBounds(low, high, state);
    return state;
}

} // namespace crumple::ode
