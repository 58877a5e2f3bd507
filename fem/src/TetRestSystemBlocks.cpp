// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "TetRestSystemBlocks.h"

#include <array>
#include <cstring>
#include <limits>

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

namespace
{

// The ten corner blocks (row >= column, row-major) of B^T C B + its transpose: symmetrised, as B^T C B in
// floating point is symmetric only to round-off.
std::array<Mat3, 10> ElementBlocks(const Mat3& inRestEdgeInverse, const Matrix6& inMaterial)
{
    const Eigen::Matrix<double, 6, 12> b = StrainDisplacement(inRestEdgeInverse);
    const Eigen::Matrix<double, 12, 12> bcb = b.transpose() * inMaterial * b;
    const Eigen::Matrix<double, 12, 12> sum = bcb + bcb.transpose();
    std::array<Mat3, 10> blocks;
    int pair = 0;
    for (int row_corner = 0; row_corner < 4; ++row_corner)
        for (int col_corner = 0; col_corner <= row_corner; ++col_corner)
            blocks[static_cast<std::size_t>(pair++)] = sum.block<3, 3>(3 * row_corner, 3 * col_corner);
    return blocks;
}

} // namespace

void TetRestSystemBlocks(const TetElementPassInput& inInput, std::span<const double> inMasses,
                         std::span<const int> inFreeIndex, double inMassScale, double inStiffnessScale,
                         std::vector<NodeBlock>& outBlocks, TetRestStiffnessCache* ioCache,
                         std::span<const Quat> inFrames)
{
    // Per element the blocks between free corners in the lower triangle (each node pair once), then the
    // masses.
    std::vector<NodeBlock>& blocks = outBlocks;
    blocks.clear();
    const std::size_t most = inInput.mTets.size() * 10 + inMasses.size();
    if (blocks.capacity() < most)
        blocks.reserve(most + most / 2); // room for the nodes cracks add
    const Matrix6& c = *inInput.mMaterialMatrix;
    if (ioCache != nullptr &&
        (ioCache->mBlocks.size() != inInput.mTets.size() || std::memcmp(ioCache->mMaterial.data(), c.data(), sizeof(Matrix6)) != 0))
    {
        // intent: a new material or element count makes every entry stale; an impossible edge inverse (NaN)
        // marks them so
        ioCache->mBlocks.resize(inInput.mTets.size());
        ioCache->mEdgeInverse.assign(inInput.mTets.size(), Mat3::Constant(std::numeric_limits<double>::quiet_NaN()));
        ioCache->mMaterial = c;
    }
    for (std::size_t tet = 0; tet < inInput.mTets.size(); ++tet)
    {
        const TetIndices& nodes = inInput.mTets[tet];
        // intent: an element with no free corner adds no block (pieces that left the prop are anchored whole)
        if (inFreeIndex[nodes[0]] < 0 && inFreeIndex[nodes[1]] < 0 && inFreeIndex[nodes[2]] < 0 && inFreeIndex[nodes[3]] < 0)
            continue;
        const TetElementRest& rest = inInput.mRest[tet];
        std::array<Mat3, 10> fresh;
        const std::array<Mat3, 10>* element = &fresh;
        if (ioCache == nullptr)
            fresh = ElementBlocks(rest.mRestEdgeInverse, c);
        else
        {
            // Byte comparison: the sign of a zero counts too, and the NaN stale mark never matches a real one.
            if (std::memcmp(ioCache->mEdgeInverse[tet].data(), rest.mRestEdgeInverse.data(), sizeof(Mat3)) != 0)
            {
                ioCache->mBlocks[tet] = ElementBlocks(rest.mRestEdgeInverse, c);
                ioCache->mEdgeInverse[tet] = rest.mRestEdgeInverse;
            }
            element = &ioCache->mBlocks[tet];
        }
        const double scale = 0.5 * inStiffnessScale * rest.mRestVolume;
        const bool rotated = !inFrames.empty();
        const Mat3 frame = rotated ? Mat3(inFrames[tet].toRotationMatrix()) : Mat3(Mat3::Identity());
        int pair = 0;
        for (int row_corner = 0; row_corner < 4; ++row_corner)
            for (int col_corner = 0; col_corner <= row_corner; ++col_corner, ++pair)
            {
                // Each node pair once, in the lower triangle of the free numbering: a block and its transpose.
                const int row = inFreeIndex[nodes[row_corner]];
                const int column = inFreeIndex[nodes[col_corner]];
                if (row < 0 || column < 0)
                    continue;
                const Mat3 rest_block = scale * (*element)[static_cast<std::size_t>(pair)];
                const Mat3 k = rotated ? Mat3(frame * rest_block * frame.transpose()) : rest_block;
                if (row > column || (row == column && row_corner == col_corner))
                    blocks.push_back({row, column, k});
                else if (row < column)
                    blocks.push_back({column, row, Mat3(k.transpose())});
            }
    }
    for (std::size_t node = 0; node < inMasses.size(); ++node)
        if (inFreeIndex[node] >= 0)
            blocks.push_back({inFreeIndex[node], inFreeIndex[node], (inMassScale * inMasses[node]) * Mat3::Identity()});
}

} // namespace crumple::fem
