// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/plugin/SurfaceContactPoints.h>

namespace crumple::plugin
{

SurfacePoints SurfaceContactPoints(const ContactEvent& inContact)
{
    // Two distinct points: the engine already put them on the surfaces (Bullet's manifold points).
    if (inContact.mPointOnA != inContact.mPointOnB)
        return {inContact.mPointOnA, inContact.mPointOnB};
    // One point in the overlap: split the depth evenly along the normal (ODE's contact position).
    const Vec3 half_depth = 0.5 * inContact.mPenetrationDepth * inContact.mNormal;
    return {inContact.mPointOnA - half_depth, inContact.mPointOnA + half_depth};
}

} // namespace crumple::plugin
