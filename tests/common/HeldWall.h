// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/plugin/ConvexBodySettings.h>
#include <crumple/plugin/PropBodySettings.h>

namespace crumple::common
{

/// A held prop body for the adapters' contact-mass tests: a 4 m x 1 m x 0.1 m plate of 50 kg, its faces
/// along x (at x = +-0.05), its centre at the origin, one piece.
plugin::PropBodySettings HeldWall();

/// A 10 kg octahedron, its tips 0.1 m from its centre along the axes, at (-0.3, inY, 0), moving along +x at
/// 5 m/s towards HeldWall's face, not turning.
plugin::ConvexBodySettings WallBall(double inY);

/// The impulse (N s) WallBall takes in one step, from its speed after it (m/s): M (5 - v).
double WallBallImpulse(double inSpeedAfter);

/// The reduced mass M m / (M + m) of WallBall and a body it meets as a point mass of inContactMass (kg): what
/// a contact's impulse is proportional to, whatever the engine's push out of the penetration adds to the
/// approach speed (so ratios of impulses are ratios of these).
double WallBallReducedMass(double inContactMass);

} // namespace crumple::common
