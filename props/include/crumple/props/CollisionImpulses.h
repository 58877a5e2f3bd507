// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Result.h>
#include <crumple/fem/TetMesh.h>
#include <crumple/fem/TetSolver.h>
#include <crumple/plugin/Collision.h>

#include <span>
#include <vector>

namespace crumple::props
{

/// An impulse on one node of a prop.
struct CRUMPLE_API NodalImpulse
{
    int mNode = 0;                  ///< Current node index
    Vec3 mImpulse = Vec3::Zero();   ///< N s, in the prop's body frame
};

/// Turns the contacts of a dispatched collision (the core's plugin::Collision) into nodal impulses on a
/// prop. The prop's solver works in its body's frame, so each contact is read in that frame: its local point
/// (mLocalPointOnA/B) and its impulse along the local normal (+j n on body A, -j n on body B). Each contact
/// impulse goes to the four nodes of the element that contains its point, by the point's barycentric
/// coordinates (of the nearest element, with negative coordinates clamped and the rest renormalised, when the
/// point lies on or just off the surface). Inside an element this keeps the total impulse and its moment
/// about any point exactly. O(#T) to prepare, then O(#T) per contact.
/// @param[in] inCollision     a collision one of whose bodies is the prop
/// @param[in] inPropBody      the prop's body id (mBodyA or mBodyB of inCollision)
/// @param[in] inElementNodes  #T current connectivity (TetSolver::GetElementNodes())
/// @param[in] inPositions     #N current node positions (m, body frame)
/// @return impulses in contact order, four per contact; refused when the prop is not in the collision, the
///         mesh is empty, an element names a node that is not in inPositions, or a contact is not finite
CRUMPLE_API Result<std::vector<NodalImpulse>> CollisionNodalImpulses(const plugin::Collision& inCollision,
                                                         plugin::BodyId inPropBody,
                                                         std::span<const fem::TetIndices> inElementNodes,
                                                         std::span<const Vec3> inPositions);

/// How a contact's impulse is shared among a prop's nodes beyond the element that contains its point.
struct CRUMPLE_API ContactSpread
{
    /// Footprint radius (m, finite, >= 0). 0: the four nodes of the containing element (the default, as
    /// before). Above 0: every free node within the radius of the contact point takes a share proportional to
    /// its mass times (1 - d^2 / r^2)^2 (d its distance from the point), so the struck material gets a smooth
    /// velocity change that peaks at the point, instead of the element's few light nodes taking it all.
    double mRadius = 0.0;
    std::span<const double> mMasses;        ///< #N lumped node masses (kg), needed when mRadius > 0
    std::span<const double> mInverseMasses; ///< #N, 0 for a fixed node (which takes no share)
};

/// A contact spread radius (m) is finite and >= 0; refused with a message naming inWho otherwise.
CRUMPLE_API Status CheckContactSpreadRadius(double inRadius, const char* inWho);

/// CollisionNodalImpulses with each contact's impulse spread over its footprint (ContactSpread). The total
/// impulse is kept exactly; its moment about the contact point only as far as the footprint's nodes balance
/// around the point. On a flat face struck square on they lie behind it along the normal and the error is
/// small; it grows with the normal's tilt and near edges and rims (a thin rail, a post), up to about
/// radius x impulse. A contact with no free node within the radius (a mesh coarser than the footprint, or
/// only fixed nodes in reach) falls back to its element's four nodes. With a radius of 0 the result is
/// CollisionNodalImpulses' bit for bit. O(#T) to prepare (the element search, for the fallback), then O(#N)
/// per spread contact and O(#T) per contact that falls back. Refused as CollisionNodalImpulses, and for a
/// radius that is not finite and >= 0 or, when the radius is above 0, for masses and inverse masses that are
/// not one per node, a mass that is not finite and > 0, or an inverse mass that is not finite and >= 0.
CRUMPLE_API Result<std::vector<NodalImpulse>> CollisionNodalImpulses(const plugin::Collision& inCollision,
                                                         plugin::BodyId inPropBody,
                                                         std::span<const fem::TetIndices> inElementNodes,
                                                         std::span<const Vec3> inPositions,
                                                         const ContactSpread& inSpread);

/// Whether nodal impulses can all be applied: refused, naming the node, when one would leave a node's
/// velocity (inVelocities + inInverseMasses x its impulses so far, added in order as a solver adds them) not
/// finite or, in any component, beyond inLimit (m/s; a GPU solver's float range). Lets an application be all
/// or nothing.
CRUMPLE_API Status CheckNodalImpulses(std::span<const NodalImpulse> inImpulses, std::span<const Vec3> inVelocities,
                                      std::span<const double> inInverseMasses, double inLimit);

/// Applies CollisionNodalImpulses() to a solver (waking it). All or nothing: a refused collision changes
/// nothing.
CRUMPLE_API Status ApplyCollision(fem::TetSolver& ioSolver, const plugin::Collision& inCollision, plugin::BodyId inPropBody);

} // namespace crumple::props
