// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/GroupPrincipalStress.h>

#include <Eigen/Eigenvalues>

#include <string>

namespace crumple::fem
{

Status GroupPrincipalStress(const FractureLinks& inLinks, std::span<const Mat3> inElementStress,
                            std::span<const TetElementRest> inRest, std::span<PrincipalStress> outPrincipal)
{
    // intent: what is read is checked before anything is written (O(#T), a fraction of the stress pass that
    // fills inElementStress)
    const auto groups = static_cast<std::size_t>(inLinks.GetGroupCount());
    if (inRest.size() != inElementStress.size() || outPrincipal.size() != groups ||
        inLinks.mGroupElementOffsets.size() != groups + 1 || inLinks.mGroupElementOffsets.front() != 0 ||
        static_cast<std::size_t>(inLinks.mGroupElementOffsets.back()) != inLinks.mGroupElements.size())
        return MakeError(EError::InvalidArgument, "GroupPrincipalStress: " + std::to_string(inElementStress.size()) + " stresses, " +
                                                      std::to_string(inRest.size()) + " rest data and " +
                                                      std::to_string(outPrincipal.size()) + " outputs for " +
                                                      std::to_string(groups) + " groups");
    for (std::size_t group = 0; group < groups; ++group)
        if (inLinks.mGroupElementOffsets[group] >= inLinks.mGroupElementOffsets[group + 1])
            return MakeError(EError::InvalidArgument, "GroupPrincipalStress: group " + std::to_string(group) + " has no element");
    for (int tet : inLinks.mGroupElements)
        if (tet < 0 || static_cast<std::size_t>(tet) >= inElementStress.size())
            return MakeError(EError::OutOfRange, "GroupPrincipalStress: the links name element " + std::to_string(tet) + " of " +
                                                     std::to_string(inElementStress.size()));
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
    return Status::Ok();
}

} // namespace crumple::fem
