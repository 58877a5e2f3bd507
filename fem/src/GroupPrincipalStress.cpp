// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/GroupPrincipalStress.h>

#include <Eigen/Eigenvalues>

namespace crumple::fem
{

void GroupPrincipalStress(const FractureLinks& inLinks, std::span<const Mat3> inElementStress,
                          std::span<const TetElementRest> inRest, std::span<PrincipalStress> outPrincipal)
{
    Eigen::SelfAdjointEigenSolver<Mat3> eigen;
    for (int group = 0; group < inLinks.GetGroupCount(); ++group)
    {
        // Volume-weighted mean over the group's elements (element order).
        Mat3 sum = Mat3::Zero();
        double volume = 0.0;
        for (int entry = inLinks.mGroupElementOffsets[group]; entry < inLinks.mGroupElementOffsets[group + 1];
             ++entry)
        {
            const int tet = inLinks.mGroupElements[entry];
            sum += inRest[tet].mRestVolume * inElementStress[tet];
            volume += inRest[tet].mRestVolume;
        }
        const Mat3 mean = 0.5 * (sum + sum.transpose()) / volume;

        // Eigenvalues come in increasing order: the last is the largest.
        eigen.computeDirect(mean);
        outPrincipal[group].mValue = eigen.eigenvalues()(2);
        outPrincipal[group].mDirection = eigen.eigenvectors().col(2).normalized();
    }
}

} // namespace crumple::fem
