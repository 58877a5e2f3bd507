// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/props/FemProp.h>

#include <crumple/base/TimeStep.h>
#include <crumple/props/CollisionImpulses.h>

#include <algorithm>
#include <limits>

#if defined(CRUMPLE_PROPS_WITH_GPU)
#include <crumple/gpu/ComputeDevice.h>
#include <crumple/gpu/GpuTetSolver.h>
#endif


namespace crumple::props
{

bool HasGpuBackend()
{
#if defined(CRUMPLE_PROPS_WITH_GPU)
    return true;
#else
    return false;
#endif
}

const char* ToString(EFemBackend inBackend)
{
    switch (inBackend)
    {
    case EFemBackend::Cpu:
        return "Cpu";
    case EFemBackend::Gpu:
        return "Gpu";
    }
    return "unknown";
}

void FemProp::GpuSolverDeleter::operator()(gpu::GpuTetSolver* inSolver) const
{
#if defined(CRUMPLE_PROPS_WITH_GPU)
    delete inSolver;
#else
    (void)inSolver; // never set without the GPU backend
#endif
}

FemProp::FemProp() = default;
FemProp::FemProp(FemProp&& ioOther) noexcept = default;
FemProp& FemProp::operator=(FemProp&& ioOther) noexcept = default;
FemProp::~FemProp() = default;

Result<FemProp> FemProp::Create(gpu::ComputeDeviceProvider* ioProvider, const fem::TetMesh& inMesh,
                                const fem::FemMaterialSettings& inMaterial, const fem::TetSolverSettings& inSettings,
                                const FemPropSettings& inPropSettings)
{
    if (Status valid = CheckSettings(inPropSettings); valid.HasError())
        return valid.GetError();

    // Bad input is refused whatever the backend: the CPU solver validates everything.
    Result<fem::TetSolver> cpu = fem::TetSolver::Create(inMesh, inMaterial, inSettings);
    if (cpu.HasError())
        return cpu.GetError();
    return FromSolver(ioProvider, std::move(cpu.Get()), inPropSettings);
}

Status FemProp::CheckSettings(const FemPropSettings& inPropSettings)
{
    if (inPropSettings.mBackend != EFemBackend::Cpu && inPropSettings.mBackend != EFemBackend::Gpu)
        return MakeError(EError::InvalidArgument, "FemPropSettings.mBackend is not an EFemBackend");
    return Status::Ok();
}

FemProp FemProp::FromSolver(gpu::ComputeDeviceProvider* ioProvider, fem::TetSolver&& ioSolver,
                            const FemPropSettings& inPropSettings)
{
    FemProp prop;
    if (inPropSettings.mBackend == EFemBackend::Gpu)
    {
#if defined(CRUMPLE_PROPS_WITH_GPU)
        // The device, made on the first GPU prop of the scene; then the GPU solver, which refuses what it
        // cannot do yet. Either failure is a fallback with its reason, not an error.
        Result<std::shared_ptr<gpu::ComputeDevice>> device =
            ioProvider != nullptr ? ioProvider->Acquire()
                                  : Result<std::shared_ptr<gpu::ComputeDevice>>(
                                        MakeError(EError::InvalidArgument, "no ComputeDeviceProvider given"));
        if (device.IsValid())
        {
            Result<gpu::GpuTetSolver> gpu = gpu::GpuTetSolver::CreateFrom(device.Get(), ioSolver);
            if (gpu.IsValid())
            {
                prop.mGpu.reset(new gpu::GpuTetSolver(std::move(gpu.Get())));
                return prop;
            }
            prop.mFallbackReason = gpu.GetError().mMessage;
        }
        else
            prop.mFallbackReason = device.GetError().mMessage;
#else
        (void)ioProvider;
        prop.mFallbackReason = "this build of Crumple has no GPU backend (crumple::gpu was not built: "
                               "CRUMPLE_WITH_GPU off or EGL/OpenGL missing)";
#endif
        if (inPropSettings.mLog)
            inPropSettings.mLog("FemProp: GPU requested, running on the CPU: " + prop.mFallbackReason);
    }
    prop.mCpu.emplace(std::move(ioSolver));
    return prop;
}

// Each call goes to the GPU solver when the prop has one (only possible in builds with crumple::gpu), else
// to the CPU solver.
#if defined(CRUMPLE_PROPS_WITH_GPU)
#define CRUMPLE_PROPS_ON_GPU(inCall)                                                                                \
    if (mGpu)                                                                                                      \
        return mGpu->inCall;
#else
#define CRUMPLE_PROPS_ON_GPU(inCall)
#endif

Status FemProp::SetNodeFixed(int inNode, bool inFixed)
{
    CRUMPLE_PROPS_ON_GPU(SetNodeFixed(inNode, inFixed))
    return mCpu->SetNodeFixed(inNode, inFixed);
}

Status FemProp::SetNodesFixed(std::span<const int> inNodes, bool inFixed)
{
    CRUMPLE_PROPS_ON_GPU(SetNodesFixed(inNodes, inFixed))
    return mCpu->SetNodesFixed(inNodes, inFixed);
}

Status FemProp::SetNodesLeft(std::span<const int> inNodes)
{
    if (Status fixed = SetNodesFixed(inNodes, true); fixed.HasError())
        return fixed; // checks every node before it fixes any
    std::vector<std::uint8_t> left(static_cast<std::size_t>(GetNodeCount()), 0);
    for (int node : inNodes)
        left[static_cast<std::size_t>(node)] = 1;
    const std::vector<fem::TetIndices>& elements = GetElementNodes();
    mLeftElements.resize(elements.size(), 0);
    for (std::size_t element = 0; element < elements.size(); ++element)
        for (int node : elements[element])
            mLeftElements[element] |= left[static_cast<std::size_t>(node)];
    return Status::Ok();
}

Status FemProp::ApplyImpulse(int inNode, const Vec3& inImpulse)
{
    CRUMPLE_PROPS_ON_GPU(ApplyImpulse(inNode, inImpulse))
    return mCpu->ApplyImpulse(inNode, inImpulse);
}

Status FemProp::SetExternalForce(int inNode, const Vec3& inForce)
{
    CRUMPLE_PROPS_ON_GPU(SetExternalForce(inNode, inForce))
    return mCpu->SetExternalForce(inNode, inForce);
}

Status FemProp::SetGravity(const Vec3& inGravity)
{
    CRUMPLE_PROPS_ON_GPU(SetGravity(inGravity))
    return mCpu->SetGravity(inGravity);
}

Result<fem::TetStepResult> FemProp::Step(double inDeltaTime)
{
    CRUMPLE_PROPS_ON_GPU(Step(inDeltaTime))
    return mCpu->Step(inDeltaTime);
}

Status FemProp::CheckStep(double inDeltaTime) const
{
    CRUMPLE_PROPS_ON_GPU(CheckStep(inDeltaTime))
    return mCpu->CheckStep(inDeltaTime);
}

Status FemProp::Prepare(double inDeltaTime)
{
    if (mCpu)
        return mCpu->Prepare(inDeltaTime);
    return CheckTimeStep(inDeltaTime, "FemProp::Prepare");
}

Status FemProp::SetContactSpread(double inRadius)
{
    if (Status radius = CheckContactSpreadRadius(inRadius, "FemProp::SetContactSpread"); radius.HasError())
        return radius;
    mContactSpread = inRadius;
    return Status::Ok();
}

Status FemProp::ApplyCollision(const plugin::Collision& inCollision, plugin::BodyId inPropBody,
                               std::vector<NodalImpulse>* outApplied)
{
    // intent: the CPU solver's positions in place; the GPU's read back
    std::vector<Vec3> read_back;
    if (!mCpu)
        ReadPositions(read_back);
    const std::span<const Vec3> positions = mCpu ? std::span<const Vec3>(mCpu->GetPositions()) : std::span<const Vec3>(read_back);
#if defined(CRUMPLE_PROPS_WITH_GPU)
    const std::vector<double>& inverse_masses = mGpu ? mGpu->GetInverseMasses() : mCpu->GetInverseMasses();
    const double limit = mGpu ? static_cast<double>(std::numeric_limits<float>::max()) : fem::TetSolver::cMaxStateMagnitude;
#else
    const std::vector<double>& inverse_masses = mCpu->GetInverseMasses();
    const double limit = fem::TetSolver::cMaxStateMagnitude;
#endif
    const ContactSpread spread{.mRadius = mContactSpread, .mMasses = GetMasses(), .mInverseMasses = inverse_masses};
    // intent: the elements still the prop's; a piece that left keeps its elements, fixed where it broke off
    const std::vector<fem::TetIndices>& all = GetElementNodes();
    std::vector<fem::TetIndices> kept;
    if (!mLeftElements.empty())
    {
        kept.reserve(all.size());
        for (std::size_t element = 0; element < all.size(); ++element)
            if (mLeftElements[element] == 0)
                kept.push_back(all[element]);
        if (kept.empty())
            return Status::Ok();
    }
    const std::span<const fem::TetIndices> elements = mLeftElements.empty()
                                                          ? std::span<const fem::TetIndices>(all)
                                                          : std::span<const fem::TetIndices>(kept);
    Result<std::vector<NodalImpulse>> impulses =
        CollisionNodalImpulses(inCollision, inPropBody, elements, positions, spread);
    if (impulses.HasError())
        return impulses.GetError();
    // intent: all or nothing: every struck node's velocity checked before any impulse lands (the GPU's floats)
    std::vector<Vec3> velocities;
    ReadVelocities(velocities);
    if (Status fits = CheckNodalImpulses(impulses.Get(), velocities, inverse_masses, limit); fits.HasError())
        return fits;
    // Node indices come from the solver's own connectivity and every velocity stays in range: none can be
    // refused, so the collision applies in full.
    for (const NodalImpulse& impulse : impulses.Get())
        if (Status status = ApplyImpulse(impulse.mNode, impulse.mImpulse); status.HasError())
            return status;
    if (outApplied != nullptr)
        outApplied->insert(outApplied->end(), impulses.Get().begin(), impulses.Get().end());
    return Status::Ok();
}

std::vector<fem::TetFragment> FemProp::ComputeFragments() const
{
    CRUMPLE_PROPS_ON_GPU(ComputeFragments())
    return mCpu->ComputeFragments();
}

void FemProp::ReadPositions(std::vector<Vec3>& outPositions) const
{
#if defined(CRUMPLE_PROPS_WITH_GPU)
    if (mGpu)
    {
        mGpu->ReadPositions(outPositions);
        return;
    }
#endif
    outPositions = mCpu->GetPositions();
}

void FemProp::ReadVelocities(std::vector<Vec3>& outVelocities) const
{
#if defined(CRUMPLE_PROPS_WITH_GPU)
    if (mGpu)
    {
        mGpu->ReadVelocities(outVelocities);
        return;
    }
#endif
    outVelocities = mCpu->GetVelocities();
}

const std::vector<double>& FemProp::GetMasses() const
{
    CRUMPLE_PROPS_ON_GPU(GetMasses())
    return mCpu->GetMasses();
}

const std::vector<double>& FemProp::GetInverseMasses() const
{
    CRUMPLE_PROPS_ON_GPU(GetInverseMasses())
    return mCpu->GetInverseMasses();
}

const std::vector<fem::TetIndices>& FemProp::GetElementNodes() const
{
    CRUMPLE_PROPS_ON_GPU(GetElementNodes())
    return mCpu->GetElementNodes();
}

int FemProp::GetBrokenLinkCount() const
{
#if defined(CRUMPLE_PROPS_WITH_GPU)
    if (mGpu)
        return static_cast<int>(std::count(mGpu->GetBrokenLinks().begin(), mGpu->GetBrokenLinks().end(), std::uint8_t{1}));
#endif
    return mCpu->GetBrokenLinkCount();
}

int FemProp::GetNodeCount() const
{
    CRUMPLE_PROPS_ON_GPU(GetNodeCount())
    return mCpu->GetNodeCount();
}

#undef CRUMPLE_PROPS_ON_GPU

} // namespace crumple::props
