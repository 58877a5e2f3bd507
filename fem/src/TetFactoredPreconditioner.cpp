// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "TetFactoredPreconditioner.h"

#include "TetRestSystemBlocks.h"

#include <algorithm>

namespace crumple::fem
{

bool TetFactoredPreconditioner::Matches(std::span<const TetIndices> inTets, std::span<const std::uint8_t> inFree,
                                        double inMassScale, double inStiffnessScale) const
{
    return mAttempted && inMassScale == mMassScale && inStiffnessScale == mStiffnessScale &&
           std::equal(inFree.begin(), inFree.end(), mFree.begin(), mFree.end()) &&
           std::equal(inTets.begin(), inTets.end(), mTets.begin(), mTets.end());
}

bool TetFactoredPreconditioner::Precompute(const TetElementPassInput& inInput, std::span<const double> inMasses,
                                           std::span<const std::uint8_t> inFree, double inMassScale,
                                           double inStiffnessScale, bool inKeepElementStiffness,
                                           std::span<const Quat> inFrames)
{
    // Forget the old factor first: a failure leaves none.
    mFactored = false;
    mAttempted = true;
    mTets.assign(inInput.mTets.begin(), inInput.mTets.end());
    mFree.assign(inFree.begin(), inFree.end());
    mMassScale = inMassScale;
    mStiffnessScale = inStiffnessScale;

    // Free nodes numbered in node order.
    mFreeIndex.assign(inFree.size(), -1);
    int free_count = 0;
    for (std::size_t node = 0; node < inFree.size(); ++node)
        if (inFree[node] != 0)
            mFreeIndex[node] = free_count++;
    if (free_count == 0)
        return false;

    // Factor; a non-positive pivot (a free rigid mode of the static stiffness) fails the factorisation.
    if (!inKeepElementStiffness)
        mElementStiffness = TetRestStiffnessCache{};
    mKeepElementStiffness = inKeepElementStiffness;
    mFrames.assign(inFrames.begin(), inFrames.end());
    TetRestSystemBlocks(inInput, inMasses, mFreeIndex, inMassScale, inStiffnessScale, mBlocks,
                        inKeepElementStiffness ? &mElementStiffness : nullptr, mFrames);
    if (!mCholesky.Factor(free_count, mBlocks))
        return false;
    mRhs.assign(free_count, Vec3::Zero());
    mNodeRotations.clear();
    mFactored = true;
    return true;
}

bool TetFactoredPreconditioner::Refresh(const TetElementPassInput& inInput, std::span<const double> inMasses,
                                        std::span<const Quat> inFrames)
{
    if (!mFactored || inFrames.size() != mTets.size())
        return false;
    mFactored = false;
    mFrames.assign(inFrames.begin(), inFrames.end());
    TetRestSystemBlocks(inInput, inMasses, mFreeIndex, mMassScale, mStiffnessScale, mBlocks,
                        mKeepElementStiffness ? &mElementStiffness : nullptr, mFrames);
    // intent: the same connectivity and anchors give the same block sequence, so the analysis is reused
    if (!mCholesky.Refactor(static_cast<int>(mRhs.size()), mBlocks))
        return false;
    mNodeRotations.clear();
    mFactored = true;
    return true;
}

double TetFactoredPreconditioner::GetRefreshCostInIterations() const
{
    if (!mFactored)
        return 0.0;
    const double elements = static_cast<double>(mTets.size());
    const double nodes = static_cast<double>(mRhs.size());
    const double lower_blocks = static_cast<double>(mCholesky.GetBlockCount()) - nodes;
    const double refresh = 540.0 * elements + 27.0 * static_cast<double>(mCholesky.GetNumericBlockProducts());
    const double iteration = 130.0 * elements + 18.0 * (lower_blocks + nodes) + 18.0 * nodes + 20.0 * nodes;
    return refresh / iteration;
}

void TetFactoredPreconditioner::SetNodeRotations(std::span<const TetIndices> inTets, std::span<const Quat> inRotations,
                                                 bool inWarp)
{
    if (!inWarp)
    {
        mNodeRotations.clear();
        return;
    }

    // Sum of the element quaternions around each node, each flipped to the sum's hemisphere (q and -q are the
    // same rotation), in element order: deterministic.
    const std::size_t node_count = mFreeIndex.size();
    mQuaternionSums.assign(node_count, Eigen::Vector4d::Zero());
    const bool framed = !mFrames.empty() && mFrames.size() == inTets.size();
    for (std::size_t tet = 0; tet < inTets.size(); ++tet)
    {
        // The turn from the factored frame to the current one (the current frame itself at rest).
        const Eigen::Vector4d q = framed ? (inRotations[tet] * mFrames[tet].conjugate()).coeffs()
                                         : inRotations[tet].coeffs();
        for (int corner = 0; corner < 4; ++corner)
        {
            Eigen::Vector4d& sum = mQuaternionSums[inTets[tet][corner]];
            sum += sum.dot(q) < 0.0 ? Eigen::Vector4d(-q) : q;
        }
    }
    mNodeRotations.resize(node_count);
    for (std::size_t node = 0; node < node_count; ++node)
    {
        const double norm = mQuaternionSums[node].norm();
        mNodeRotations[node] = norm > 0.0 ? Quat(mQuaternionSums[node] / norm).toRotationMatrix()
                                          : Mat3(Mat3::Identity());
    }
}

void TetFactoredPreconditioner::Apply(std::span<const Vec3> inR, std::span<Vec3> outZ) const
{
    // R^T r gathered onto the free degrees of freedom.
    const bool warp = !mNodeRotations.empty();
    for (std::size_t node = 0; node < mFreeIndex.size(); ++node)
    {
        const int index = mFreeIndex[node];
        if (index >= 0)
            mRhs[index] = warp ? Vec3(mNodeRotations[node].transpose() * inR[node]) : inR[node];
    }

    // A0^-1 by the two triangular solves of the factor, in place (no allocation).
    mCholesky.Solve(mRhs);

    // R scattered back; anchored nodes get zero.
    for (std::size_t node = 0; node < mFreeIndex.size(); ++node)
    {
        const int index = mFreeIndex[node];
        if (index < 0)
            outZ[node].setZero();
        else
            outZ[node] = warp ? Vec3(mNodeRotations[node] * mRhs[index]) : mRhs[index];
    }
}

LinearOperator3 TetFactoredPreconditioner::AsOperator() const
{
    return [this](std::span<const Vec3> inX, std::span<Vec3> outY) { Apply(inX, outY); };
}

} // namespace crumple::fem
