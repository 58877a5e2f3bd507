// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Result.h>
#include <crumple/fem/FemMaterial.h>
#include <crumple/fem/FractureLinks.h>
#include <crumple/fem/TetCoarseSpace.h>
#include <crumple/fem/TetElementRest.h>
#include <crumple/fem/TetFragment.h>
#include <crumple/fem/TetMesh.h>
#include <crumple/fem/TetSolver.h>
#include <crumple/fem/TetSolverSettings.h>
#include <crumple/fem/TetStepResult.h>
#include <crumple/fem/TetStepper.h>
#include <crumple/gpu/ComputeDevice.h>
#include <crumple/gpu/ComputeProgram.h>
#include <crumple/gpu/StorageBuffer.h>

#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <vector>

namespace crumple::gpu
{

class GpuImplicitStep; // private (src/GpuImplicitStep.h)

/// The tetrahedral FEM of fem::TetSolver as GLSL compute shaders (the GPU destruction paper, section IV, in
/// compute form), in single precision: the same mesh, material and settings structs, the same symplectic
/// Euler with the same proven stable sub-step (fem::StableTimeStep), the same corotated or St.
/// Venant-Kirchhoff elasticity with Rayleigh damping. Per sub-step an element pass writes each element's four
/// corner forces, then a node pass gathers them per node through an adjacency list in element order
/// (deterministic: no float atomics) and integrates.
///
/// Structure of arrays on the GPU: positions with the inverse mass in w, velocities, external forces (vec4
/// each), element nodes (ivec4), rest data (three vec4 per element), rotations (quaternions), corner forces,
/// adjacency offsets and entries. Nothing is read back per explicit step except the status words (the
/// divergence flag, links opened, kinetic energy, plastic flow events; the implicit step also reads its
/// scalars, below); positions are read only when asked (ReadPositions).
///
/// Fracture (breakable materials) runs the CPU's criterion after every sub-step in three more passes:
/// element Cauchy stress, group principal stress (closed-form eigen solution), and the links that open
/// (fem::OpenCracks, the same byte-per-link state as the CPU). A breakable prop therefore reads the 8-byte
/// status after every sub-step; when links opened, the broken flags and the node state come back, the
/// CPU's fem::FractureTopology duplicates the nodes, and the new connectivity goes up (cracks are rare, so
/// this costs little, but the per-sub-step status read is a GPU sync: on a discrete GPU it dominates small
/// props). ComputeFragments() reports the pieces as the CPU does.
///
/// Sleep as on the CPU (TetSolverSettings::mSleepSpeed, mSleepStepCount): the kinetic energy comes from a
/// one-work-group reduction with the step's status; a sleeping prop dispatches nothing until an input
/// changes.
///
/// Implicit Euler (EIntegrator::ImplicitEuler, the default: one step per game step, stable for steel) runs
/// as the CPU's StepImplicit does, Newton on the end velocity with the same convergence test, for either
/// model (St. Venant-Kirchhoff linearised with the positive part of its stress, as the CPU); each linear
/// solve is a conjugate gradient preconditioned by the nodes' 3x3 diagonal blocks (block Jacobi) plus, with
/// TetSolverSettings::mPreconditioner RestFactorization (the default), a coarse correction on the rigid modes
/// of node aggregates from the rest system (fem::TetCoarseSpace, rebuilt on the host after a crack, an anchor
/// or a time-step change; none for a prop of fewer than 12 aggregates: GetCoarseUnknowns). The CPU's factored
/// rest system needs sequential triangular solves; here the coarse space is turned with its aggregates (their
/// rotations from the positions read back) before a step that follows a solve longer than
/// mFactorRefreshIterations, which with the default 0 is every step but the first. The scalars stay on the
/// GPU, read back once per Newton iteration and at CG iterations 1, 2, 4, 8, then every 8th
/// (GpuImplicitStep). A breakable prop runs the fracture passes after each implicit step, as after a
/// sub-step.
///
/// Plasticity as the CPU's (von Mises, radial return at the creep rate, capped): a plastic-strain buffer the
/// force and stress passes subtract, and a flow pass after each sub-step or implicit step, before fracture;
/// its event count comes back with the step's status.
///
/// Divergence is detected as a NaN or Inf in the state (the CPU also checks for an energy gain). A refused
/// input changes nothing.
class CRUMPLE_API GpuTetSolver
{
public:
    ~GpuTetSolver();
    GpuTetSolver(GpuTetSolver&& ioOther) noexcept;
    GpuTetSolver& operator=(GpuTetSolver&& ioOther) noexcept;

    /// Validates like fem::TetSolver::Create and uploads the mesh. inDevice comes from a ComputeDeviceProvider.
    static Result<GpuTetSolver> Create(std::shared_ptr<ComputeDevice> inDevice, const fem::TetMesh& inMesh,
                                       const fem::FemMaterialSettings& inMaterial,
                                       const fem::TetSolverSettings& inSettings);

    /// A GPU solver in the state of a CPU one (positions, velocities, rotations, anchoring, external forces,
    /// gravity, cracks, and its element work count: a solver that has stepped stays one that has stepped):
    /// how a prop moves from the CPU to the GPU. Refused like Create.
    static Result<GpuTetSolver> CreateFrom(std::shared_ptr<ComputeDevice> inDevice, const fem::TetSolver& inSolver);

    /// Anchors node inNode (inverse mass 0, velocity 0) or frees it again.
    Status SetNodeFixed(int inNode, bool inFixed);
    /// SetNodeFixed for each of inNodes, with the same result, in one read and one write of the node buffers
    /// over the range the nodes span (SetNodeFixed reads one node back and writes it, a device sync per node);
    /// refused with nothing changed if any is not a node.
    Status SetNodesFixed(std::span<const int> inNodes, bool inFixed);
    /// Adds inImpulse (N s, world) to node inNode: dv = inImpulse / m; an anchored node absorbs it.
    Status ApplyImpulse(int inNode, const Vec3& inImpulse);
    /// Sets the constant external force (N, world) on node inNode.
    Status SetExternalForce(int inNode, const Vec3& inForce);
    /// Sets the acceleration of gravity (m/s^2, world).
    Status SetGravity(const Vec3& inGravity);
    /// Replaces all node positions (m), #N.
    Status SetPositions(std::span<const Vec3> inPositions);

    /// Advances by inDeltaTime (s): one implicit step, or ceil(dt / GetStableTimeStep()) symplectic
    /// sub-steps, refused beyond mMaxSubSteps. A step whose state becomes NaN or Inf is retried split into 2,
    /// 4, ... as many pieces (up to 2^mMaxStepSplits, explicit ones within mMaxSubSteps); if all fail the
    /// state is restored to the start of the step and ETetStepEvent::Diverged is reported. An implicit step
    /// reports its Newton and CG iterations and residual as the CPU's does.
    Result<fem::TetStepResult> Step(double inDeltaTime);
    /// What Step(inDeltaTime) would refuse before doing anything (a step length that is not finite and > 0, or
    /// more than mMaxSubSteps sub-steps), as fem::TetSolver::CheckStep. Changes nothing.
    Status CheckStep(double inDeltaTime) const;

    /// The pieces now, as fem::TetSolver::ComputeFragments (reads positions back).
    std::vector<fem::TetFragment> ComputeFragments() const;
    /// #L, 1 where a link is broken (host copy, current after every Step); empty for an unbreakable material
    const std::vector<std::uint8_t>& GetBrokenLinks() const { return mBroken; }
    /// Current element -> node connectivity (host copy), #T
    const std::vector<fem::TetIndices>& GetElementNodes() const { return mElementNodes; }

    /// True while asleep
    bool IsSleeping() const { return mStepper.IsSleeping(); }
    /// Ends sleep without changing the state.
    void WakeUp();

    /// Reads the node positions back (m), #N (waits for the GPU); #N zeros when the device could not be made
    /// current (a lost context, or one current on another thread): callers index by node. ReadNodeState says
    /// whether the read succeeded.
    void ReadPositions(std::vector<Vec3>& outPositions) const;
    /// Reads the node velocities back (m/s), #N; zeros as ReadPositions.
    void ReadVelocities(std::vector<Vec3>& outVelocities) const;
    /// Reads each element's plastic strain back (in the model's frame, 3 by 3 symmetric), #T, as the GPU
    /// holds them (float); empty for a material without plasticity or when the device could not be made
    /// current.
    void ReadPlasticStrains(std::vector<Mat3>& outStrains) const;
    /// Reads the external forces back (N), #N, as the GPU holds them (float); zeros as ReadPositions.
    void ReadExternalForces(std::vector<Vec3>& outForces) const;
    /// The three reads above, or the device's error (the outputs then empty): for a caller that must not take
    /// zeros for a state (a recording).
    Status ReadNodeState(std::vector<Vec3>& outPositions, std::vector<Vec3>& outVelocities, std::vector<Vec3>& outForces) const;
    /// True when the state on the GPU is exactly the one it was made at rest in: every velocity and external
    /// force 0 and every position its node's rest position (as a float). The CPU's
    /// fem::TetSolver::IsStillAndUnstrained applied to the float state, so a prop recorded from the GPU and
    /// rebuilt answers the same. Reads the three node buffers back (false when that fails).
    bool IsStillAndUnstrained() const;

    /// The rest mesh
    const fem::TetMesh& GetMesh() const { return mMesh; }
    /// The material it was made with
    const fem::FemMaterialSettings& GetMaterialSettings() const { return mMaterial; }
    /// The solver settings, gravity as last set
    const fem::TetSolverSettings& GetSettings() const { return mSettings; }
    /// Each node's rest position (m, double) as the solver was made: the CPU solver's, #N then (a breakable
    /// mesh's split joints included; nodes that cracks add later are not). A state read back equal to these
    /// as floats is the made one (MakePropSetup records these doubles for it).
    const std::vector<Vec3>& GetMadeRestPositions() const { return mMadeRestPositions; }
    /// Inverse node masses (1/kg), #N, 0 where a node is anchored (host copy)
    const std::vector<double>& GetInverseMasses() const { return mInverseMasses; }

    /// Number of nodes #N
    int GetNodeCount() const { return static_cast<int>(mInverseMasses.size()); }
    /// Lumped node masses (kg), #N (host copy)
    const std::vector<double>& GetMasses() const { return mMasses; }
    /// The symplectic sub-step (s), the CPU solver's
    double GetStableTimeStep() const { return mStableTimeStep; }
    /// Element evaluations so far (one per element per sub-step), as fem::TetSolver counts them
    std::uint64_t GetElementWorkCount() const { return mElementWork; }
    /// Unknowns of the coarse correction the last implicit step's solves used (six per aggregate of
    /// fem::TetCoarseSpace; 0: block Jacobi alone: the explicit integrator, the BlockJacobi preconditioner,
    /// or a prop too small for it to help)
    int GetCoarseUnknowns() const { return mCoarseUnknowns; }
    /// Coarse spaces built so far (on the host, at rest): on the first implicit step and after a crack, an
    /// anchor or a new time step
    int GetCoarseSpaceBuilds() const { return mCoarseBuilds; }
    /// Times the coarse space was turned with its aggregates: before a step that follows a solve longer than
    /// TetSolverSettings::mFactorRefreshIterations (the default 0: every step but the first)
    int GetCoarseSpaceTurns() const { return mCoarseTurns; }
    /// The device this solver runs on
    const ComputeDevice& GetDevice() const { return *mDevice; }

private:
    // Sub-steps of a step of inDeltaTime, refused beyond mMaxSubSteps.
    Result<int> SubStepCount(double inDeltaTime) const;
    explicit GpuTetSolver(const fem::TetMesh& inMesh); // out of line: mImplicit's type is private

    // Create() on a CPU solver already validated for this mesh, material and settings (its rest data, masses,
    // stable step and links are read from it): CreateFrom() passes the prop's own solver instead of building
    // a second one.
    static Result<GpuTetSolver> CreateFromReference(std::shared_ptr<ComputeDevice> inDevice, const fem::TetMesh& inMesh,
                                                    const fem::FemMaterialSettings& inMaterial,
                                                    const fem::TetSolverSettings& inSettings,
                                                    const fem::TetSolver& inReference);

    // Runs inSubSteps sub-steps of inDeltaTime / inSubSteps (implicit: inSubSteps implicit steps, their
    // solver statistics added to ioResult), then the kinetic energy reduction; returns true when the state
    // stayed finite. Sets ioAttempt's kinetic energy (J) and plastic flow events, adds the links opened.
    bool Integrate(double inDeltaTime, int inSubSteps, fem::TetStepResult& ioResult,
                   fem::TetStepAttempt& ioAttempt);
    // The force pass's uniforms, with Kelvin-Voigt damping inStiffnessDamping (s; 0 for the implicit step,
    // which carries beta in its system).
    void SetElementPassUniforms(double inStiffnessDamping) const;
    // Plastic flow and the fracture passes after a sub-step or implicit step (the node count updated where
    // links opened; their count added to ioBrokenLinks).
    void AfterSubStep(int& ioBrokenLinks);
    // The plastic flow pass's uniforms for sub-steps of inDeltaTime (s).
    void SetPlasticUniforms(double inDeltaTime) const;
    bool IsImplicit() const { return mSettings.mIntegrator == fem::EIntegrator::ImplicitEuler; }
    // An input changed: wake up.
    void InputChanged();
    // The implicit solves' coarse space built anew (at rest) when the connectivity, the anchors or the step
    // inDeltaTime (s) changed since it was built, and turned with its aggregates when a solve since took more
    // iterations than mFactorRefreshIterations (none wanted: fem::EImplicitPreconditioner::BlockJacobi).
    void RefreshCoarseSpace(double inDeltaTime);
    // Turns the coarse space's aggregates to their nodes' current positions (a readback): each aggregate's
    // rotation from its rest offsets (the polar factor of sum (x - c) d^T, Kabsch's).
    void TurnCoarseSpace();
    // The fracture passes after a sub-step; returns the number of links opened.
    int Fracture();
    // The fracture passes' uniforms.
    void SetFractureUniforms() const;
    // Uploads a new connectivity: element nodes, adjacency, and node buffers of inPositions etc.
    Status UploadTopology(const std::vector<fem::TetIndices>& inElementNodes, const std::vector<std::array<float, 4>>& inPositions,
                          const std::vector<std::array<float, 4>>& inVelocities,
                          const std::vector<std::array<float, 4>>& inForces);
    // Duplicates nodes along the opened links (CPU topology, GPU state).
    void Reconnect();
    // Binds every buffer to its binding point.
    void BindAll() const;
    Status CheckNode(int inNode, const char* inCaller) const;
    // SetNodeFixed / SetNodesFixed, inCaller naming the call in errors
    Status FixNodes(std::span<const int> inNodes, bool inFixed, const char* inCaller);
    // A node buffer (#N float4) read back as Vec3s (waits for the GPU); empty and an error when the device
    // could not be made current.
    Status ReadNodeBuffer(const StorageBuffer& inBuffer, std::vector<Vec3>& outValues) const;

    std::shared_ptr<ComputeDevice> mDevice;
    fem::TetMesh mMesh;
    std::vector<fem::TetElementRest> mRest;
    std::vector<fem::TetIndices> mElementNodes; // host copy of the current connectivity
    fem::FractureLinks mLinks;                  // empty when unbreakable
    // J: fem::TetSolver::GetCrackSafeEnergy() of the solver it was made from
    double mCrackSafeEnergy = std::numeric_limits<double>::infinity();
    std::vector<std::uint8_t> mBroken;          // host copy of the broken flags, #L
    bool mBreakable = false;
    bool mPlastic = false;    // the material flows plastically (mPlasticPass, mPlasticStrains)
    bool mPlasticSet = false; // made from a CPU solver with a plastic set (not at rest, whatever its state)
    fem::TetSolverSettings mSettings;
    fem::FemMaterialSettings mMaterial;
    float mLambda = 0.0f;
    float mMu = 0.0f;
    std::vector<double> mMasses;        // kg, #N (CPU copy: inputs need it without a readback)
    std::vector<double> mInverseMasses; // 1/kg, #N, 0 = anchored
    std::uint32_t mElementCount = 0;
    double mStableTimeStep = 0.0;
    std::uint64_t mElementWork = 0;
    std::vector<Vec3> mMadeRestPositions; // GetMadeRestPositions
    // Set by the first integration: from then on the state is not known without a readback per step, and the
    // stepper's at-rest test answers no (a sleeping prop still sleeps by its quiet-step count). Before it, the
    // test reads the state back once per wake-up, so it answers exactly as a rebuilt prop would.
    bool mIntegrated = false;

    // The step policy (validation, split-retry, restore, sleep), the CPU solver's, and this solver's side of
    // it (GpuTetSolver.cpp): the start of a step is kept in the mSaved* buffers and, for a breakable prop, the
    // host copies below.
    fem::TetStepper mStepper;
    class StepBackend;
    std::vector<fem::TetIndices> mSavedElementNodes;
    std::vector<std::uint8_t> mSavedBroken;
    std::vector<double> mSavedMasses, mSavedInverseMasses;
    ComputeProgram mElementPass, mNodePass, mStressPass, mGroupPass, mCrackPass, mEnergyPass, mPlasticPass;
    std::unique_ptr<GpuImplicitStep> mImplicit; // the implicit step's programs and vectors; null if explicit
    // The coarse space's inputs as last built (RefreshCoarseSpace): connectivity, free nodes and step
    fem::Matrix6 mMaterialMatrix = fem::Matrix6::Zero(); // C (Pa), the CPU solver's
    std::vector<fem::TetIndices> mCoarseElementNodes;
    std::vector<std::uint8_t> mCoarseFree;
    double mCoarseTimeStep = -1.0;
    int mCoarseUnknowns = 0;
    int mLongestSolve = 0; // CG iterations of the longest solve since the space was built
    int mCoarseBuilds = 0, mCoarseTurns = 0;
    fem::TetCoarseSpace mCoarseSpace; // as last built (its aggregates and rest offsets)
    StorageBuffer mPositions, mVelocities, mElements, mRestBuffer, mRotations, mCorners, mExternal, mOffsets,
        mIncident, mStatus;
    StorageBuffer mStress, mGroupOffsets, mGroupElements, mPrincipal, mLinkBuffer, mLinkFaces, mLinkNormals,
        mBrokenBuffer;
    StorageBuffer mSavedPositions, mSavedVelocities, mSavedRotations, mSavedExternal;
    StorageBuffer mPlasticStrains, mSavedPlasticStrains; // #T x 3 columns (a dummy without plasticity)
};

} // namespace crumple::gpu
