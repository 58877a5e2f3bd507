// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Result.h>
#include <crumple/fem/TetMesh.h>

#include <string_view>
#include <vector>

namespace crumple::fem
{

/// What tetgen wrote: its nodes and its tetrahedra (not yet checked against the surface it was given).
struct CRUMPLE_API TetgenOutput
{
    std::vector<Vec3> mNodes;      ///< In tetgen's order (m)
    std::vector<TetIndices> mTets; ///< Indices into mNodes, from 0
};

/// Reads tetgen's output pair, the text of <name>.1.node ("count 3 #attributes #markers", then "index x y z
/// ...") and <name>.1.ele ("count 4 #attributes", then "index n0 n1 n2 n3 ..."), numbered from 0 or 1; "#"
/// starts a comment. Refused with EError::CorruptData naming the file and the line: a bad header, too few
/// lines, a malformed number, a coordinate that is not finite, indices that do not count up, a node out of range, more than
/// TetMesh::cMaxCount entries. Tetrahedralize reads tetgen's files with it.
CRUMPLE_API Result<TetgenOutput> ParseTetgenOutput(std::string_view inNodeText, std::string_view inElementText);

} // namespace crumple::fem
