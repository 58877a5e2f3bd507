// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include "ConjugateGradient.h"
#include "TetFactoredPreconditioner.h"
#include "TetPassParallel.h"
#include "TetPreconditioner.h"

#include <crumple/base/Math.h>
#include <crumple/fem/TetLinearization.h>

#include <cstdint>
#include <vector>

namespace crumple::fem
{

/// The scratch of TetSolver's implicit steps and static solves, sized on first use and kept (no allocation
/// per step once sized), and the factored rest system they reuse.
struct TetSolveScratch
{
    TetFactoredPreconditioner mFactor;
    TetPreconditioner mJacobi;
    TetPassParallel mParallel; ///< Gather scratch of the element passes on the host's jobs
    ConjugateGradientScratch mCg;
    std::vector<Vec3> mKv;             ///< #N K v (N s/m x m/s)
    std::vector<Vec3> mResidual;       ///< #N
    std::vector<Vec3> mDeltaV;         ///< #N
    std::vector<Vec3> mPreconditioned; ///< #N
    std::vector<Vec3> mLineStart;      ///< #N velocities before the last Newton update (the line search)
    std::vector<Mat3> mBlocks;         ///< #N diagonal blocks for block Jacobi
    std::vector<std::uint8_t> mGroundHeld; ///< #N nodes the ground holds this step (sized with a ground only)
    std::vector<double> mGroundImpulses;   ///< #N the ground's normal impulse on them (N s)
    /// ContactEffectiveMass's linearisation where the solver holds none of its positions (sized on first
    /// need)
    std::vector<TetLinearization> mContactLinearization; ///< #T
    std::vector<Quat> mContactRotations;                 ///< #T
    std::vector<Vec3> mContactForces;                    ///< #N

    /// Sizes every #N vector to inNodeCount (allocates only when the count grows past the capacity)
    void Resize(std::size_t inNodeCount)
    {
        mKv.resize(inNodeCount);
        mResidual.resize(inNodeCount);
        mDeltaV.resize(inNodeCount);
        mPreconditioned.resize(inNodeCount);
        mBlocks.resize(inNodeCount);
    }
};

} // namespace crumple::fem
