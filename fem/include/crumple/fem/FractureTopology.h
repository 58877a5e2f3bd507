// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/fem/FractureLinks.h>

#include <cstdint>
#include <span>
#include <vector>

namespace crumple::fem
{

/// Element connectivity after fracture: where links are broken, the nodes on them are duplicated.
struct CRUMPLE_API FractureConnectivity
{
    std::vector<TetIndices> mElementNodes; ///< #T current element -> node indices
    std::vector<int> mNodeOrigin;          ///< #N' rest node each current node is a copy of (identity for i < N)
};

/// Node duplication from a set of broken links, a pure function of that set (so the same cracks give the same
/// numbering whatever order they opened in). At each rest node the groups touching it are joined by the
/// unbroken links through it; each resulting cluster is one node. The cluster with the lowest group keeps
/// the rest node's index, the others get new indices appended in order of rest node, then lowest group.
/// With no broken link the result is the mesh's own connectivity when groups sharing a node are joined
/// through faces around it (any grid of whole cubes); groups that touch only along an edge or at a corner
/// (a masked grid) have no link there and get separate nodes.
/// @param[in] inMesh    the rest mesh the links were built from
/// @param[in] inLinks   BuildFractureLinks(inMesh)
/// @param[in] inBroken  #L, nonzero where a link is broken
/// Refused when the links fail ValidateFractureLinks for the mesh or are not its own where they are read (a
/// group missing from a node it touches), or inBroken's size is not #L.
CRUMPLE_API Result<FractureConnectivity> FractureTopology(const TetMesh& inMesh, const FractureLinks& inLinks,
                                                          std::span<const std::uint8_t> inBroken);

} // namespace crumple::fem
