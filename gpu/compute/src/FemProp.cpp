// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/gpu/FemProp.h>

namespace crumple::gpu
{

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

Result<FemProp> FemProp::Create(ComputeDeviceProvider* ioProvider, const fem::TetMesh& inMesh,
                                const fem::FemMaterialSettings& inMaterial, const fem::TetSolverSettings& inSettings,
                                const FemPropSettings& inPropSettings)
{
    if (inPropSettings.mBackend != EFemBackend::Cpu && inPropSettings.mBackend != EFemBackend::Gpu)
        return MakeError(EError::InvalidArgument, "FemPropSettings.mBackend is not an EFemBackend");

    // Bad input is refused whatever the backend: the CPU solver validates everything.
    Result<fem::TetSolver> cpu = fem::TetSolver::Create(inMesh, inMaterial, inSettings);
    if (cpu.HasError())
        return cpu.GetError();
    FemProp prop;
    if (inPropSettings.mBackend == EFemBackend::Gpu)
    {
        // The device, made on the first GPU prop of the scene; then the GPU solver, which refuses what it
        // cannot do yet. Either failure is a fallback with its reason, not an error.
        Result<std::shared_ptr<ComputeDevice>> device =
            ioProvider != nullptr ? ioProvider->Acquire()
                                  : Result<std::shared_ptr<ComputeDevice>>(
                                        MakeError(EError::InvalidArgument, "no ComputeDeviceProvider given"));
        if (device.IsValid())
        {
            Result<GpuTetSolver> gpu = GpuTetSolver::CreateFrom(device.Get(), cpu.Get());
            if (gpu.IsValid())
            {
                prop.mGpu.emplace(std::move(gpu.Get()));
                return prop;
            }
            prop.mFallbackReason = gpu.GetError().mMessage;
        }
        else
            prop.mFallbackReason = device.GetError().mMessage;
        if (inPropSettings.mLog)
            inPropSettings.mLog("FemProp: GPU requested, running on the CPU: " + prop.mFallbackReason);
    }
    prop.mCpu.emplace(std::move(cpu.Get()));
    return prop;
}

Status FemProp::SetNodeFixed(int inNode, bool inFixed)
{
    return mGpu ? mGpu->SetNodeFixed(inNode, inFixed) : mCpu->SetNodeFixed(inNode, inFixed);
}

Status FemProp::ApplyImpulse(int inNode, const Vec3& inImpulse)
{
    return mGpu ? mGpu->ApplyImpulse(inNode, inImpulse) : mCpu->ApplyImpulse(inNode, inImpulse);
}

Status FemProp::SetExternalForce(int inNode, const Vec3& inForce)
{
    return mGpu ? mGpu->SetExternalForce(inNode, inForce) : mCpu->SetExternalForce(inNode, inForce);
}

Status FemProp::SetGravity(const Vec3& inGravity)
{
    return mGpu ? mGpu->SetGravity(inGravity) : mCpu->SetGravity(inGravity);
}

Result<fem::TetStepResult> FemProp::Step(double inDeltaTime)
{
    return mGpu ? mGpu->Step(inDeltaTime) : mCpu->Step(inDeltaTime);
}

Status FemProp::ApplyCollision(const plugin::Collision& inCollision, plugin::BodyId inPropBody)
{
    if (mCpu)
        return fem::ApplyCollision(*mCpu, inCollision, inPropBody);
    std::vector<Vec3> positions;
    mGpu->ReadPositions(positions);
    Result<std::vector<fem::NodalImpulse>> impulses =
        fem::CollisionNodalImpulses(inCollision, inPropBody, mGpu->GetElementNodes(), positions);
    if (impulses.HasError())
        return impulses.GetError();
    // Node indices come from the solver's own connectivity and impulses are finite: none can be refused.
    for (const fem::NodalImpulse& impulse : impulses.Get())
        if (Status status = mGpu->ApplyImpulse(impulse.mNode, impulse.mImpulse); status.HasError())
            return status;
    return Status::Ok();
}

std::vector<fem::TetFragment> FemProp::ComputeFragments() const
{
    return mGpu ? mGpu->ComputeFragments() : mCpu->ComputeFragments();
}

void FemProp::ReadPositions(std::vector<Vec3>& outPositions) const
{
    if (mGpu)
        mGpu->ReadPositions(outPositions);
    else
        outPositions = mCpu->GetPositions();
}

int FemProp::GetNodeCount() const
{
    return mGpu ? mGpu->GetNodeCount() : mCpu->GetNodeCount();
}

} // namespace crumple::gpu
