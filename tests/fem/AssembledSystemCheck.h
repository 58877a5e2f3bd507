// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// White-box helpers of the factored-solve tests: an assembled block system as a dense matrix, and how far it
// is from the matrix-free implicit operator a M + b K on a random direction.
#pragma once

#include "DrawVec3.h"
#include "NodeBlockCholesky.h"
#include "TetElementPass.h"

#include <Eigen/Dense>

#include <algorithm>
#include <random>
#include <span>
#include <vector>

namespace crumple::test
{

/// The symmetric matrix of inFreeCount block rows whose lower triangle inBlocks holds (repeats summed).
inline Eigen::MatrixXd DenseSymmetric(std::span<const fem::NodeBlock> inBlocks, int inFreeCount)
{
    Eigen::MatrixXd system = Eigen::MatrixXd::Zero(3 * inFreeCount, 3 * inFreeCount);
    for (const fem::NodeBlock& block : inBlocks)
    {
        system.block<3, 3>(3 * block.mRow, 3 * block.mColumn) += block.mBlock;
        if (block.mRow != block.mColumn)
            system.block<3, 3>(3 * block.mColumn, 3 * block.mRow) += block.mBlock.transpose();
    }
    return system;
}

/// Largest entry of (assembled - matrix-free) applied to one random direction on the free nodes (zero on
/// anchored ones), and the largest entry of the matrix-free product as its scale.
struct OperatorDifference
{
    double mDifference = 0.0;
    double mScale = 0.0;
};

/// inSystem (over the free nodes numbered by inFreeIndex, -1 for anchored) against inMassScale M +
/// inStiffnessScale K, K the matrix-free product of inLinearization, on a direction drawn from ioRandom.
inline OperatorDifference AssembledAgainstMatrixFree(const fem::TetElementPassInput& inInput,
                                                     std::span<const fem::TetLinearization> inLinearization,
                                                     const Eigen::MatrixXd& inSystem, std::span<const double> inMasses,
                                                     std::span<const int> inFreeIndex, double inMassScale,
                                                     double inStiffnessScale, std::mt19937& ioRandom)
{
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const std::size_t node_count = inFreeIndex.size();
    std::vector<Vec3> direction(node_count, Vec3::Zero());
    Eigen::VectorXd gathered(inSystem.cols());
    for (std::size_t node = 0; node < node_count; ++node)
        if (inFreeIndex[node] >= 0)
        {
            direction[node] = common::DrawVec3([&] { return unit(ioRandom); });
            gathered.segment<3>(3 * inFreeIndex[node]) = direction[node];
        }
    std::vector<Vec3> product(node_count);
    fem::TetStiffnessProduct(inInput, inLinearization, direction, product);
    const Eigen::VectorXd assembled = inSystem * gathered;
    OperatorDifference result;
    for (std::size_t node = 0; node < node_count; ++node)
        if (inFreeIndex[node] >= 0)
        {
            const Vec3 matrix_free = inMassScale * inMasses[node] * direction[node] + inStiffnessScale * product[node];
            result.mScale = std::max(result.mScale, matrix_free.cwiseAbs().maxCoeff());
            result.mDifference = std::max(
                result.mDifference, (matrix_free - Vec3(assembled.segment<3>(3 * inFreeIndex[node]))).cwiseAbs().maxCoeff());
        }
    return result;
}

} // namespace crumple::test
