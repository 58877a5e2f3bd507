// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Math.h>
#include <crumple/plugin/Ids.h>

namespace crumple::plugin
{

/// One contact point as a rigid-body engine reports it after a step.
///
/// Conventions (Bullet's manifold points): mNormal points from B towards A; a positive penetration depth
/// means the bodies overlap by that much along the normal. Engines that report a single point (ODE's
/// dContactGeom::pos) put it in both mPointOnA and mPointOnB; SurfaceContactPoints() then moves it onto
/// each surface by half the depth.
struct CRUMPLE_API ContactEvent
{
    BodyId mBodyA;                   ///< First body
    BodyId mBodyB;                   ///< Second body (may be static: the world)
    Vec3 mPointOnA = Vec3::Zero();   ///< Contact point on A's surface, world frame (m)
    Vec3 mPointOnB = Vec3::Zero();   ///< Contact point on B's surface, world frame (m)
    Vec3 mNormal = Vec3::UnitZ();    ///< Unit contact normal from B towards A, world frame
    double mPenetrationDepth = 0.0;  ///< Overlap along the normal (m), > 0 when penetrating, < 0 for a gap
    double mFriction = 0.0;          ///< Coulomb friction coefficient of the two surfaces (dimensionless, >= 0;
                                     ///< +inf: they never slide); 0 gives frictionless impulses. The adapters
                                     ///< pass the engine's own (Bullet's combined friction, ODE's surface mu)
    double mTime = 0.0;              ///< Simulation time of the step that reported it (s)
};

} // namespace crumple::plugin
