// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Result.h>
#include <crumple/ffd/TriangleMesh.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace crumple::crash
{

/// How a mesh body was prepared for the crash (VehicleSpec::mMeshMaxEdge and mMeshFlipDeviation): the
/// surface is the file's, its triangles are not.
struct MeshPreparation
{
    std::size_t mFileTriangles = 0;   ///< As loaded (the meshes mesh_name kept)
    std::size_t mFileVertices = 0;    ///< As loaded
    std::size_t mTriangles = 0;       ///< After the re-cut: the mesh the crash deforms
    std::size_t mVertices = 0;        ///< After the re-cut (midpoints added)
    double mMaxEdge = 0.0;            ///< The re-cut's longest edge (m); 0: no re-cut
    std::size_t mFlatFlips = 0;       ///< Edges flipped in exactly flat parts (ffd::FlipFlatEdges, both passes)
    double mFlipDeviation = 0.0;      ///< How far a flip of a nearly flat pair may move the surface (m)
    std::size_t mNearlyFlatFlips = 0; ///< Edges flipped within mFlipDeviation (ffd::FlipNearlyFlatEdges)
    std::size_t mCapSplitVertices = 0; ///< Vertices added where the caps left were split (ffd::SplitCaps)
    std::size_t mLooseSlivers =
        0; ///< Zero-area triangles that bounded nothing, removed (ffd::DropLooseSlivers)
};

/// Re-cuts a loaded car body so that a dent's smooth field can be sampled at its vertices without turning
/// triangles over: the zero-area triangles that bound nothing removed (ffd::DropLooseSlivers: a cap split
/// there would split the surface beside it), the flat parts made Delaunay (ffd::FlipFlatEdges), every edge
/// longer than inMaxEdge split at its midpoint (ffd::RefineLongEdges), the flat parts made Delaunay again,
/// then the nearly flat ones within inFlipDeviation, across texture seams (ffd::FlipNearlyFlatEdges: a
/// crash's mesh carries positions only), and the caps no flip removed split at their feet (ffd::SplitCaps;
/// both take caps as triangles with a corner of 150 degrees or more). The rigid parts' vertex lists follow
/// the added vertices (samples::PartsAfterRefinement).
/// @param[in,out] ioMesh        the body, body frame (m); on error it may be partly re-cut
/// @param[in,out] ioRigidParts  vertex lists of the parts that move rigidly (wheels)
/// @param[in]     inMaxEdge     longest edge wanted (m), >= 0; 0: the triangles stay as they are
/// @param[in]     inFlipDeviation how far a nearly flat flip may move the surface (m), >= 0; 0: none
/// @return what was done, or the first step's error
Result<MeshPreparation> RecutCarMesh(ffd::TriangleMesh& ioMesh, std::vector<std::vector<std::uint32_t>>& ioRigidParts,
                                     double inMaxEdge, double inFlipDeviation);

} // namespace crumple::crash
