// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>
#include <crumple/base/Result.h>

#include <crumple/fem/TetMesh.h>

#include <array>
#include <cstdint>
#include <vector>

namespace crumple::fem
{

/// One triangle of the face two element groups share: an element of the link's first group and three of its
/// corner slots (0..3), ordered so that the triangle's normal points out of that element, towards the second
/// group. Reading the nodes through the current connectivity (GetElementNodes()[mElement][slot]) gives the
/// face as it is now.
struct CRUMPLE_API FractureLinkFace
{
    int mElement = 0;                  ///< Element of the link's group A
    std::array<std::uint8_t, 3> mCorners{}; ///< Corner slots of mElement, counter-clockwise seen from outside
};

/// The connectivity that fracture can cut, built once from the rest mesh. Element groups (the cubes of a
/// TetGrid, or single tetrahedra) are numbered densely 0..#G-1 in the order of their ids; a link joins two
/// groups that share a face (at least three nodes). Fracture marks links broken; FractureTopology() turns a
/// set of broken links into duplicated nodes. The same arrays describe the state for the CPU and the GPU
/// solver: a byte per link.
struct CRUMPLE_API FractureLinks
{
    std::vector<int> mGroupOfElement;              ///< #T dense group index of each element
    std::vector<int> mGroupIds;                    ///< #G the mesh's group id of each dense group
    std::vector<int> mGroupElementOffsets;         ///< #G+1 into mGroupElements
    std::vector<int> mGroupElements;               ///< #T elements by group, each group in element order
    std::vector<std::array<int, 2>> mLinkGroups;   ///< #L dense groups (A < B), sorted
    std::vector<Vec3> mLinkRestNormals;            ///< #L unit rest normal of the shared face, from A to B
    std::vector<int> mLinkFaceOffsets;             ///< #L+1 into mLinkFaces
    std::vector<FractureLinkFace> mLinkFaces;      ///< Triangles of each shared face
    std::vector<int> mLinkNodeOffsets;             ///< #L+1 into mLinkNodes
    std::vector<int> mLinkNodes;                   ///< Rest nodes the two groups share, ascending per link
    std::vector<int> mNodeGroupOffsets;            ///< #N+1 into mNodeGroups
    std::vector<int> mNodeGroups;                  ///< Dense groups touching each rest node, ascending
    std::vector<int> mNodeLinkOffsets;             ///< #N+1 into mNodeLinks
    std::vector<int> mNodeLinks;                   ///< Links sharing each rest node, ascending

    /// Number of dense groups #G
    int GetGroupCount() const { return static_cast<int>(mGroupIds.size()); }
    /// Number of links #L
    int GetLinkCount() const { return static_cast<int>(mLinkGroups.size()); }
};

/// Builds the links of a mesh: deterministic (every list is sorted), O(#T log #T).
/// @param[in] inMesh  a valid mesh; its group ids say which elements break away together
CRUMPLE_API FractureLinks BuildFractureLinks(const TetMesh& inMesh);

/// Checks that inLinks can describe a mesh of inElementCount elements and inNodeCount rest nodes: every
/// array's size, every offset table ascending and ending at its array's size, every group, link, element,
/// node and corner index in range, each node's groups strictly ascending (O(size of the links)). It does not check that they are the mesh's own
/// (BuildFractureLinks makes those), only that reading them cannot leave the arrays. FractureTopology and
/// OpenCracks refuse links that fail it.
CRUMPLE_API Status ValidateFractureLinks(const FractureLinks& inLinks, int inElementCount, int inNodeCount);

} // namespace crumple::fem
