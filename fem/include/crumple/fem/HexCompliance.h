// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace crumple::fem
{

/// Precomputed compliance ("instant quasi-static dents"): the block of K^-1 (fixed nodes eliminated) that maps
/// forces on chosen load nodes to displacements of chosen output nodes, so that a dent is one dense
/// matrix-vector product, U_out = C F_load (HexComplianceSolve). Built by HexCompliancePrecompute, saved and
/// loaded by SaveHexCompliance / LoadHexCompliance, so that a game can ship it instead of the mesh solver.
/// Memory: 72 #output #load bytes (9 doubles per node pair).
struct CRUMPLE_API HexCompliance
{
    int mNodeCount = 0;              ///< Nodes of the mesh it was computed for
    std::uint32_t mSourceCrc = 0;    ///< HexSourceCrc of that mesh, material and fixed nodes
    std::vector<int> mLoadNodes;     ///< Nodes that may carry a force, no repeats, in column order
    std::vector<int> mOutputNodes;   ///< Nodes whose displacement is returned, no repeats, in row order
    /// 3 #output by 3 #load compliance (m/N): entry (3 o + b, 3 l + a) is the displacement of mOutputNodes[o]
    /// along axis b for a unit force on mLoadNodes[l] along axis a (axes x, y, z, body frame). Rows of fixed
    /// output nodes and columns of fixed load nodes are zero (supports take their forces). Symmetric when the
    /// two node lists are equal (Maxwell-Betti reciprocity).
    Eigen::MatrixXd mMatrix;
};

} // namespace crumple::fem
