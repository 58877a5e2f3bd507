// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/fem/TetSolver.h>
#include <crumple/props/CollisionImpulses.h>
#include <crumple/plugin/Collision.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace crumple::gpu
{
class ComputeDeviceProvider; // crumple/gpu/ComputeDevice.h, when the build has crumple::gpu
class GpuTetSolver;          // crumple/gpu/GpuTetSolver.h
} // namespace crumple::props

namespace crumple::props
{

/// True in builds whose crumple::props has the GPU backend (crumple::gpu was built), false elsewhere.
CRUMPLE_API bool HasGpuBackend();

/// Where a prop's FEM runs.
enum class EFemBackend : std::uint8_t
{
    Cpu, ///< fem::TetSolver, double precision: every feature
    Gpu, ///< gpu::GpuTetSolver, float, compute shaders: symplectic and implicit Euler, both elastic models,
         ///< damping, plasticity and fracture (only in builds with crumple::gpu; elsewhere a GPU request runs
         ///< on the CPU with that reason)
};

/// Short name of an EFemBackend, for messages.
CRUMPLE_API const char* ToString(EFemBackend inBackend);

/// How a FemProp chooses its backend.
struct CRUMPLE_API FemPropSettings
{
    EFemBackend mBackend = EFemBackend::Cpu; ///< The wanted backend
    /// Called once with the reason when a GPU prop falls back to the CPU (no device, or programs the device
    /// cannot build); empty: no log. The reason is also in GetFallbackReason().
    std::function<void(std::string_view)> mLog;
};

/// A destructible prop's solver on the CPU or the GPU behind one interface, so a game can balance load per
/// prop. A prop that asks for the GPU where there is none (or whose programs the device cannot build) runs on
/// the CPU instead: GetBackend() says which, GetFallbackReason() why. Bad input (mesh, material, settings) is
/// an error either way, never a fallback. A CPU prop never touches the device provider, so a scene without
/// GPU props makes no EGL context, and a game built without crumple::gpu (CRUMPLE_WITH_GPU off) links this
/// type without EGL or OpenGL: the GPU backend is compiled in only where crumple::gpu is (HasGpuBackend()).
///
/// Lives in crumple::props, the layer that knows both the damage core (plugin::Collision) and the FEM: the
/// FEM itself depends on Eigen only.
class CRUMPLE_API FemProp
{
public:
    /// @param ioProvider  shared device provider of the scene; may be nullptr for CPU-only scenes
    static Result<FemProp> Create(gpu::ComputeDeviceProvider* ioProvider, const fem::TetMesh& inMesh,
                                  const fem::FemMaterialSettings& inMaterial, const fem::TetSolverSettings& inSettings,
                                  const FemPropSettings& inPropSettings);

    /// Refuses prop settings Create would refuse (a backend that is not an EFemBackend), for callers that
    /// build the solver themselves before FromSolver
    static Status CheckSettings(const FemPropSettings& inPropSettings);

    /// A prop in the state of a CPU solver (positions, velocities, anchors, forces, gravity, cracks): on the
    /// CPU as it is, or moved to the GPU (gpu::GpuTetSolver::CreateFrom) when inPropSettings ask for it and
    /// the GPU can run it; otherwise on the CPU with the reason, as Create. How a recorded prop is rebuilt.
    static FemProp FromSolver(gpu::ComputeDeviceProvider* ioProvider, fem::TetSolver&& ioSolver,
                              const FemPropSettings& inPropSettings);

    /// The backend actually used
    EFemBackend GetBackend() const { return mGpu ? EFemBackend::Gpu : EFemBackend::Cpu; }
    /// Why a GPU request runs on the CPU; empty otherwise
    const std::string& GetFallbackReason() const { return mFallbackReason; }

    /// As fem::TetSolver / GpuTetSolver.
    Status SetNodeFixed(int inNode, bool inFixed);
    Status SetNodesFixed(std::span<const int> inNodes, bool inFixed);
    /// The nodes of a piece that left the prop (handed over as a body of its own,
    /// PropWorld::TakeLooseFragments): fixed where they are, and from now on no collision lands on an element
    /// with one of them now (ApplyCollision leaves those elements out; elements keep their indices through
    /// later cracks, which renumber the nodes they split). The piece's elements stay in the mesh, fixed where
    /// it broke off, and overlap what is left of the prop there: a contact with the rest found them as its
    /// nearest elements, and its impulse vanished into their fixed nodes (the racing fence's held body then
    /// met the car at rest, as a wall, step after step). Refused, changing nothing, for a node out of range.
    Status SetNodesLeft(std::span<const int> inNodes);
    Status ApplyImpulse(int inNode, const Vec3& inImpulse);
    Status SetExternalForce(int inNode, const Vec3& inForce);
    Status SetGravity(const Vec3& inGravity);
    Result<fem::TetStepResult> Step(double inDeltaTime);
    /// What Step(inDeltaTime) would refuse before doing anything (fem::TetSolver::CheckStep). Changes nothing.
    Status CheckStep(double inDeltaTime) const;
    /// fem::TetSolver::Prepare on the CPU (the GPU solver factors nothing: it only checks the step)
    Status Prepare(double inDeltaTime);
    /// How far each contact's impulse spreads over the prop's nodes (ContactSpread::mRadius, m, finite, >= 0;
    /// 0, the default: the containing element's four nodes). Set it before the prop is recorded (PropWorld::
    /// AddProp with a recorder attached, or AttachRecorder): the recording holds the radius it had then, and a
    /// later change (through PropWorld::GetProp) is not recorded, so a replay would differ. A prop rebuilt from
    /// a PropSetup by hand (RebuildProp, FromSolver) starts at 0: set PropSetup::mContactSpread again.
    /// Refused, changing nothing, for a bad radius.
    Status SetContactSpread(double inRadius);
    double GetContactSpread() const { return mContactSpread; }
    /// Applies a dispatched collision's contact impulses (CollisionNodalImpulses, spread by
    /// GetContactSpread()) to the prop whose body is inPropBody; all or nothing. Elements of pieces that left
    /// (SetNodesLeft) take none; a prop with nothing else left takes nothing. outApplied (may be null)
    /// receives the nodal impulses applied (appended).
    Status ApplyCollision(const plugin::Collision& inCollision, plugin::BodyId inPropBody,
                          std::vector<NodalImpulse>* outApplied = nullptr);
    /// The pieces now (fem::TetFragment), as the CPU solver reports them
    std::vector<fem::TetFragment> ComputeFragments() const;
    /// Current node positions (m), #N (a readback on the GPU)
    void ReadPositions(std::vector<Vec3>& outPositions) const;
    /// Current node velocities (m/s), #N (a readback on the GPU)
    void ReadVelocities(std::vector<Vec3>& outVelocities) const;
    /// Lumped node masses (kg), #N
    const std::vector<double>& GetMasses() const;
    /// Node inverse masses (1/kg), #N: 0 where the node is fixed
    const std::vector<double>& GetInverseMasses() const;
    /// Number of nodes #N
    int GetNodeCount() const;
    /// Each element's current nodes (fracture gives a crack's sides nodes of their own)
    const std::vector<fem::TetIndices>& GetElementNodes() const;
    /// The CPU solver, or nullptr on the GPU backend
    fem::TetSolver* GetCpuSolver() { return mCpu ? &*mCpu : nullptr; }
    const fem::TetSolver* GetCpuSolver() const { return mCpu ? &*mCpu : nullptr; }
    /// The GPU solver, or nullptr on the CPU backend
    gpu::GpuTetSolver* GetGpuSolver() { return mGpu.get(); }
    const gpu::GpuTetSolver* GetGpuSolver() const { return mGpu.get(); }
    /// Links broken so far (0 for an unbreakable material)
    int GetBrokenLinkCount() const;

    FemProp(FemProp&& ioOther) noexcept;
    FemProp& operator=(FemProp&& ioOther) noexcept;
    ~FemProp();

private:
    FemProp();

    // Deletes the GPU solver; defined in FemProp.cpp, where a build without crumple::gpu never has one.
    struct GpuSolverDeleter
    {
        void operator()(gpu::GpuTetSolver* inSolver) const;
    };

    std::optional<fem::TetSolver> mCpu;
    std::unique_ptr<gpu::GpuTetSolver, GpuSolverDeleter> mGpu; // incomplete here: a CPU-only build never defines it
    std::string mFallbackReason;
    double mContactSpread = 0.0; // m, SetContactSpread
    // Per element, empty until a piece leaves: 1 for an element of a piece that left (SetNodesLeft)
    std::vector<std::uint8_t> mLeftElements;
};

} // namespace crumple::props
