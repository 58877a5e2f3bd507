// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Math.h>
#include <crumple/base/Result.h>
#include <crumple/fem/TetCoarseSpace.h>
#include <crumple/fem/TetSolverSettings.h>
#include <crumple/gpu/ComputeDevice.h>
#include <crumple/gpu/ComputeProgram.h>
#include <crumple/gpu/StorageBuffer.h>

#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <vector>

namespace crumple::gpu
{

/// What one implicit step reads besides the buffers GpuTetSolver binds (positions, velocities, elements,
/// rest, rotations, corners, external forces, adjacency, status at bindings 0-9).
struct GpuImplicitStepInput
{
    double mDeltaTime = 0.0;                           ///< h (s)
    double mMassDamping = 0.0;                         ///< Rayleigh alpha (1/s)
    double mStiffnessDamping = 0.0;                    ///< Rayleigh beta (s)
    float mLambda = 0.0f;                              ///< Lame lambda (Pa)
    float mMu = 0.0f;                                  ///< shear modulus (Pa)
    Vec3 mGravity = Vec3::Zero();                      ///< m/s^2, world
    bool mCorotated = true;                            ///< Corotated (else St. Venant-Kirchhoff)
    bool mPlastic = false;                             ///< The elastic strain less the plastic strains
    const fem::TetSolverSettings* mSettings = nullptr; ///< Newton and CG tolerances and limits
    /// J: Newton also goes on until the remaining correction's energy is below it (a breakable material's
    /// fem::TetSolver::GetCrackSafeEnergy(); infinity: no such bound)
    double mCrackSafeEnergy = std::numeric_limits<double>::infinity();
    std::span<const double> mInverseMasses;            ///< #N host copy (1/kg), 0 = anchored
    std::span<const double> mMasses;                   ///< #N host copy (kg)
    std::uint32_t mElementCount = 0;                   ///< #T
    /// The solver's force pass (TetElementForces) with its uniforms set and uBeta 0: elastic forces and the
    /// corotated frames at the current positions
    const ComputeProgram* mForcePass = nullptr;
    const StorageBuffer* mPositions = nullptr;  ///< #N, copied to x0 at the start
    const StorageBuffer* mVelocities = nullptr; ///< #N, copied to v0 at the start; the K v direction
};

/// What one implicit step did.
struct GpuImplicitStepStats
{
    int mNewtonIterations = 0;        ///< Linear solves
    int mSolverIterations = 0;        ///< Conjugate-gradient iterations, all solves
    int mMostSolveIterations = 0;     ///< Conjugate-gradient iterations of the longest solve
    double mSolverResidual = 0.0;     ///< Largest final relative residual sqrt(r.z / b.Pb) of a solve
    bool mConverged = true;           ///< Every solve and the Newton test converged
    std::uint64_t mElementPasses = 0; ///< Element evaluations / #T (forces, products, diagonal blocks)
    bool mAllocated = true; ///< False when the step's buffers could not be made (nothing was stepped)
    bool mDiverged = false; ///< A residual was not finite (the step stopped there)
    int mCoarseUnknowns = 0; ///< Unknowns of the coarse correction the solves used (0: block Jacobi alone)
};

/// fem::TetSolver::StepImplicit as compute shaders: backward Euler with Rayleigh damping for both elastic
/// models, Newton on the end velocity (forces and frames re-evaluated at x0 + h v per iteration) with the
/// same convergence test (the energy of the remaining correction, 1/2 r.Br, against mImplicitTolerance of the
/// step's kinetic and load energy and the crack-safe energy), each linear solve a conjugate gradient
/// preconditioned by the nodes' 3x3 diagonal blocks (block Jacobi; the CPU's factored rest system needs
/// sequential triangular solves) plus, where SetCoarseSpace gave one, the coarse correction on the rigid
/// modes of node aggregates (fem::TetCoarseSpace: a gather per aggregate, a dense product with the coarse
/// inverse, a scatter per node; three more dispatches per iteration). The scalars of an iteration stay on the
/// GPU: the host reads them back once per Newton iteration and at CG iterations 1, 2, 4, 8, then every 8th (a
/// sync each), so a solve may run up to 7 iterations past its tolerance. Deterministic: fixed-order gathers
/// and reductions, no float atomics.
class GpuImplicitStep
{
public:
    /// Compiles the step's programs on inDevice; with inStVenantKirchhoff also the pass that keeps each
    /// element's F and S+ per Newton iteration (the model the solver steps).
    static Result<GpuImplicitStep> Create(std::shared_ptr<ComputeDevice> inDevice, bool inStVenantKirchhoff);
    GpuImplicitStep() = default;

    /// One step from the current positions and velocities (the caller's buffers bound, see
    /// GpuImplicitStepInput); writes the new positions and velocities and raises the status flag on a
    /// non-finite state.
    GpuImplicitStepStats Step(const GpuImplicitStepInput& inInput);

    /// The coarse space the next steps' solves add to block Jacobi (its inverse as floats), or none (null or
    /// no aggregate): block Jacobi alone. A space for another node count than a step's is not used by it.
    Status SetCoarseSpace(const fem::TetCoarseSpace* inSpace);
    /// Turns the coarse space's aggregates (#A rotations from the frame it was built in; SetCoarseSpace
    /// starts them unturned): each aggregate's modes and coarse system are its built ones turned rigidly.
    void TurnCoarseSpace(std::span<const Mat3> inTurns);

private:
    // The step's vectors for inNodes nodes and inElements elements (kept while the counts stay).
    Status Reserve(std::size_t inNodes, std::size_t inElements);
    // a . b into the scalars in inMode (TetDot).
    void Dot(const StorageBuffer& inA, const StorageBuffer& inB, std::uint32_t inMode) const;
    // One TetConjugateGradient operation over the nodes.
    void NodeOperation(std::uint32_t inOperation) const;
    // K inDirection into the product corners; with inNewDirection, K (z + beta inDirection).
    void StiffnessProduct(const StorageBuffer& inDirection, bool inNewDirection) const;
    // Binds the St. Venant-Kirchhoff linearisation for the next pass that reads it (its binding is shared).
    void BindLinearization() const;
    // z += P (P^T A0 P)^-1 P^T r on the residual and preconditioned vectors (when a coarse space is set).
    void CoarseCorrection() const;

    std::shared_ptr<ComputeDevice> mDevice;
    bool mStVenantKirchhoff = false; // the model the solver steps: TetStvkLinearization runs
    ComputeProgram mProduct, mResidual, mJacobi, mConjugateGradient, mDot, mScale, mLinearize, mCoarse;
    StorageBuffer mStartPositions, mStartVelocities, mResidualVector, mPreconditioned, mDirection,
        mOperatorProduct, mSolution, mBlocks, mProducts, mScalars, mLinearization;
    std::size_t mNodeCount = 0, mElementCount = 0;
    // The coarse space (SetCoarseSpace): per node its rest offset and aggregate, the aggregates' members, the
    // coarse vectors and inverse; used while a step's node count is mCoarseNodeCount
    StorageBuffer mCoarseNodes, mCoarseMembers, mCoarseValues;
    std::uint32_t mCoarseAggregates = 0;
    std::size_t mCoarseNodeCount = 0;
    std::vector<Vec3> mCoarseOffsets; // the space's node offsets as built (TurnCoarseSpace turns them)
    std::vector<int> mCoarseNodeAggregate;
    bool mCoarseActive = false;                            // of the step running
    std::uint32_t mRunNodeCount = 0, mRunElementCount = 0; // of the step running
};

} // namespace crumple::gpu
