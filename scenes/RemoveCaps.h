// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Result.h>
#include <crumple/ffd/TriangleMesh.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace crumple::samples
{

/// What RemoveCaps did to a mesh.
struct CapRemoval
{
    std::size_t mFlips = 0;         ///< Cap edges flipped within the deviation (ffd::FlipNearlyFlatEdges)
    std::size_t mSplitVertices = 0; ///< Vertices added where caps were split (ffd::SplitCaps)
    std::size_t mFlipProneVertices = 0; ///< Vertices added where flip-prone triangles were split
                                        ///< (ffd::SplitFlipProneTriangles)
};

/// Takes the caps out of a mesh whose vertices carry positions only (flips join the sides of a seam): the
/// caps' long edges flipped where that moves the surface by inFlipDeviation at most (none when it is 0),
/// then the caps no flip removed split at their feet, the two alternating until no cap is left (32 rounds
/// at most). A cap is a triangle with a corner of 150 degrees or more: a dent's smooth field turns such
/// triangles over although it folds nothing (ffd::SplitCaps says why). The rigid parts' vertex lists follow
/// the added vertices. With a bend curvature each round also splits the triangles a dent bending the surface
/// that much could turn over although no corner makes them caps (ffd::SplitFlipProneTriangles: long thin
/// triangles); the flips between rounds remove the caps such splits leave in fans of thin neighbours.
/// @param[in,out] ioMesh          the body (m); on error it may be partly changed
/// @param[in,out] ioRigidParts    vertex lists of the parts that move rigidly (wheels)
/// @param[in]     inFlipDeviation how far a flip may move the surface (m), >= 0
/// @param[in]     inBendCurvature the dents' largest bend the triangles must show without turning over (1/m);
///                                0: caps only
/// @return what was done, or the first step's error (a deviation or curvature that is negative or not
///         finite: refused, the mesh unchanged)
Result<CapRemoval> RemoveCaps(ffd::TriangleMesh& ioMesh,
                              std::vector<std::vector<std::uint32_t>>& ioRigidParts, double inFlipDeviation,
                              double inBendCurvature = 0.0);

} // namespace crumple::samples
