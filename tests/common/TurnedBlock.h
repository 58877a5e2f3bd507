// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/plugin/ConvexBodySettings.h>
#include <crumple/plugin/PropBodySettings.h>

namespace crumple::common
{

/// The adapters' convex-body tests' block: 0.6 x 0.1 x 0.2 m, 12 kg (a uniform box's moments), turned 0.9 rad
/// about an oblique axis at (2, 1, 0.5) m, moving at (3, -1, 0.5) m/s and spinning at (0.5, 2, -1) rad/s. Its
/// hull points are the box's corners, shifted along the body's z by inHullOffsetZ (m): 0 centres them on the
/// centre of mass.
plugin::ConvexBodySettings TurnedBlock(double inHullOffsetZ = 0.0);

/// The adapters' prop-body tests' slab: TurnedBlock's mass, inertia and pose, at rest, its shape the block's
/// two halves along x as two pieces; held unless inHeld is false.
plugin::PropBodySettings TurnedSlab(bool inHeld = true);

} // namespace crumple::common
