// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/ffd/TriangleMesh.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <vector>

namespace crumple::ffd
{

/// A mesh with some of its edges split, and where each added vertex came from.
struct CRUMPLE_API RefinedMesh
{
    TriangleMesh mMesh; ///< The input's vertices first, in their order, then the added ones; its triangles
    /// #added by 2: added vertex mMesh.mPositions.size() - mSplitParents.size() + k lies on the edge between
    /// vertices mSplitParents[k] (either may itself be an added vertex of a lower index), at
    /// (1 - f) p0 + f p1 with f = mSplitFractions[k]. A game carries its own vertex attributes (texture
    /// coordinates, colours, bone weights) over with the same weights.
    std::vector<std::array<std::uint32_t, 2>> mSplitParents;
    std::vector<double> mSplitFractions; ///< #added fractions f in (0, 1) (RefineLongEdges: 0.5, the midpoints)
};

/// Splits every edge longer than inMaxEdge at its midpoint until none is, keeping the mesh conforming (an
/// edge is split for every triangle that uses it, so a closed mesh stays closed), each triangle's
/// orientation, its plane and the total area.
///
/// Why: a dent is a smooth field sampled at the vertices, and a triangle shows it as the plane through its
/// three samples. A long thin triangle (a bumper strip 1.3 m wide and 6 cm deep) cannot follow a pole's
/// pocket that varies across it: its vertices move farther apart than the triangle is deep and it turns over
/// although the field folds nothing. Edges shorter than about a third of the lattice's control spacing follow
/// the field closely enough (crumple-crash's default, mesh_max_edge_m).
///
/// A triangle with one long edge becomes two, with two becomes three (the quad left over is cut along its
/// shorter diagonal), with three becomes four; passes repeat until no edge is longer. The result depends only
/// on the input (vertices are added in triangle order).
///
/// With inMaxBend below pi only edges whose triangles meet flat (their normals within inMaxBend of each
/// other) are split: where a curved surface is drawn with long triangles, a vertex added on one of them lies
/// on the flat triangle, not on the surface, and its normal (the flat triangles') shows as a streak in
/// shading; a flat panel is the same split or not. An exporter draws a curved surface with short triangles
/// already.
///
/// @param[in] inMesh        the mesh; ValidateTriangleMesh must accept it
/// @param[in] inMaxEdge     longest edge wanted (m), finite and > 0
/// @param[in] inMaxTriangles refuse (and return an error) rather than grow past this many triangles
/// @param[in] inMaxBend     largest angle between the normals of an edge's triangles for it to be split (rad,
///                          in [0, pi]; pi: every long edge)
/// @return the refined mesh, or an error for bad input or too many triangles (nothing is half-made)
CRUMPLE_API Result<RefinedMesh> RefineLongEdges(const TriangleMesh& inMesh, double inMaxEdge,
                                                std::size_t inMaxTriangles = 4'000'000,
                                                double inMaxBend = std::numbers::pi);

} // namespace crumple::ffd
