// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "ImpulseBodies.h"

namespace crumple::common
{

plugin::BodyState Sphere(double inMass, double inRadius, const Vec3& inCentre, const Vec3& inVelocity)
{
    plugin::BodyState state;
    state.mMass = inMass;
    state.mInverseInertiaWorld = Mat3::Identity() / (0.4 * inMass * inRadius * inRadius);
    state.mTransform.mTranslation = inCentre;
    state.mCenterOfMass = inCentre;
    state.mLinearVelocity = inVelocity;
    return state;
}

plugin::BodyState BoxCarBeforeWall(double inMass, const Vec3& inHalfExtents, double inSpeed)
{
    plugin::BodyState car;
    car.mMass = inMass;
    const Vec3 size = 2.0 * inHalfExtents;
    car.mInverseInertiaWorld = Vec3(12.0 / (inMass * (size.y() * size.y() + size.z() * size.z())),
                                    12.0 / (inMass * (size.x() * size.x() + size.z() * size.z())),
                                    12.0 / (inMass * (size.x() * size.x() + size.y() * size.y())))
                                   .asDiagonal();
    car.mTransform.mTranslation = Vec3(-inHalfExtents.x(), 0.0, 0.0);
    car.mCenterOfMass = car.mTransform.mTranslation;
    car.mLinearVelocity = Vec3(inSpeed, 0.0, 0.0);
    return car;
}

plugin::BodyState StaticGround()
{
    plugin::BodyState ground;
    ground.mMotionType = plugin::EMotionType::Static;
    return ground;
}

} // namespace crumple::common
