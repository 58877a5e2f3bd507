// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/TetSolver.h>

#include "ConjugateGradient.h"
#include "TetElementPass.h"
#include "TetFactoredPreconditioner.h"
#include "TetPreconditioner.h"
#include "TetSolveScratch.h"

#include <crumple/base/TimeStep.h>

#include <cmath>
#include <limits>
#include <string>

namespace crumple::fem
{

namespace
{

// The solve needs the compliance to a few digits (it weighs an engine body); 1e-8 in the preconditioner's
// norm is far below that and costs the factored system one or two iterations.
constexpr double cComplianceTolerance = 1.0e-8;

Status CheckContact(std::span<const int> inNodes, std::span<const double> inShares, const Vec3& inDirection,
                    int inNodeCount)
{
    const std::string who = "TetSolver::ContactEffectiveMass: ";
    if (inNodes.size() != inShares.size())
        return MakeError(EError::InvalidArgument, who + std::to_string(inNodes.size()) + " nodes but " +
                                                      std::to_string(inShares.size()) + " shares");
    if (!inDirection.allFinite() || !(inDirection.norm() > 0.0))
        return MakeError(EError::InvalidArgument, who + "the direction must be finite and not zero");
    double sum = 0.0;
    for (std::size_t i = 0; i < inNodes.size(); ++i)
    {
        if (inNodes[i] < 0 || inNodes[i] >= inNodeCount)
            return MakeError(EError::OutOfRange, who + "node " + std::to_string(inNodes[i]) +
                                                     " is outside [0, " + std::to_string(inNodeCount) + ")");
        if (!std::isfinite(inShares[i]) || inShares[i] < 0.0)
            return MakeError(EError::InvalidArgument,
                             who + "share " + std::to_string(i) + " must be finite and >= 0");
        sum += inShares[i];
    }
    if (!(sum > 0.0) || !std::isfinite(sum))
        return MakeError(EError::InvalidArgument, who + "the shares must sum to a finite value above 0");
    return Status::Ok();
}

} // namespace

Result<TetContactMass> TetSolver::ContactEffectiveMass(std::span<const int> inNodes,
                                                       std::span<const double> inShares,
                                                       const Vec3& inDirection, double inDeltaTime)
{
    if (Status valid = CheckTimeStep(inDeltaTime, "TetSolver::ContactEffectiveMass"); !valid)
        return valid.GetError();
    if (Status valid = CheckContact(inNodes, inShares, inDirection, static_cast<int>(mPositions.size()));
        !valid)
        return valid.GetError();
    const std::size_t node_count = mPositions.size();
    const Vec3 direction = inDirection.normalized();
    double share_sum = 0.0;
    for (double share : inShares)
        share_sum += share;

    TetSolveScratch& scratch = mWorkspace.Get();
    scratch.Resize(node_count);
    // intent: the load w_i d on the free nodes; an anchored node takes its share and does not move
    std::fill(scratch.mResidual.begin(), scratch.mResidual.end(), Vec3::Zero());
    bool any_free = false;
    for (std::size_t i = 0; i < inNodes.size(); ++i)
    {
        const auto node = static_cast<std::size_t>(inNodes[i]);
        if (mFree[node] == 0)
            continue;
        scratch.mResidual[node] += (inShares[i] / share_sum) * direction;
        any_free = any_free || inShares[i] > 0.0;
    }
    if (!any_free)
        return TetContactMass{std::numeric_limits<double>::infinity(), 0, true};

    // The step's system at the current positions: the last implicit step's linearisation where it is of these
    // positions (then its frames too), else one made here, in the scratch, from the current frames (the
    // solver's own linearisation, frames and forces stay as they are).
    const TetElementPassInput input = ParallelPassInput();
    const bool cached = mForcesCached && mForcePositions == mPositions;
    const std::vector<TetLinearization>* linearization = &mLinearization;
    const std::vector<Quat>* rotations = &mRotations;
    if (!cached)
    {
        scratch.mContactRotations = mRotations;
        scratch.mContactLinearization.resize(mElementNodes.size());
        scratch.mContactForces.resize(node_count);
        TetElasticForces(input, mPositions, {}, 0.0, scratch.mContactRotations, scratch.mContactLinearization,
                         scratch.mContactForces, nullptr);
        mElementWork += mActiveElementCount;
        linearization = &scratch.mContactLinearization;
        rotations = &scratch.mContactRotations;
    }
    const FemMaterialSettings& material = mMaterial.GetSettings();
    const double mass_scale = 1.0 + inDeltaTime * material.mMassDamping;
    const double stiffness_scale = inDeltaTime * inDeltaTime + inDeltaTime * material.mStiffnessDamping;
    std::uint64_t products = 0;
    const LinearOperator3 system = [&](std::span<const Vec3> inX, std::span<Vec3> outY)
    {
        TetStiffnessProduct(input, *linearization, inX, outY);
        ++products;
        for (std::size_t node = 0; node < outY.size(); ++node)
            outY[node] = mFree[node] != 0
                             ? Vec3(mass_scale * mMasses[node] * inX[node] + stiffness_scale * outY[node])
                             : Vec3::Zero();
    };

    // The factored system of this step length and connectivity, set to the current frames as the step sets it
    // before each solve: the one the solver holds, or, after a crack or a change of anchors, the one its next
    // step would build (the same bits: a function of the mesh, the anchors and the step), built here. Block
    // Jacobi where the settings ask for it or the system cannot be factored.
    TetFactoredPreconditioner* const factor = FactoredRestSystem(input, mass_scale, stiffness_scale);
    const bool factored = factor != nullptr;
    if (factored)
        factor->SetNodeRotations(mElementNodes, *rotations,
                                 material.mModel == EElasticModel::CorotatedLinear);
    else
    {
        TetStiffnessDiagonal(input, *linearization, scratch.mBlocks);
        mElementWork += mActiveElementCount;
        for (std::size_t node = 0; node < node_count; ++node)
            scratch.mBlocks[node] =
                mass_scale * mMasses[node] * Mat3::Identity() + stiffness_scale * scratch.mBlocks[node];
        scratch.mJacobi.Build(system, scratch.mBlocks, mPositions, mFree);
    }
    const LinearOperator3 preconditioner = [&](std::span<const Vec3> inR, std::span<Vec3> outZ)
    {
        if (factored)
            factor->Apply(inR, outZ);
        else
            scratch.mJacobi.Apply(inR, outZ);
    };
    std::fill(scratch.mDeltaV.begin(), scratch.mDeltaV.end(), Vec3::Zero());
    const ConjugateGradientResult cg =
        ConjugateGradient(system, preconditioner, scratch.mResidual, cComplianceTolerance,
                          mSettings.mCgMaxIterations, scratch.mDeltaV, scratch.mCg);
    mElementWork += products * mActiveElementCount;

    // intent: the load's own weights read the response back: w^T d . A^-1 (w d) (s/kg), symmetric in the
    // struck nodes, positive for a positive definite A
    double compliance = 0.0;
    for (std::size_t node = 0; node < node_count; ++node)
        compliance += scratch.mResidual[node].dot(scratch.mDeltaV[node]);
    if (!(compliance > 0.0) || !std::isfinite(compliance))
        return MakeError(EError::NonFinite,
                         "TetSolver::ContactEffectiveMass: the step's system gave no finite "
                         "positive compliance at these nodes");
    return TetContactMass{1.0 / compliance, cg.mIterations, cg.mConverged};
}

} // namespace crumple::fem
