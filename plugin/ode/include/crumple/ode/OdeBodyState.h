// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/plugin/BodyState.h>

#include <ode/common.h>

namespace crumple::ode
{

/// The state a Baraff impulse needs, read from an ODE body. ODE keeps a body's centre of mass at its
/// origin, so the body frame is the centre-of-mass frame: deformable meshes attached to it are given in it.
/// The state's shape bounds cover the body's geoms in that frame (a box geom exactly, others by ODE's world
/// bounding box).
CRUMPLE_API plugin::BodyState OdeBodyState(dBodyID inBody);

/// The state of a static geom (no body): static, at the geom's position and rotation.
CRUMPLE_API plugin::BodyState OdeStaticGeomState(dGeomID inGeom);

} // namespace crumple::ode
