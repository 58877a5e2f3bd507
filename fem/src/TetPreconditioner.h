// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include "ConjugateGradient.h"

#include <Eigen/Cholesky>

#include <cstdint>
#include <span>
#include <vector>

namespace crumple::fem
{

/// Two-level preconditioner for the FEM systems A = a M + b K on #N nodes: block Jacobi (the inverse 3x3
/// diagonal blocks of A) plus an exact coarse correction on the six rigid modes of the free nodes,
///   P r = D^-1 r + Z (Z^T A Z)^-1 Z^T r,
///   Z = [translations, rotations about the free centre of mass] (#N x 6).
/// Block Jacobi alone resolves the stiff local modes but barely touches the global ones: a stiff free body's
/// translation or rotation then hides under the stopping tolerance of conjugate gradient (a falling steel
/// block lost gravity that way). The coarse space fixes exactly those modes. Anchored nodes have zero rows
/// throughout.
class TetPreconditioner
{
public:
    /// Builds the preconditioner.
    /// @param[in] inOperator        A, masked to the free nodes (anchored rows and columns zero)
    /// @param[in] inDiagonalBlocks  #N diagonal 3x3 blocks of A (zero or ignored on anchored nodes)
    /// @param[in] inPositions       #N current positions (m), for the rotation modes
    /// @param[in] inFree            #N 1 for free nodes, 0 for anchored ones
    void Build(const LinearOperator3& inOperator, std::span<const Mat3> inDiagonalBlocks,
               std::span<const Vec3> inPositions, std::span<const std::uint8_t> inFree);

    /// outZ = P inR, #N each.
    void Apply(std::span<const Vec3> inR, std::span<Vec3> outZ) const;

    /// As a LinearOperator3 for ConjugateGradient (valid while this object lives).
    LinearOperator3 AsOperator() const;

private:
    std::vector<Mat3> mBlockInverses;
    std::vector<std::array<Vec3, 6>> mModes; // Z row by row: the six mode vectors at each node
    Eigen::LDLT<Eigen::Matrix<double, 6, 6>> mCoarse;
    bool mHasCoarse = false;
};

} // namespace crumple::fem
