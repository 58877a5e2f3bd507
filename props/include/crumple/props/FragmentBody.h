// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Result.h>
#include <crumple/fem/TetFragment.h>
#include <crumple/plugin/BodyState.h>
#include <crumple/plugin/ConvexBodySettings.h>

#include <span>

namespace crumple::props
{

/// A loose fragment of a prop as a rigid body (FragmentBody).
struct CRUMPLE_API FragmentRigidBody
{
    plugin::ConvexBodySettings mBody;      ///< For an engine adapter's CreateConvexBody
    double mNodalKineticEnergy = 0.0;      ///< The fragment's nodes' kinetic energy, world frame (J)
    double mRigidKineticEnergy = 0.0;      ///< The rigid body's (J), at most mNodalKineticEnergy (for a prop body at rest)
    double mAngularMomentumChange = 0.0;   ///< |L_body - L_nodes| about the body's centre of mass (kg m^2/s)
};

/// The rigid body a fragment that broke loose from a prop becomes in the engine (issue: fragments as engine
/// bodies). Mass, centre of mass and inertia are the fragment's own (fem::TetFragments: exact tetrahedron
/// integrals); the body frame is the centre of mass along the principal axes (a right-handed eigenbasis of the
/// inertia, moments ascending); the hull points are the fragment's nodes.
///
/// Velocities from the nodes' (lumped masses m_i, velocities v_i): the body's momentum is exactly the nodes',
/// M v = sum m_i v_i, and its spin is the nodes' least-squares rigid spin, w = J^-1 sum m_i r_i x v_i with r_i
/// the nodes' offsets from their mass centre and J their (lumped) inertia, so a rigid motion of the nodes keeps
/// its spin exactly. The body's kinetic energy never exceeds the nodes': the rigid part of the nodes' motion
/// has energy M v^2 / 2 + w.J w / 2, and the exact inertia I is below J (each tetrahedron's own second moment is
/// a fifth of its lumped corners'). The body's angular momentum I w differs from the nodes' by the same
/// inertia difference (and by what did not move rigidly); mAngularMomentumChange reports it.
///
/// Positions and velocities are in the frame of the prop's body (the frame its solver works in), whose state
/// inPropBody maps them to the world: x_world = T x, v_world = R v + the body's velocity at x_world.
/// @param[in] inFragment   the fragment (fem::TetFragment), not anchored
/// @param[in] inPositions  #N node positions, prop frame (m)
/// @param[in] inVelocities #N node velocities, prop frame (m/s)
/// @param[in] inMasses     #N lumped node masses (kg), finite and >= 0; the fragment's nodes' must add up to
///                         at least its mass (to 1e-9), as the lumped masses of its elements do
/// @param[in] inPropBody   the prop body's state (its transform; its velocities unless static)
CRUMPLE_API Result<FragmentRigidBody> FragmentBody(const fem::TetFragment& inFragment, std::span<const Vec3> inPositions,
                                       std::span<const Vec3> inVelocities, std::span<const double> inMasses,
                                       const plugin::BodyState& inPropBody);

} // namespace crumple::props
