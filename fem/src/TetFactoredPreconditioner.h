// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include "ConjugateGradient.h"
#include "NodeBlockCholesky.h"
#include "TetRestSystemBlocks.h"
#include "TetElementPass.h"


#include <cstdint>
#include <span>
#include <vector>

namespace crumple::fem
{

/// Precompute/solve pair of the implicit system at fixed element frames, A_F = a M + b sum_e F_e K0_e F_e^T
/// (TetRestSystemBlocks; F_e = identity at rest), used as the preconditioner of the implicit and static
/// solves: P r = R A_F^-1 R^T r, R the block diagonal of node rotations (the mean, around each node, of the
/// rotation of each element's current corotated frame away from its frame F_e; identity for St.
/// Venant-Kirchhoff).
///
/// Why: the implicit system is A = a M + b R K0 R^T for the corotated model. A_F is constant while the
/// connectivity, the anchors and the time step are (the per-step cost is then two sparse triangular solves,
/// no factorisation), and R A_F^-1 R^T inverts A exactly for a body rigidly rotated since the frames F, so
/// conjugate gradient only has to resolve how far the element frames differ from their nodes' mean: a few
/// iterations instead of the hundreds block Jacobi needs for a stiff material (the "stiffness warping" of
/// Mueller et al. 2002 used as a preconditioner, with the prefactorised constant matrix of projective
/// dynamics, Bouaziz et al. 2014). Where a body bends or is crushed, neighbouring elements turn apart and no
/// node rotation fits them all: Refresh() then refactors at the current frames (the sparsity, ordering and
/// symbolic analysis kept), after which the preconditioner is exact again (Hecht et al. 2012 refactor a
/// corotated stiffness when its frames have drifted in the same way).
/// Fracture, SetNodeFixed and a new time step change A_F's pattern; the owner calls Matches() and
/// Precompute() again.
///
/// Memory: the Cholesky factor (NodeBlockCholesky): GetFactorBlockCount() blocks of 9 doubles and an index;
/// with frames, one quaternion per element.
/// Not thread-safe: Apply() uses scratch held here.
class TetFactoredPreconditioner
{
public:
    /// True when Precompute() was last called (successfully or not) for this connectivity, these anchors and
    /// these scales: nothing to redo.
    bool Matches(std::span<const TetIndices> inTets, std::span<const std::uint8_t> inFree, double inMassScale,
                 double inStiffnessScale) const;

    /// Assembles and factors A_F. Returns false, and holds no factor, when A_F is not positive definite (a
    /// static system whose anchors leave a rigid mode free) or has no free node.
    /// @param[in] inInput           connectivity, rest data and material
    /// @param[in] inMasses          #N lumped masses (kg)
    /// @param[in] inFree            #N 1 for free nodes, 0 for anchored ones
    /// @param[in] inMassScale       a (1 + h alpha, or 0 for statics)
    /// @param[in] inStiffnessScale  b (h^2 + h beta (s^2), or 1 for statics)
    /// @param[in] inKeepElementStiffness  keep each element's rest stiffness for the next Precompute (a solver
    ///                                    that refactors after cracks: TetRestStiffnessCache); false drops it
    /// @param[in] inFrames          #T element frames F_e (unit quaternions), or empty for the rest frames
    bool Precompute(const TetElementPassInput& inInput, std::span<const double> inMasses,
                    std::span<const std::uint8_t> inFree, double inMassScale, double inStiffnessScale,
                    bool inKeepElementStiffness = false, std::span<const Quat> inFrames = {});

    /// Refactors A_F at new element frames inFrames (#T), with the connectivity, anchors, scales and element
    /// stiffness of the last Precompute(): the numeric factorisation only (NodeBlockCholesky::Refactor). The
    /// node rotations become identity until the next SetNodeRotations(). Returns false, and holds no factor,
    /// when there is no factor to refresh or A_F is not positive definite.
    /// @param[in] inInput   the connectivity and rest data of the last Precompute()
    /// @param[in] inMasses  #N lumped masses (kg), as in the last Precompute()
    bool Refresh(const TetElementPassInput& inInput, std::span<const double> inMasses, std::span<const Quat> inFrames);

    /// Forgets the factor: the next Matches() is false, so the owner precomputes again.
    void Invalidate()
    {
        mAttempted = false;
        mFactored = false;
    }

    /// True after a successful Precompute()
    bool IsFactored() const { return mFactored; }
    /// What a Refresh() costs in conjugate-gradient iterations of an implicit solve preconditioned by this
    /// factor, from operation counts (multiply-adds): the refresh assembles each element's rotated rest
    /// stiffness (10 blocks of F K0 F^T, 540) and runs the numeric factorisation (27 per block product,
    /// NodeBlockCholesky::GetNumericBlockProducts); an iteration applies the stiffness to a direction (about
    /// 130 per element), solves with L and L^T (18 per block of L and per node) and turns the nodes (18 per
    /// node), with about 20 per node of vector work. Counts, not timings, so that a solver's choices, which
    /// depend on it, repeat bit for bit on any machine. 0 without a factor.
    double GetRefreshCostInIterations() const;
    /// 3 x 3 blocks of the Cholesky factor L (0 without one)
    std::int64_t GetFactorBlockCount() const { return mCholesky.GetBlockCount(); }

    /// Sets the node rotations R from the element frames: the sign-aligned mean, over the elements around each
    /// node, of the quaternion that turns the element's factored frame F_e into its current frame. Call after
    /// the elements' rotations change (each Newton iteration).
    /// @param[in] inTets       #T element -> node indices (as in Precompute())
    /// @param[in] inRotations  #T element rotations, unit quaternions
    /// @param[in] inWarp       false: R = identity (St. Venant-Kirchhoff keeps no frames)
    void SetNodeRotations(std::span<const TetIndices> inTets, std::span<const Quat> inRotations, bool inWarp);

    /// outZ = R A0^-1 R^T inR on the free nodes, zero on anchored ones; #N each.
    void Apply(std::span<const Vec3> inR, std::span<Vec3> outZ) const;

    /// As a LinearOperator3 for ConjugateGradient (valid while this object lives).
    LinearOperator3 AsOperator() const;

private:
    NodeBlockCholesky mCholesky;
    bool mFactored = false;
    bool mAttempted = false;
    bool mKeepElementStiffness = false;

    // What the factor was built for.
    std::vector<TetIndices> mTets;
    std::vector<std::uint8_t> mFree;
    double mMassScale = 0.0;
    double mStiffnessScale = 0.0;

    std::vector<int> mFreeIndex;    // #N, -1 for anchored nodes
    std::vector<NodeBlock> mBlocks; // A0's blocks, kept for the next Precompute (no fresh pages)
    TetRestStiffnessCache mElementStiffness; // empty unless Precompute was asked to keep it
    std::vector<Quat> mFrames;        // #T, the frames F_e the factor was made at; empty at rest
    std::vector<Mat3> mNodeRotations; // #N, empty while all are identity
    std::vector<Eigen::Vector4d> mQuaternionSums; // #N scratch of SetNodeRotations

    // Scratch of Apply(), #free, sized by Precompute().
    mutable std::vector<Vec3> mRhs;
};

} // namespace crumple::fem
