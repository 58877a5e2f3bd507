// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/plugin/ContactEvent.h>

namespace crumple::plugin
{

/// A contact's points on the two surfaces, world frame (m).
struct CRUMPLE_API SurfacePoints
{
    Vec3 mOnA = Vec3::Zero(); ///< On A's surface (inside B when penetrating)
    Vec3 mOnB = Vec3::Zero(); ///< On B's surface (inside A when penetrating)
};

/// Moves a reported contact onto the body surfaces using the penetration depth (D4MD section 6.2: engines
/// let bodies interpenetrate, so a reported point lies inside a body).
/// With the normal n from B to A and depth d, the surfaces satisfy onA = onB - n d. When the engine gave two
/// distinct points they are already on the surfaces and are kept; when it gave one point p (both fields
/// equal), p is taken as the midpoint of the overlap: onA = p - n d/2, onB = p + n d/2.
CRUMPLE_API SurfacePoints SurfaceContactPoints(const ContactEvent& inContact);

} // namespace crumple::plugin
