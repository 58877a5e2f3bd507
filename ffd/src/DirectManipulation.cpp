// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/ffd/CubicBSplineWeights.h>
#include <crumple/ffd/DirectManipulation.h>

#include <algorithm>

namespace crumple::ffd
{

DirectManipulationData DirectManipulationPrecompute(const FfdLattice& inLattice,
                                                    std::span<const LatticeLocation> inLocations,
                                                    double inRelativeTolerance)
{
    DirectManipulationData data;

    // Columns: the union of the 64 controls of every point, sorted so that B does not depend on point order.
    std::vector<int> controls;
    controls.reserve(inLocations.size() * 64);
    for (const LatticeLocation& location : inLocations)
        for (int c = 0; c < 4; ++c)
            for (int b = 0; b < 4; ++b)
                for (int a = 0; a < 4; ++a)
                    controls.push_back(inLattice.ControlIndex(location.mCell[0] + a, location.mCell[1] + b,
                                                              location.mCell[2] + c));
    std::sort(controls.begin(), controls.end());
    controls.erase(std::unique(controls.begin(), controls.end()), controls.end());
    data.mControls = std::move(controls);

    // Rows: tensor-product weights of each point.
    data.mB = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(inLocations.size()),
                                    static_cast<Eigen::Index>(data.mControls.size()));
    for (std::size_t row = 0; row < inLocations.size(); ++row)
    {
        const LatticeLocation& location = inLocations[row];
        const std::array<double, 4> wx = CubicBSplineWeights(location.mT.x());
        const std::array<double, 4> wy = CubicBSplineWeights(location.mT.y());
        const std::array<double, 4> wz = CubicBSplineWeights(location.mT.z());
        for (int c = 0; c < 4; ++c)
            for (int b = 0; b < 4; ++b)
                for (int a = 0; a < 4; ++a)
                {
                    const int control = inLattice.ControlIndex(location.mCell[0] + a, location.mCell[1] + b,
                                                               location.mCell[2] + c);
                    const auto column = std::lower_bound(data.mControls.begin(), data.mControls.end(), control) -
                                        data.mControls.begin();
                    data.mB(static_cast<Eigen::Index>(row), column) = wx[a] * wy[b] * wz[c];
                }
    }

    // Rank-revealing factorization for the minimum-norm least-squares solve.
    data.mDecomposition.setThreshold(inRelativeTolerance);
    data.mDecomposition.compute(data.mB);
    data.mRank = static_cast<int>(data.mDecomposition.rank());
    return data;
}

Eigen::MatrixX3d DirectManipulationSolve(const DirectManipulationData& inData, const Eigen::MatrixX3d& inDisplacements)
{
    if (inData.mControls.empty())
        return Eigen::MatrixX3d(0, 3);
    return inData.mDecomposition.solve(inDisplacements);
}

} // namespace crumple::ffd
