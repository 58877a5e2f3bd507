// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/JobSystem.h>
#include <crumple/base/Result.h>
#include <crumple/fem/FactorRefreshLedger.h>
#include <crumple/fem/FemMaterial.h>
#include <crumple/fem/FractureLinks.h>
#include <crumple/fem/FractureTopology.h>
#include <crumple/fem/GroupPrincipalStress.h>
#include <crumple/fem/TetElementRest.h>
#include <crumple/fem/TetFragment.h>
#include <crumple/fem/TetLinearization.h>
#include <crumple/fem/TetMesh.h>
#include <crumple/fem/TetSolverSettings.h>
#include <crumple/fem/TetSolverWorkspace.h>
#include <crumple/fem/TetStepResult.h>
#include <crumple/fem/TetStepper.h>

#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace crumple::fem
{

struct TetElementPassInput; // private to the solvers (src/TetElementPass.h)
class TetFactoredPreconditioner; // private to the solver (src/TetFactoredPreconditioner.h)

/// What TetSolver::ContactEffectiveMass found.
struct CRUMPLE_API TetContactMass
{
    double mMass = 0.0;      ///< kg; +infinity when every share is on an anchored node
    int mIterations = 0;     ///< Conjugate-gradient iterations
    bool mConverged = false; ///< The solve reached its tolerance (else mMass is its last estimate)
};

/// A tetrahedral finite-element body (destructible prop): linear tetrahedra, lumped masses, the elasticity
/// model of its FemMaterial, symplectic or implicit Euler. Node and element order are the mesh's; every loop
/// is serial in that order, so two solvers given the same inputs produce bitwise the same states.
///
/// Data per node: rest and current position, velocity, mass and inverse mass (0 = anchored), external force.
/// Data per element: rest data (D_m^-1, V0) and rotation state (the corotated frame, warm start of
/// PolarRotation).
///
/// Every input is checked; a refused input returns an error and changes nothing.
class CRUMPLE_API TetSolver
{
public:
    /// Validates the material and settings and builds a solver at rest (positions = rest positions, zero
    /// velocity, no fixed node, no external force).
    static Result<TetSolver> Create(const TetMesh& inMesh, const FemMaterialSettings& inMaterial,
                                    const TetSolverSettings& inSettings);

    /// Anchors node inNode (inverse mass 0, velocity 0) or frees it again (inverse mass 1 / mass).
    Status SetNodeFixed(int inNode, bool inFixed);
    /// SetNodeFixed for each of inNodes, in their order, with the same result; refused with nothing changed if
    /// any is not a node. For many at once (a piece that broke loose: its nodes leave the prop).
    Status SetNodesFixed(std::span<const int> inNodes, bool inFixed);
    /// Bound on every coordinate of what the setters take (positions m, velocities m/s, forces N, gravity
    /// m/s^2, and the velocity an impulse leaves): far beyond any simulation, and small enough that squares,
    /// energies and their sums over the nodes stay finite (1e300 m/s made every later step "diverged")
    static constexpr double cMaxStateMagnitude = 1.0e100;

    /// Adds an impulse inImpulse (N s, world) to node inNode: dv = inImpulse / m. An anchored node absorbs
    /// it. Refused, changing nothing, for an impulse that is not finite or would leave the node's velocity
    /// beyond cMaxStateMagnitude (NonFinite when it would be infinite, else OutOfRange).
    Status ApplyImpulse(int inNode, const Vec3& inImpulse);
    /// Sets the constant external force (N, world) on node inNode until changed; forces on anchored nodes do
    /// nothing.
    Status SetExternalForce(int inNode, const Vec3& inForce);
    /// Sets every external force to zero.
    void ClearExternalForces();
    /// Sets the acceleration of gravity (m/s^2, world).
    Status SetGravity(const Vec3& inGravity);
    /// Replaces all node positions (m, world), #N; for deforming a body directly or restoring a saved state.
    Status SetPositions(std::span<const Vec3> inPositions);
    /// Replaces all node velocities (m/s, world), #N; anchored nodes keep velocity 0.
    Status SetVelocities(std::span<const Vec3> inVelocities);
    /// Ends sleep without changing the state.
    void WakeUp();
    /// Runs the element passes of Step() and SolveStatic() (forces with the polar decompositions, stiffness
    /// products) on the host's job system, or serially when inJobs is null (the default). The results are
    /// bitwise the same for any number of workers and any scheduling: each element writes only its own slots
    /// and each node sums its elements' in element order. inJobs must outlive its use (or be replaced);
    /// Step() and SolveStatic() call it from the calling thread only.
    void SetJobSystem(const JobSystem* inJobs);

    /// Advances by inDeltaTime (s, > 0, finite). Refused (nothing changes) when symplectic Euler would need
    /// more than mMaxSubSteps sub-steps. A step that diverges is retried from its start split into 2, 4, ...
    /// pieces (up to 2^mMaxStepSplits); if all fail the state is restored to the start of the step and the
    /// result reports ETetStepEvent::Diverged. A divergence is therefore not an error of the call, and a NaN
    /// never reaches the state.
    Result<TetStepResult> Step(double inDeltaTime);
    /// Does now what the first Step(inDeltaTime) would do first: sizes the step's scratch and, for the implicit
    /// integrator with EImplicitPreconditioner::RestFactorization, factors the rest system of this step length
    /// (s, finite, > 0; counted by GetFactorizationCount). For a game's level load: the first hit on a prop
    /// then does not pay the factorisation in its frame (fracture, a change of anchors or another step length
    /// factor again). Changes no state, so results are the same with and without it. Refused for a step
    /// length that is not finite and > 0; a symplectic step Step() would refuse (too many sub-steps) is
    /// not checked here.
    Status Prepare(double inDeltaTime);
    /// What Step(inDeltaTime) would refuse before doing anything: a step length (s) that is not finite and
    /// > 0, or a symplectic step that needs more sub-steps than TetSolverSettings::mMaxSubSteps. Changes
    /// nothing; lets a caller that steps several solvers (props::PropWorld) refuse a step before any moved.
    Status CheckStep(double inDeltaTime) const;
    /// The mass a contact meets in one implicit Euler step of inDeltaTime (s) from the current state (kg): an
    /// impulse J along inDirection (world, any length), shared among inNodes in proportion to inShares,
    /// changes those nodes' share-weighted mean velocity along inDirection by J / m, with
    ///   m = 1 / (w^T A^-1 w),  w_i = (share_i / sum of shares) d,  A = (1 + h alpha) M + (h^2 + h beta) K,
    /// the implicit step's system (alpha, beta: the material's mass and stiffness damping; K linearised at
    /// the current positions; anchored nodes held). It lies between the struck nodes' lumped mass (h -> 0)
    /// and infinity (the anchors, h -> inf). It is what a rigid stand-in for the prop must weigh (a held prop
    /// body: props::PropWorld::GetContactMass) for an engine's contact to take from the other body the
    /// momentum the FEM's step then gives the struck nodes. For a symplectic solver it is the same implicit
    /// estimate (its sub-steps carry a wave no farther than the implicit step's reach). +infinity when every
    /// share is on an anchored node. Preconditioned conjugate gradient to 1e-8 in at most
    /// TetSolverSettings::mCgMaxIterations: with EImplicitPreconditioner::RestFactorization (the default)
    /// preconditioned by the factored rest system of this step length (a few iterations; factored here when
    /// the solver holds none for it, as after a crack: the one its next step of that length would build and
    /// then reuses), with BlockJacobi by block Jacobi (a hundred times slower; it may stop short:
    /// TetContactMass::mConverged). Changes no state: later steps are bitwise the same. Refused for a step
    /// length that is not finite and > 0, a direction that is not finite and nonzero, nodes and shares of
    /// different sizes, a node out of range, a share that is not finite and >= 0, or shares that do not sum
    /// to a finite value above 0.
    Result<TetContactMass> ContactEffectiveMass(std::span<const int> inNodes,
                                                std::span<const double> inShares, const Vec3& inDirection,
                                                double inDeltaTime);

    /// Moves the body to static equilibrium under gravity and the external forces (velocities become 0):
    /// repeated linearisations K(x) dx = f_elastic(x) + f_ext solved by conjugate gradient, until the
    /// residual force is below inRelativeTolerance x |f_ext| (gravity included). Needs at least one anchored
    /// node. Refused, with the state unchanged, when it does not converge in inMaxIterations
    /// re-linearisations of inMaxCgIterations each. Positions are stored absolutely, so round-off puts a
    /// floor of about ulp(|x|) x stiffness under the residual: 1e-6 is reachable for a 1 m steel beam, 1e-8
    /// is not.
    Result<TetStaticResult> SolveStatic(int inMaxIterations = 20, double inRelativeTolerance = 1.0e-6,
                                        int inMaxCgIterations = 100000);

    /// Elastic forces (N, world) at the current positions, #N, without damping; zero at rest.
    void ElasticForces(std::vector<Vec3>& outForces) const;
    /// Kinetic energy 1/2 sum m v^2 (J)
    double KineticEnergy() const;
    /// Elastic (strain) energy sum V0 psi(F) (J)
    double ElasticEnergy() const;
    /// Potential of gravity and the external forces on free nodes, -sum f . (x - X) (J), zero at rest
    double ExternalPotentialEnergy() const;
    /// Mechanical energy: kinetic + elastic + external potential (J); conserved by the undamped continuous
    /// system
    double TotalEnergy() const { return KineticEnergy() + ElasticEnergy() + ExternalPotentialEnergy(); }

    /// The rest mesh as created (connectivity before any fracture, rest positions, groups)
    const TetMesh& GetMesh() const { return mMesh; }
    /// Number of nodes #N now: the mesh's nodes plus the copies fracture made (see GetElementNodes())
    int GetNodeCount() const { return static_cast<int>(mPositions.size()); }
    /// Current element -> node connectivity, #T. Equal to the mesh's until a fracture: then the nodes on a
    /// crack are duplicated and the elements on one side point to the copies. (For a breakable material,
    /// groups that touch only along an edge or at a corner get their own nodes from the start.) Element indices never change;
    /// node i < GetMesh().GetNodeCount() keeps its index, copies are appended.
    const std::vector<TetIndices>& GetElementNodes() const { return mElementNodes; }
    /// Rest position (m, body frame) of every current node, #N: a copy has its original's
    const std::vector<Vec3>& GetNodeRestPositions() const { return mNodeRestPositions; }
    /// The validated material
    const FemMaterial& GetMaterial() const { return mMaterial; }
    /// The settings, with gravity as last set by SetGravity()
    const TetSolverSettings& GetSettings() const { return mSettings; }
    /// Current node positions (m, world), #N
    const std::vector<Vec3>& GetPositions() const { return mPositions; }
    /// Current node velocities (m/s, world), #N
    const std::vector<Vec3>& GetVelocities() const { return mVelocities; }
    /// External forces (N, world), #N
    const std::vector<Vec3>& GetExternalForces() const { return mExternalForces; }
    /// Lumped node masses (kg), #N
    const std::vector<double>& GetMasses() const { return mMasses; }
    /// Inverse masses (1/kg), #N; 0 for anchored nodes
    const std::vector<double>& GetInverseMasses() const { return mInverseMasses; }
    /// Plastic strain of every element (in its model's frame: rotated for the corotated model), #T; empty when
    /// the material has no plasticity (infinite yield stress)
    const std::vector<Mat3>& GetPlasticStrains() const { return mPlasticStrains; }
    /// The links fracture can break (empty for an unbreakable material)
    const FractureLinks& GetFractureLinks() const { return mLinks; }
    /// #L, 1 where a link is broken (empty for an unbreakable material)
    const std::vector<std::uint8_t>& GetBrokenLinks() const { return mBroken; }
    /// Number of broken links
    int GetBrokenLinkCount() const;
    /// The strain energy (J) below which the implicit step's Newton test also stops for a breakable material
    /// (CrackSafeEnergy() of the smallest group and mCrackStressTolerance); infinity when unbreakable
    double GetCrackSafeEnergy() const { return mCrackSafeEnergy; }
    /// Largest principal stress of each group's mean stress at the end of the last step, #G (empty for an
    /// unbreakable material, zeros before the first step)
    const std::vector<PrincipalStress>& GetGroupPrincipalStress() const { return mPrincipal; }
    /// The connected pieces now (TetFragments), ordered by lowest group; one piece while nothing is broken
    /// and the groups are joined through faces. O(#T) for a breakable material (O(#T log #T) otherwise, which
    /// builds the links); call it after a step that reported ETetStepEvent::Fractured.
    std::vector<TetFragment> ComputeFragments() const;
    /// Element rest data, #T
    const std::vector<TetElementRest>& GetElementRest() const { return mRest; }
    /// Element rotations, #T: corotated frames after the last step as unit quaternions (identity for
    /// St. Venant-Kirchhoff)
    const std::vector<Quat>& GetElementRotations() const { return mRotations; }
    /// The symplectic Euler sub-step (s) that Step() divides its time step by
    double GetStableTimeStep() const { return mStableTimeStep; }
    /// True while asleep
    bool IsSleeping() const { return mStepper.IsSleeping(); }
    /// True when no node moves, no external force acts and nothing is strained (positions at the nodes' rest
    /// positions, no plastic strain), compared exactly: with no gravity on a free node, a step could not move
    /// anything (the solver then sleeps at its first step). A GPU solver made from this state knows it without
    /// a readback.
    bool IsStillAndUnstrained() const;
    /// Element evaluations done by Step() and SolveStatic() so far (force, stiffness-product, diagonal and
    /// energy passes, one per element each; elements whose corners are all anchored are skipped and not
    /// counted): a cost counter that tests can compare instead of timing
    std::uint64_t GetElementWorkCount() const { return mElementWork; }
    /// Factorisations of the rest system done so far (EImplicitPreconditioner::RestFactorization): one on the
    /// first implicit step or static solve, one more after each change of connectivity (fracture), anchors
    /// or step length (and after a step that refreshed the factor and was restored, or a refresh that
    /// failed); a cost counter like GetElementWorkCount()
    int GetFactorizationCount() const { return mFactorizationCount; }
    /// Refreshes of the factor at the current element frames (TetSolverSettings::mFactorRefreshIterations,
    /// mFactorRefreshByCost): successful numeric refactorisations within or before a solve whose frames had
    /// drifted; a cost counter like GetFactorizationCount()
    int GetFactorRefreshCount() const { return mFactorRefreshCount; }
    /// What a refresh of the factored system held now costs, in conjugate-gradient iterations of an implicit
    /// solve (operation counts: TetFactoredPreconditioner::GetRefreshCostInIterations; what
    /// mFactorRefreshByCost weighs extra iterations against). 0 without a factor.
    double GetFactorRefreshCost() const;

private:
    // Sub-steps of a symplectic step of inDeltaTime, refused beyond mMaxSubSteps.
    Result<int> SymplecticSubSteps(double inDeltaTime) const;
    TetSolver(const TetMesh& inMesh, const FemMaterial& inMaterial, const TetSolverSettings& inSettings);

    // Element pass input with the current connectivity and plastic strains, skipping the elements with no
    // free corner (they cannot move: a piece handed to the engine costs no element work).
    TetElementPassInput PassInput() const;
    // The same over every element: the public ElasticForces() and ElasticEnergy() (reactions at anchors).
    TetElementPassInput EveryElementInput() const;
    // PassInput() with the host's jobs and the gather scratch prepared for the current connectivity, when a
    // job system with more than one worker is set.
    TetElementPassInput ParallelPassInput();
    // Density x rest volume per element (kg).
    std::vector<double> ElementMasses() const;
    // One step of plastic flow; returns the number of elements that flowed.
    int FlowPlastically(double inDeltaTime);
    // Rankine fracture on the current state; returns the number of links broken.
    int Fracture();
    // Moves node state onto a new connectivity after fracture.
    void Reconnect(const FractureConnectivity& inConnectivity);
    // Plastic flow and fracture after each symplectic sub-step or implicit piece.
    void AfterSubStep(double inDeltaTime);
    // What plasticity and fracture change, kept to restore a diverged step.
    struct ShapeState
    {
        std::vector<TetIndices> mElementNodes;
        std::vector<Vec3> mNodeRestPositions;
        std::vector<double> mMasses;
        std::vector<double> mInverseMasses;
        std::vector<std::uint8_t> mFree;
        std::vector<Vec3> mExternalForces;
        std::vector<Mat3> mPlasticStrains;
        std::vector<std::uint8_t> mBroken;
        std::vector<PrincipalStress> mPrincipal;
        double mFreeMass = 0.0;
    };
    void SaveShape(ShapeState& outShape) const;
    void RestoreShape(const ShapeState& inShape);

    // SetNodeFixed's change of one checked node, without waking the stepper; true when it changed
    bool FixNode(int inNode, bool inFixed);
    // After a crack or new anchors, a refreshing solver's next factorisation (a new pattern) is at the
    // current element frames: mFactorFrames = mRotations, those of the last element pass, where the next
    // step's first solve is linearised. At its last refresh's frames that solve spent
    // mFactorRefreshIterations and refreshed anyway (nearly every step after a crack of the racing fence).
    // Set here, as solver state, and not when the factor is built, so that a copy, a replay and Prepare
    // factor at the same frames.
    void FollowFramesAfterNewSystem();
    // A node's anchoring changed (SetNodeFixed, SetNodesFixed): the factor's frames follow, and the last
    // pass's energy no longer counts the elements the passes now evaluate.
    void AnchorsChanged();
    // Marks that an input changed: wake up and take a new energy reference before the next step.
    void InputChanged();
    // Symplectic Euler over inDeltaTime in inSubSteps sub-steps.
    void StepSymplectic(double inDeltaTime, int inSubSteps);
    // One implicit Euler step; fills the solver statistics of ioResult.
    void StepImplicit(double inDeltaTime, TetStepResult& ioResult);
    // The factored system inMassScale M + inStiffnessScale K for the current connectivity and anchors,
    // factored again when they or the scales changed (K at mFactorFrames for a refreshing solver's implicit
    // system; the rest stiffness K0 otherwise); null when the settings ask for block Jacobi or the system
    // cannot be factored.
    TetFactoredPreconditioner* FactoredRestSystem(const TetElementPassInput& inInput, double inMassScale,
                                                  double inStiffnessScale);
    // True when the implicit solves refresh the factor (mFactorRefreshIterations > 0, corotated, factored).
    bool RefreshesFactor() const;
    // Newton's line-search merit at the current iterate (the last element pass's energy, mPassEnergy): the
    // incremental potential of implicit Euler, 1/2 |v - v0|_M^2 + h alpha/2 |v|_M^2 + E(x0 + h v) -
    // h v . (f_ext + M g), whose gradient in v is minus the momentum residual (stiffness damping left out).
    // An exact step minimises it, so an update that raises it overshot (J).
    double LineSearchMerit(double inDeltaTime, std::span<const Vec3> inStartVelocities) const;
    // At most this many halvings of one Newton update, and the relative rise of the merit they tolerate
    // (round-off of a merit of large cancelling terms).
    static constexpr int cMaxLineSearchHalvings = 4;
    static constexpr double cLineSearchSlack = 1.0e-12;
    // mFactorFrames = inFrames, the step's start frames kept for RestoreStepStart first; inByCost: a refresh
    // mRefreshLedger asked for (its next solve judges it).
    void KeepFactorFrames(std::span<const Quat> inFrames, bool inByCost = false);
    // ioFactor refactored at the current element frames mRotations (the rest factor should that fail); false
    // when both failed and ioFactor holds no factor. inByCost: asked for by mRefreshLedger.
    bool RefreshFactor(TetFactoredPreconditioner& ioFactor, const TetElementPassInput& inInput,
                       double inMassScale, double inStiffnessScale, bool inByCost = false);
    // Gravity plus external force on each free node, zero on anchored ones (N).
    void LoadForces(std::vector<Vec3>& outForces) const;
    // Kinetic, elastic and external-potential energy and the content C at the current state; updates the
    // rotations.
    struct EnergyParts
    {
        double mKinetic = 0.0;
        double mElastic = 0.0;
        double mPotential = 0.0;
        double mPotentialMagnitude = 0.0;
    };
    EnergyParts MeasureEnergy();
    // MeasureEnergy(), but with the elastic energy of the implicit step's last force pass when it was taken
    // at the current positions and shape (saves an element pass per step).
    EnergyParts MeasuredOrPassEnergy();
    // The external potential -sum f . (x - X) (J) of gravity and the external forces on free nodes, and its
    // scale sum |f . (x - X)| (J); touches no element.
    void ExternalPotential(double& outPotential, double& outMagnitude) const;

    TetMesh mMesh;
    std::vector<TetIndices> mElementNodes;  // current connectivity (fracture duplicates nodes)
    std::vector<Vec3> mNodeRestPositions;   // rest position of each current node
    FemMaterial mMaterial;
    TetSolverSettings mSettings;
    std::vector<TetElementRest> mRest;
    std::vector<double> mMasses;
    std::vector<double> mInverseMasses;
    std::vector<std::uint8_t> mFree; // 1 where mInverseMasses > 0
    std::vector<Vec3> mPositions;
    std::vector<Vec3> mVelocities;
    std::vector<Vec3> mExternalForces;
    std::vector<Quat> mRotations;
    std::vector<Mat3> mPlasticStrains;       // #T, empty without plasticity
    FractureLinks mLinks;                    // empty when unbreakable
    std::vector<std::uint8_t> mBroken;       // #L
    std::vector<Mat3> mElementStress;        // #T scratch of the fracture pass
    // mElementStress holds the Cauchy stress of the evaluated elements from this implicit step's last force
    // pass (breakable, corotated): Fracture() takes it while that pass's positions stand (mForcesCached)
    bool mStressFromPass = false;
    std::vector<PrincipalStress> mPrincipal; // #G
    double mCrackSafeEnergy = std::numeric_limits<double>::infinity(); // J, GetCrackSafeEnergy()
    double mStableTimeStep = 0.0;
    double mFreeMass = 0.0;
    int mStepPlasticElements = 0; // plastic flow events of the current step attempt
    int mStepBrokenLinks = 0;     // links broken by the current step attempt
    ShapeState mSavedShape;

    // Elastic energy of the last force pass of StepImplicit (J), valid while the positions and shape are
    // those it saw: SetPositions, a change of anchors and a static solve clear it; impulses and forces, which
    // leave the positions, do not (SaveStepStart's reference energy after a hit takes it).
    double mPassEnergy = 0.0;
    bool mPassEnergyValid = false;
    // mForces, mLinearization, mRotations and mPassEnergy are those of mForcePositions (the end of the last
    // implicit step) while mForcesCached: plastic flow, a crack or a restored shape clear it.
    std::vector<Vec3> mForcePositions;
    bool mForcesCached = false;

    // Energy reference for divergence detection.
    double mReferenceEnergy = 0.0;
    bool mReferenceValid = false;

    // The step policy (validation, split-retry, restore, sleep), shared with the GPU solver, and this
    // solver's side of it (TetSolver.cpp).
    TetStepper mStepper;
    class StepBackend;

    std::uint64_t mElementWork = 0;
    int mFactorizationCount = 0;
    int mFactorRefreshCount = 0;
    const JobSystem* mJobs = nullptr; // the host's, not owned

    // Scratch reused across steps (no allocation per step once sized).
    std::vector<TetLinearization> mLinearization;
    std::vector<Vec3> mForces;
    std::vector<Vec3> mSavedPositions;
    std::vector<Vec3> mSavedVelocities;
    std::vector<Quat> mSavedRotations;
    // The element frames the factored system was last refreshed at, or those of the last element pass before
    // a crack or a change of anchors (FollowFramesAfterNewSystem; empty: the rest frames). Solver state,
    // not workspace: a copy, or a factor rebuilt after a static solve, factors at the same frames and so
    // continues bit for bit. Saved (once per step, when a refresh or crack first changes them) for a restore.
    std::vector<Quat> mFactorFrames;
    std::vector<Quat> mSavedFactorFrames;
    bool mFactorFramesSaved = false;
    // What the factor's frames have cost since they were set (mFactorRefreshByCost); solver state like the
    // frames, saved at a step's start.
    FactorRefreshLedger mRefreshLedger;
    FactorRefreshLedger mSavedRefreshLedger;
    // #T, 1 for an element with a free corner (the passes skip the others: TetElementPassInput::
    // mElementActive), empty while every element has one; rebuilt by PassInput() after anchors or the
    // connectivity change. mActiveElementCount counts the evaluated ones (GetElementWorkCount()).
    mutable std::vector<std::uint8_t> mElementActive;
    mutable std::size_t mActiveElementCount = 0;
    mutable bool mElementActiveValid = false;
    std::vector<Vec3> mStartPositions;
    std::vector<Vec3> mStartVelocities;
    TetSolverWorkspace mWorkspace; // linear-solve scratch and the factored rest system
};

} // namespace crumple::fem
