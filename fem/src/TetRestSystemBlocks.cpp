// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "TetRestSystemBlocks.h"

#include <array>

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

void TetRestSystemBlocks(const TetElementPassInput& inInput, std::span<const double> inMasses,
                         std::span<const int> inFreeIndex, double inMassScale, double inStiffnessScale,
                         std::vector<NodeBlock>& outBlocks)
{
    // Per element the blocks between free corners in the lower triangle (each node pair once), then the
    // masses.
    std::vector<NodeBlock>& blocks = outBlocks;
    blocks.clear();
    const std::size_t most = inInput.mTets.size() * 10 + inMasses.size();
    if (blocks.capacity() < most)
        blocks.reserve(most + most / 2); // room for the nodes cracks add
    const Matrix6& c = *inInput.mMaterialMatrix;
    for (std::size_t tet = 0; tet < inInput.mTets.size(); ++tet)
    {
        // Symmetrised: B^T C B in floating point is symmetric only to round-off.
        const TetElementRest& rest = inInput.mRest[tet];
        const Eigen::Matrix<double, 6, 12> b = StrainDisplacement(rest.mRestEdgeInverse);
        const Eigen::Matrix<double, 12, 12> bcb = b.transpose() * c * b;
        const Eigen::Matrix<double, 12, 12> k =
            (0.5 * inStiffnessScale * rest.mRestVolume) * (bcb + bcb.transpose());
        const TetIndices& nodes = inInput.mTets[tet];
        for (int row_corner = 0; row_corner < 4; ++row_corner)
            for (int col_corner = 0; col_corner < 4; ++col_corner)
            {
                const int row = inFreeIndex[nodes[row_corner]];
                const int column = inFreeIndex[nodes[col_corner]];
                if (row < 0 || column < 0 || row < column || (row == column && row_corner != col_corner))
                    continue;
                blocks.push_back({row, column, k.block<3, 3>(3 * row_corner, 3 * col_corner)});
            }
    }
    for (std::size_t node = 0; node < inMasses.size(); ++node)
        if (inFreeIndex[node] >= 0)
            blocks.push_back({inFreeIndex[node], inFreeIndex[node], (inMassScale * inMasses[node]) * Mat3::Identity()});
}

} // namespace crumple::fem
