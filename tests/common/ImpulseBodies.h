// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/plugin/BodyState.h>

namespace crumple::common
{

/// A solid sphere of inMass (kg) and inRadius (m), I = 2/5 m r^2, centred at inCentre, moving at inVelocity.
plugin::BodyState Sphere(double inMass, double inRadius, const Vec3& inCentre, const Vec3& inVelocity);

/// An immovable body (the ground, a wall).
plugin::BodyState StaticGround();

} // namespace crumple::common
