// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/LumpedNodeMass.h>
#include <crumple/fem/StableTimeStep.h>
#include <crumple/fem/TetElementRest.h>
#include <crumple/fem/TetSolver.h>
#include <crumple/gpu/GpuTetSolver.h>

#include "EmbeddedShaders.h"

#include <array>
#include <cmath>
#include <sstream>

namespace crumple::gpu
{

namespace
{

// The std430 layouts the shaders read.
using Float4 = std::array<float, 4>;
using Int4 = std::array<std::int32_t, 4>;

Float4 ToFloat4(const Vec3& inValue, double inW = 0.0)
{
    return {static_cast<float>(inValue.x()), static_cast<float>(inValue.y()), static_cast<float>(inValue.z()),
            static_cast<float>(inW)};
}

Vec3 ToVec3(const Float4& inValue)
{
    return Vec3(inValue[0], inValue[1], inValue[2]);
}

template <class T>
Result<StorageBuffer> MakeBuffer(const std::shared_ptr<ComputeDevice>& inDevice, const std::vector<T>& inData)
{
    return StorageBuffer::Create(inDevice, inData.size() * sizeof(T), inData.data());
}

} // namespace

Result<GpuTetSolver> GpuTetSolver::Create(std::shared_ptr<ComputeDevice> inDevice, const fem::TetMesh& inMesh,
                                          const fem::FemMaterialSettings& inMaterial,
                                          const fem::TetSolverSettings& inSettings)
{
    // The CPU solver's validation, then what the GPU path does not do yet.
    Result<fem::TetSolver> reference = fem::TetSolver::Create(inMesh, inMaterial, inSettings);
    if (reference.HasError())
        return reference.GetError();
    if (!inDevice)
        return MakeError(EError::InvalidArgument, "GpuTetSolver: no compute device");
    if (inSettings.mIntegrator != fem::EIntegrator::SymplecticEuler)
        return MakeError(EError::InvalidArgument,
                         "GpuTetSolver: implicit Euler is not implemented on the GPU; use "
                         "EIntegrator::SymplecticEuler (the CPU's stable sub-steps) or the CPU solver");
    const fem::FemMaterial& material = reference.Get().GetMaterial();
    if (material.IsPlastic() || material.IsBreakable())
        return MakeError(EError::InvalidArgument,
                         "GpuTetSolver: plasticity and fracture are not implemented on the GPU yet; use the CPU "
                         "solver for a plastic or breakable material");

    GpuTetSolver solver;
    solver.mDevice = inDevice;
    solver.mSettings = inSettings;
    solver.mMaterial = inMaterial;
    solver.mLambda = static_cast<float>(material.GetLambda());
    solver.mMu = static_cast<float>(material.GetShearModulus());
    solver.mMasses = reference.Get().GetMasses();
    solver.mInverseMasses = reference.Get().GetInverseMasses();
    solver.mElementCount = static_cast<std::uint32_t>(inMesh.GetTetCount());
    solver.mStableTimeStep = reference.Get().GetStableTimeStep();

    // Host-side arrays in the shaders' layouts.
    const std::size_t node_count = solver.mMasses.size();
    std::vector<Float4> positions(node_count), zeros(node_count, Float4{0.0f, 0.0f, 0.0f, 0.0f});
    for (std::size_t node = 0; node < node_count; ++node)
        positions[node] = ToFloat4(inMesh.GetRestPositions()[node], solver.mInverseMasses[node]);
    std::vector<Int4> elements;
    std::vector<Float4> rest, rotations(solver.mElementCount, Float4{0.0f, 0.0f, 0.0f, 1.0f});
    const std::vector<fem::TetElementRest>& rest_data = reference.Get().GetElementRest();
    for (std::uint32_t tet = 0; tet < solver.mElementCount; ++tet)
    {
        const fem::TetIndices& nodes = inMesh.GetTets()[tet];
        elements.push_back({nodes[0], nodes[1], nodes[2], nodes[3]});
        const Mat3& inverse = rest_data[tet].mRestEdgeInverse;
        rest.push_back(ToFloat4(inverse.col(0), rest_data[tet].mRestVolume));
        rest.push_back(ToFloat4(inverse.col(1)));
        rest.push_back(ToFloat4(inverse.col(2)));
    }

    // Adjacency: each node's (element, corner) entries in element order, so the gather sums in the CPU's
    // scatter order.
    std::vector<std::uint32_t> offsets(node_count + 1, 0), incident(4 * static_cast<std::size_t>(solver.mElementCount));
    for (const Int4& element : elements)
        for (std::int32_t node : element)
            ++offsets[node + 1];
    for (std::size_t node = 0; node < node_count; ++node)
        offsets[node + 1] += offsets[node];
    std::vector<std::uint32_t> cursor(offsets.begin(), offsets.end() - 1);
    for (std::uint32_t tet = 0; tet < solver.mElementCount; ++tet)
        for (std::uint32_t corner = 0; corner < 4; ++corner)
            incident[cursor[elements[tet][corner]]++] = 4 * tet + corner;

    // Programs and buffers.
    Result<ComputeProgram> element_pass = ComputeProgram::Create(inDevice, "TetElementForces", cShaderTetElementForces);
    if (element_pass.HasError())
        return element_pass.GetError();
    Result<ComputeProgram> node_pass = ComputeProgram::Create(inDevice, "TetNodeUpdate", cShaderTetNodeUpdate);
    if (node_pass.HasError())
        return node_pass.GetError();
    solver.mElementPass = std::move(element_pass.Get());
    solver.mNodePass = std::move(node_pass.Get());
    const std::uint32_t zero_status = 0;
    const std::vector<Float4> corners(4 * static_cast<std::size_t>(solver.mElementCount), Float4{});
    struct Upload
    {
        StorageBuffer* mBuffer;
        Result<StorageBuffer> mResult;
    } uploads[] = {{&solver.mPositions, MakeBuffer(inDevice, positions)},
                   {&solver.mVelocities, MakeBuffer(inDevice, zeros)},
                   {&solver.mExternal, MakeBuffer(inDevice, zeros)},
                   {&solver.mElements, MakeBuffer(inDevice, elements)},
                   {&solver.mRest, MakeBuffer(inDevice, rest)},
                   {&solver.mRotations, MakeBuffer(inDevice, rotations)},
                   {&solver.mCorners, MakeBuffer(inDevice, corners)},
                   {&solver.mOffsets, MakeBuffer(inDevice, offsets)},
                   {&solver.mIncident, MakeBuffer(inDevice, incident)},
                   {&solver.mStatus, StorageBuffer::Create(inDevice, sizeof(zero_status), &zero_status)},
                   {&solver.mSavedPositions, MakeBuffer(inDevice, positions)},
                   {&solver.mSavedVelocities, MakeBuffer(inDevice, zeros)},
                   {&solver.mSavedRotations, MakeBuffer(inDevice, rotations)}};
    for (Upload& upload : uploads)
    {
        if (upload.mResult.HasError())
            return upload.mResult.GetError();
        *upload.mBuffer = std::move(upload.mResult.Get());
    }
    return solver;
}

Result<GpuTetSolver> GpuTetSolver::CreateFrom(std::shared_ptr<ComputeDevice> inDevice, const fem::TetSolver& inSolver)
{
    if (inSolver.GetNodeCount() != inSolver.GetMesh().GetNodeCount())
        return MakeError(EError::InvalidArgument, "GpuTetSolver::CreateFrom: the prop has fractured; the GPU "
                                                  "solver starts from an intact mesh");
    Result<GpuTetSolver> created =
        Create(std::move(inDevice), inSolver.GetMesh(), inSolver.GetMaterial().GetSettings(), inSolver.GetSettings());
    if (created.HasError())
        return created;
    GpuTetSolver& solver = created.Get();

    // The CPU state, packed as the shaders read it.
    solver.mInverseMasses = inSolver.GetInverseMasses();
    std::vector<Float4> positions, velocities, forces, rotations;
    for (int node = 0; node < inSolver.GetNodeCount(); ++node)
    {
        positions.push_back(ToFloat4(inSolver.GetPositions()[node], solver.mInverseMasses[node]));
        velocities.push_back(ToFloat4(inSolver.GetVelocities()[node]));
        forces.push_back(ToFloat4(inSolver.GetExternalForces()[node]));
    }
    for (const Quat& rotation : inSolver.GetElementRotations())
        rotations.push_back({static_cast<float>(rotation.x()), static_cast<float>(rotation.y()),
                             static_cast<float>(rotation.z()), static_cast<float>(rotation.w())});
    solver.mPositions.Upload(0, positions.size() * sizeof(Float4), positions.data());
    solver.mVelocities.Upload(0, velocities.size() * sizeof(Float4), velocities.data());
    solver.mExternal.Upload(0, forces.size() * sizeof(Float4), forces.data());
    solver.mRotations.Upload(0, rotations.size() * sizeof(Float4), rotations.data());
    return created;
}

Status GpuTetSolver::CheckNode(int inNode, const char* inCaller) const
{
    if (inNode < 0 || inNode >= GetNodeCount())
        return MakeError(EError::OutOfRange, std::string("GpuTetSolver::") + inCaller + ": node " +
                                                 std::to_string(inNode) + " is outside [0, " +
                                                 std::to_string(GetNodeCount()) + ")");
    return mDevice->MakeCurrent();
}

Status GpuTetSolver::SetNodeFixed(int inNode, bool inFixed)
{
    if (Status status = CheckNode(inNode, "SetNodeFixed"); status.HasError())
        return status;
    mInverseMasses[inNode] = inFixed ? 0.0 : 1.0 / mMasses[inNode];
    Float4 position;
    mPositions.Download(inNode * sizeof(Float4), sizeof(Float4), &position);
    position[3] = static_cast<float>(mInverseMasses[inNode]);
    mPositions.Upload(inNode * sizeof(Float4), sizeof(Float4), &position);
    if (inFixed)
    {
        const Float4 zero{};
        mVelocities.Upload(inNode * sizeof(Float4), sizeof(Float4), &zero);
    }
    return Status::Ok();
}

Status GpuTetSolver::ApplyImpulse(int inNode, const Vec3& inImpulse)
{
    if (!IsFinite(inImpulse))
        return MakeError(EError::NonFinite, "GpuTetSolver::ApplyImpulse: impulse on node " + std::to_string(inNode) +
                                                " must be finite");
    if (Status status = CheckNode(inNode, "ApplyImpulse"); status.HasError())
        return status;
    Float4 velocity;
    mVelocities.Download(inNode * sizeof(Float4), sizeof(Float4), &velocity);
    const Vec3 updated = ToVec3(velocity) + mInverseMasses[inNode] * inImpulse;
    velocity = ToFloat4(updated);
    mVelocities.Upload(inNode * sizeof(Float4), sizeof(Float4), &velocity);
    return Status::Ok();
}

Status GpuTetSolver::SetExternalForce(int inNode, const Vec3& inForce)
{
    if (!IsFinite(inForce))
        return MakeError(EError::NonFinite, "GpuTetSolver::SetExternalForce: force on node " +
                                                std::to_string(inNode) + " must be finite");
    if (Status status = CheckNode(inNode, "SetExternalForce"); status.HasError())
        return status;
    const Float4 force = ToFloat4(inForce);
    mExternal.Upload(inNode * sizeof(Float4), sizeof(Float4), &force);
    return Status::Ok();
}

Status GpuTetSolver::SetGravity(const Vec3& inGravity)
{
    if (!IsFinite(inGravity))
        return MakeError(EError::NonFinite, "GpuTetSolver::SetGravity: gravity must be finite");
    mSettings.mGravity = inGravity;
    return Status::Ok();
}

Status GpuTetSolver::SetPositions(std::span<const Vec3> inPositions)
{
    if (inPositions.size() != mMasses.size())
        return MakeError(EError::InvalidArgument, "GpuTetSolver::SetPositions: " + std::to_string(inPositions.size()) +
                                                      " positions for " + std::to_string(mMasses.size()) + " nodes");
    for (const Vec3& position : inPositions)
        if (!IsFinite(position))
            return MakeError(EError::NonFinite, "GpuTetSolver::SetPositions: positions must be finite");
    if (Status status = mDevice->MakeCurrent(); status.HasError())
        return status;
    std::vector<Float4> packed(inPositions.size());
    for (std::size_t node = 0; node < packed.size(); ++node)
        packed[node] = ToFloat4(inPositions[node], mInverseMasses[node]);
    mPositions.Upload(0, packed.size() * sizeof(Float4), packed.data());
    return Status::Ok();
}

bool GpuTetSolver::Integrate(double inDeltaTime, int inSubSteps)
{
    const double dt = inDeltaTime / inSubSteps;
    mPositions.Bind(0);
    mVelocities.Bind(1);
    mElements.Bind(2);
    mRest.Bind(3);
    mRotations.Bind(4);
    mCorners.Bind(5);
    mExternal.Bind(6);
    mOffsets.Bind(7);
    mIncident.Bind(8);
    mStatus.Bind(9);
    const std::uint32_t zero = 0;
    mStatus.Upload(0, sizeof(zero), &zero);
    const std::uint32_t node_count = static_cast<std::uint32_t>(mMasses.size());
    const float damping_scale = static_cast<float>(1.0 / (1.0 + mMaterial.mMassDamping * dt));

    // Uniforms are per program and stay set: set them once, then alternate the two passes.
    mElementPass.Use();
    mElementPass.SetUInt("uElementCount", mElementCount);
    mElementPass.SetInt("uCorotated", mMaterial.mModel == fem::EElasticModel::CorotatedLinear ? 1 : 0);
    mElementPass.SetFloat("uLambda", mLambda);
    mElementPass.SetFloat("uMu", mMu);
    mElementPass.SetFloat("uBeta", static_cast<float>(mMaterial.mStiffnessDamping));
    mNodePass.Use();
    mNodePass.SetUInt("uNodeCount", node_count);
    mNodePass.SetFloat("uDeltaTime", static_cast<float>(dt));
    mNodePass.SetFloat("uDampingScale", damping_scale);
    mNodePass.SetVec3("uGravity", mSettings.mGravity);
    for (int sub_step = 0; sub_step < inSubSteps; ++sub_step)
    {
        mElementPass.Use();
        mElementPass.Dispatch(mElementCount);
        mNodePass.Use();
        mNodePass.Dispatch(node_count);
    }
    mElementWork += static_cast<std::uint64_t>(inSubSteps) * mElementCount;

    // The one readback of a step: the divergence flag.
    std::uint32_t status = 0;
    mStatus.Download(0, sizeof(status), &status);
    return status == 0;
}

Result<fem::TetStepResult> GpuTetSolver::Step(double inDeltaTime)
{
    if (!std::isfinite(inDeltaTime) || !(inDeltaTime > 0.0))
    {
        std::ostringstream message;
        message << "GpuTetSolver::Step: time step " << inDeltaTime << " s must be finite and > 0";
        return MakeError(std::isfinite(inDeltaTime) ? EError::InvalidArgument : EError::NonFinite, message.str());
    }
    const double count = std::ceil(inDeltaTime / mStableTimeStep);
    if (!(count <= static_cast<double>(mSettings.mMaxSubSteps)))
    {
        std::ostringstream message;
        message << "GpuTetSolver::Step: " << inDeltaTime << " s needs " << count << " sub-steps of at most "
                << mStableTimeStep << " s, more than TetSolverSettings.mMaxSubSteps = " << mSettings.mMaxSubSteps;
        return MakeError(EError::InvalidArgument, message.str());
    }
    if (Status status = mDevice->MakeCurrent(); status.HasError())
        return status.GetError();
    const int sub_steps = std::max(1, static_cast<int>(count));

    // Keep the start of the step on the GPU (copies, no readback) to restore on divergence.
    mSavedPositions.CopyFrom(mPositions);
    mSavedVelocities.CopyFrom(mVelocities);
    mSavedRotations.CopyFrom(mRotations);
    fem::TetStepResult result;
    bool finite = false;
    for (int split = 0; split <= mSettings.mMaxStepSplits && !finite; ++split)
    {
        const long long pieces = static_cast<long long>(sub_steps) << split;
        if (pieces > mSettings.mMaxSubSteps)
            break;
        if (split > 0)
        {
            result.mEvents = result.mEvents | fem::ETetStepEvent::Split;
            mPositions.CopyFrom(mSavedPositions);
            mVelocities.CopyFrom(mSavedVelocities);
            mRotations.CopyFrom(mSavedRotations);
        }
        result.mSubSteps = static_cast<int>(pieces);
        finite = Integrate(inDeltaTime, result.mSubSteps);
    }
    if (!finite)
    {
        mPositions.CopyFrom(mSavedPositions);
        mVelocities.CopyFrom(mSavedVelocities);
        mRotations.CopyFrom(mSavedRotations);
        result.mEvents = result.mEvents | fem::ETetStepEvent::Diverged;
    }
    return result;
}

void GpuTetSolver::ReadPositions(std::vector<Vec3>& outPositions) const
{
    std::vector<Float4> packed(mMasses.size());
    if (mDevice->MakeCurrent().IsValid())
        mPositions.Download(0, packed.size() * sizeof(Float4), packed.data());
    outPositions.resize(packed.size());
    for (std::size_t node = 0; node < packed.size(); ++node)
        outPositions[node] = ToVec3(packed[node]);
}

void GpuTetSolver::ReadVelocities(std::vector<Vec3>& outVelocities) const
{
    std::vector<Float4> packed(mMasses.size());
    if (mDevice->MakeCurrent().IsValid())
        mVelocities.Download(0, packed.size() * sizeof(Float4), packed.data());
    outVelocities.resize(packed.size());
    for (std::size_t node = 0; node < packed.size(); ++node)
        outVelocities[node] = ToVec3(packed[node]);
}

} // namespace crumple::gpu
