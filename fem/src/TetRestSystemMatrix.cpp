// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "TetRestSystemMatrix.h"

#include <array>
#include <vector>

namespace crumple::fem
{

namespace
{

// B_e, 6 x 12: Voigt strain (xx, yy, zz, 2xy, 2yz, 2zx) of the corner displacements; corner a contributes
// the gradient g_a of its shape function (rows of D_m^-1 for corners 1..3, minus their sum for corner 0).
Eigen::Matrix<double, 6, 12> StrainDisplacement(const Mat3& inRestEdgeInverse)
{
    std::array<Vec3, 4> g;
    g[1] = inRestEdgeInverse.row(0).transpose();
    g[2] = inRestEdgeInverse.row(1).transpose();
    g[3] = inRestEdgeInverse.row(2).transpose();
    g[0] = -(g[1] + g[2] + g[3]);
    Eigen::Matrix<double, 6, 12> b = Eigen::Matrix<double, 6, 12>::Zero();
    for (int corner = 0; corner < 4; ++corner)
    {
        const int c = 3 * corner;
        b(0, c + 0) = g[corner].x();
        b(1, c + 1) = g[corner].y();
        b(2, c + 2) = g[corner].z();
        b(3, c + 0) = g[corner].y();
        b(3, c + 1) = g[corner].x();
        b(4, c + 1) = g[corner].z();
        b(4, c + 2) = g[corner].y();
        b(5, c + 0) = g[corner].z();
        b(5, c + 2) = g[corner].x();
    }
    return b;
}

} // namespace

Eigen::SparseMatrix<double> TetRestSystemMatrix(const TetElementPassInput& inInput, std::span<const double> inMasses,
                                                std::span<const int> inFreeIndex, int inFreeCount,
                                                double inMassScale, double inStiffnessScale)
{
    // Triplets of every element block between free corners, then the masses; setFromTriplets sums duplicates
    // in a fixed order, so the matrix is the same bit for bit on every run.
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(inInput.mTets.size() * 144 + 3 * static_cast<std::size_t>(inFreeCount));
    const Matrix6& c = *inInput.mMaterialMatrix;
    for (std::size_t tet = 0; tet < inInput.mTets.size(); ++tet)
    {
        const TetElementRest& rest = inInput.mRest[tet];
        const Eigen::Matrix<double, 6, 12> b = StrainDisplacement(rest.mRestEdgeInverse);
        // Symmetrised: B^T C B in floating point is symmetric only to round-off, and the factor reads one
        // triangle.
        const Eigen::Matrix<double, 12, 12> bcb = b.transpose() * c * b;
        const Eigen::Matrix<double, 12, 12> k =
            (0.5 * inStiffnessScale * rest.mRestVolume) * (bcb + bcb.transpose());
        const TetIndices& nodes = inInput.mTets[tet];
        for (int row_corner = 0; row_corner < 4; ++row_corner)
        {
            const int row_node = inFreeIndex[nodes[row_corner]];
            if (row_node < 0)
                continue;
            for (int col_corner = 0; col_corner < 4; ++col_corner)
            {
                const int col_node = inFreeIndex[nodes[col_corner]];
                if (col_node < 0)
                    continue;
                for (int row = 0; row < 3; ++row)
                    for (int col = 0; col < 3; ++col)
                        entries.emplace_back(3 * row_node + row, 3 * col_node + col,
                                             k(3 * row_corner + row, 3 * col_corner + col));
            }
        }
    }
    for (std::size_t node = 0; node < inMasses.size(); ++node)
        if (inFreeIndex[node] >= 0)
            for (int axis = 0; axis < 3; ++axis)
                entries.emplace_back(3 * inFreeIndex[node] + axis, 3 * inFreeIndex[node] + axis,
                                     inMassScale * inMasses[node]);
    Eigen::SparseMatrix<double> matrix(3 * inFreeCount, 3 * inFreeCount);
    matrix.setFromTriplets(entries.begin(), entries.end());
    return matrix;
}

} // namespace crumple::fem
