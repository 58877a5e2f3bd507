// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Result.h>
#include <crumple/fem/TetMesh.h>
#include <crumple/plugin/PropBodySettings.h>

#include <cstdint>
#include <span>
#include <vector>

namespace crumple::props
{

/// A prop made into an engine body: its mesh moved into the body's frame, and the body for an adapter.
struct CRUMPLE_API PropBody
{
    fem::TetMesh mMesh;             ///< The prop's mesh in the body frame: build the FemProp from it
    plugin::PropBodySettings mBody; ///< For BulletAdapter::CreatePropBody / OdeAdapter::CreatePropBody
    Transform mMeshToBody;          ///< x_body = mMeshToBody.ToWorld(x_mesh): node indices are unchanged
};

/// Places a destructible prop in the world as an engine body (plugin::PropBodySettings). Engines need the
/// body frame at the centre of mass along the principal axes of inertia; the prop's FEM works in its body's
/// frame (PropWorld); so the mesh is moved into that frame. Mass, centre of mass and inertia are the exact
/// integrals over the tetrahedra at density inDensity (a tetrahedron's second moment is m / 20 (sum x_i x_i^T
/// + s s^T), s = sum x_i); the axes are a right-handed eigenbasis, moments ascending. The shape is
/// PropCollisionPieces of the whole mesh. A held body (inHeld: a prop anchored to the ground) is put back at
/// its pose by the adapter after every step (PropBodySettings).
/// @param[in] inMesh      the prop's rest mesh, in its own frame (m)
/// @param[in] inDensity   kg/m^3, finite and > 0 (its material's)
/// @param[in] inPose      the mesh's frame in the world
/// @param[in] inHeld      PropBodySettings::mHeld
/// @param[in] inCellSize  edge of the shape's pieces (m), finite and > 0: about the prop's smallest member
///                        that can break away, so a piece that leaves takes its part of the shape with it
/// @return refused with a message for bad arguments, a non-rotation pose or a prop the engines cannot hold
///         (PropBodySettings' ranges)
CRUMPLE_API Result<PropBody> MakePropBody(const fem::TetMesh& inMesh, double inDensity, const Transform& inPose, bool inHeld,
                              double inCellSize);

/// The collision shape of a prop's elements as convex pieces: each element goes to the cube of edge
/// inCellSize (a grid from the origin) that holds its centroid, and each non-empty cube gives one piece, the
/// positions of its elements' nodes (deduplicated, ascending node order). Pieces come in cube order (z, then
/// y, then x), so the same prop gives the same pieces. Elements marked in inLeftOut (one byte each; may be
/// empty) are left out: the pieces that broke loose and left as bodies of their own.
/// @param[in] inPositions  #N node positions (m), the body frame
/// @param[in] inElements   #T elements' node indices
/// @param[in] inLeftOut    #T flags, or empty
/// @param[in] inCellSize   cube edge (m), finite and > 0
/// @return refused for a cell size that is not finite and > 0, an element naming a node that is not in
///         inPositions, a position that is not finite, or a cell size so small against the positions that a
///         cube's index would not be exact (|x| / inCellSize beyond 2^52)
CRUMPLE_API Result<std::vector<std::vector<Vec3>>> PropCollisionPieces(std::span<const Vec3> inPositions,
                                                                       std::span<const fem::TetIndices> inElements,
                                                                       std::span<const std::uint8_t> inLeftOut, double inCellSize);

} // namespace crumple::props
