// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "TetPreconditioner.h"

namespace crumple::fem
{

void TetPreconditioner::Build(const LinearOperator3& inOperator, std::span<const Mat3> inDiagonalBlocks,
                              std::span<const Vec3> inPositions, std::span<const std::uint8_t> inFree)
{
    const std::size_t n = inPositions.size();

    // Block Jacobi: inverse diagonal blocks on free nodes, zero on anchored ones.
    mBlockInverses.resize(n);
    std::size_t free_count = 0;
    Vec3 centre = Vec3::Zero();
    for (std::size_t node = 0; node < n; ++node)
    {
        mBlockInverses[node] = inFree[node] != 0 ? Mat3(inDiagonalBlocks[node].inverse()) : Mat3::Zero();
        if (inFree[node] != 0)
        {
            ++free_count;
            centre += inPositions[node];
        }
    }

    // Rigid modes on the free nodes; rotations about their centroid (any point spans the same space, the
    // centroid keeps the columns well conditioned).
    mHasCoarse = false;
    mModes.assign(n, {});
    if (free_count < 3)
        return;
    centre /= static_cast<double>(free_count);
    for (std::size_t node = 0; node < n; ++node)
    {
        if (inFree[node] == 0)
        {
            mModes[node].fill(Vec3::Zero());
            continue;
        }
        const Vec3 arm = inPositions[node] - centre;
        for (int axis = 0; axis < 3; ++axis)
        {
            mModes[node][axis] = Vec3::Unit(axis);
            mModes[node][3 + axis] = Vec3::Unit(axis).cross(arm);
        }
    }

    // Galerkin coarse matrix Z^T A Z from six operator applications.
    Eigen::Matrix<double, 6, 6> coarse;
    std::vector<Vec3> column(n), product(n);
    for (int mode = 0; mode < 6; ++mode)
    {
        for (std::size_t node = 0; node < n; ++node)
            column[node] = mModes[node][mode];
        inOperator(column, product);
        for (int row = 0; row < 6; ++row)
        {
            double sum = 0.0;
            for (std::size_t node = 0; node < n; ++node)
                sum += mModes[node][row].dot(product[node]);
            coarse(row, mode) = sum;
        }
    }
    coarse = 0.5 * (coarse + coarse.transpose()).eval();
    mCoarse.compute(coarse);
    mHasCoarse = mCoarse.info() == Eigen::Success && mCoarse.isPositive() &&
                 mCoarse.vectorD().minCoeff() > 1.0e-12 * mCoarse.vectorD().maxCoeff();
}

void TetPreconditioner::Apply(std::span<const Vec3> inR, std::span<Vec3> outZ) const
{
    // Coarse right-hand side Z^T r.
    Eigen::Matrix<double, 6, 1> coarse_rhs = Eigen::Matrix<double, 6, 1>::Zero();
    if (mHasCoarse)
        for (std::size_t node = 0; node < inR.size(); ++node)
            for (int mode = 0; mode < 6; ++mode)
                coarse_rhs[mode] += mModes[node][mode].dot(inR[node]);
    const Eigen::Matrix<double, 6, 1> coarse = mHasCoarse
                                                   ? Eigen::Matrix<double, 6, 1>(mCoarse.solve(coarse_rhs))
                                                   : Eigen::Matrix<double, 6, 1>::Zero();

    // Block Jacobi plus the coarse correction.
    for (std::size_t node = 0; node < inR.size(); ++node)
    {
        Vec3 z = mBlockInverses[node] * inR[node];
        if (mHasCoarse)
            for (int mode = 0; mode < 6; ++mode)
                z += coarse[mode] * mModes[node][mode];
        outZ[node] = z;
    }
}

LinearOperator3 TetPreconditioner::AsOperator() const
{
    return [this](std::span<const Vec3> inX, std::span<Vec3> outY) { Apply(inX, outY); };
}

} // namespace crumple::fem
