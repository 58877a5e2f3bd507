// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <cstdint>
#include <memory>
#include <vector>

namespace crumple::fem
{

/// Sparse LDL^T factorization of the free-free stiffness block (AMD fill-reducing ordering).
using HexStiffnessFactorization = Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>;

/// A pivot d_i of K_ff = P^T L D L^T P below this fraction of its diagonal entry (P K_ff P^T)_ii marks the
/// stiffness as singular (Eigen itself flags only exactly zero pivots). Measured smallest ratios: well-posed
/// supports 0.03 to 0.5 (40 x 4 x 4 cantilever clamped at one face 0.33, a 400 x 2 x 2 needle 0.32, three corner
/// nodes 0.033); a rigid mode left free (1 or 2 fixed nodes, a line of fixed nodes) 2e-13 or less, sometimes
/// negative. The threshold sits far from both.
constexpr double cHexSingularPivotRatio = 1.0e-8;

/// Precomputed static solve of a hexahedral mesh (libigl precompute/solve style): the stiffness factorized
/// once with the fixed (boundary) nodes removed, so that U = K^-1 F is a pair of triangular solves. Built by
/// HexStaticPrecompute, used by HexStaticSolve and HexCompliancePrecompute. Move-only (owns the factorization).
/// Memory: the factor L (GetFactorNonZeros(), 12 bytes per entry: 3.8 MB for 40 x 4 x 4 cells, 22 MB for
/// 20 x 20 x 5) plus K_fb.
struct CRUMPLE_API HexStaticData
{
    int mNodeCount = 0;                   ///< Nodes of the mesh; forces and displacements have 3 mNodeCount rows
    std::vector<int> mFixedNodes;         ///< Fixed nodes, ascending, no repeats: displacement 0 (or prescribed)
    std::vector<int> mFreeIndex;          ///< 3 mNodeCount: row of each dof in the free system, -1 for fixed dofs
    std::vector<int> mFreeDofs;           ///< #free: the global dof (3 n + axis) of each free row, ascending
    std::vector<int> mFixedDofs;          ///< 3 #fixed: the global dofs of the fixed nodes, ascending
    Eigen::SparseMatrix<double> mFreeFixedStiffness; ///< K_fb, #free by 3 #fixed (N/m), for prescribed displacements
    std::unique_ptr<HexStiffnessFactorization> mFactorization; ///< LDL^T of K_ff (N/m); null until precomputed
    double mSmallestPivotRatio = 0.0;     ///< min_i d_i / (P K_ff P^T)_ii: a conditioning diagnostic, > cHexSingularPivotRatio
    std::uint32_t mSourceCrc = 0;         ///< HexSourceCrc of the mesh, material and fixed nodes

    /// Non-zeros of the factor L (its memory is about 12 bytes each)
    long long GetFactorNonZeros() const
    {
        return mFactorization ? static_cast<long long>(mFactorization->matrixL().nestedExpression().nonZeros()) : 0;
    }
};

} // namespace crumple::fem
