// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/plugin/BodyState.h>

namespace crumple::common
{

/// A solid sphere of inMass (kg) and inRadius (m), I = 2/5 m r^2, centred at inCentre, moving at inVelocity.
plugin::BodyState Sphere(double inMass, double inRadius, const Vec3& inCentre, const Vec3& inVelocity);

/// A uniform box car of inMass (kg) and inHalfExtents (m), its front face (+x) on the plane x = 0, moving
/// along +x at inSpeed (m/s): the test worlds' car before a wall at x = 0.
plugin::BodyState BoxCarBeforeWall(double inMass, const Vec3& inHalfExtents, double inSpeed);

/// An immovable body (the ground, a wall).
plugin::BodyState StaticGround();

} // namespace crumple::common
