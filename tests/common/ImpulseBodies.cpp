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

plugin::BodyState StaticGround()
{
    plugin::BodyState ground;
    ground.mMotionType = plugin::EMotionType::Static;
    return ground;
}

} // namespace crumple::common
