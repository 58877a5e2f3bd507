// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/base/Assert.h>
#include <crumple/base/TimeStep.h>
#include <crumple/fem/FractureTopology.h>
#include <crumple/fem/LumpedNodeMass.h>
#include <crumple/fem/OpenCracks.h>
#include <crumple/fem/TetSolver.h>
#include <crumple/gpu/GpuTetSolver.h>

#include "EmbeddedShaders.h"
#include "GpuImplicitStep.h"

#include <Eigen/SVD>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
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
    // A buffer never has size 0 (an unbreakable prop's link arrays are empty): keep one dummy element.
    if (inData.empty())
        return StorageBuffer::Create(inDevice, sizeof(T));
    return StorageBuffer::Create(inDevice, inData.size() * sizeof(T), inData.data());
}

// Fills *ioBuffer from a Result, or returns its error.
Status Assign(StorageBuffer& ioBuffer, Result<StorageBuffer> inResult)
{
    if (inResult.HasError())
        return inResult.GetError();
    ioBuffer = std::move(inResult.Get());
    return Status::Ok();
}

// Each node's (element, corner) entries in element order, so the gather sums in the CPU's scatter order.
void Adjacency(const std::vector<fem::TetIndices>& inElements, std::size_t inNodeCount, std::vector<std::uint32_t>& outOffsets,
               std::vector<std::uint32_t>& outIncident)
{
    outOffsets.assign(inNodeCount + 1, 0);
    for (const fem::TetIndices& element : inElements)
        for (int node : element)
            ++outOffsets[node + 1];
    for (std::size_t node = 0; node < inNodeCount; ++node)
        outOffsets[node + 1] += outOffsets[node];
    outIncident.resize(4 * inElements.size());
    std::vector<std::uint32_t> cursor(outOffsets.begin(), outOffsets.end() - 1);
    for (std::size_t tet = 0; tet < inElements.size(); ++tet)
        for (std::uint32_t corner = 0; corner < 4; ++corner)
            outIncident[cursor[inElements[tet][corner]]++] = static_cast<std::uint32_t>(4 * tet + corner);
}

// The shader programs, compiled from the embedded sources.
Status Compile(const std::shared_ptr<ComputeDevice>& inDevice, ComputeProgram& outProgram, const char* inName,
               std::string_view inSource)
{
    Result<ComputeProgram> program = ComputeProgram::Create(inDevice, inName, inSource);
    if (program.HasError())
        return program.GetError();
    outProgram = std::move(program.Get());
    return Status::Ok();
}

// Finite once stored as a float (the shaders' type): a double beyond FLT_MAX would become infinite there.
bool IsFiniteAsFloat(const Vec3& inValue)
{
    return IsFinite(inValue) && inValue.cwiseAbs().maxCoeff() <= static_cast<double>(std::numeric_limits<float>::max());
}

} // namespace

Result<GpuTetSolver> GpuTetSolver::Create(std::shared_ptr<ComputeDevice> inDevice, const fem::TetMesh& inMesh,
                                          const fem::FemMaterialSettings& inMaterial,
                                          const fem::TetSolverSettings& inSettings)
{
    // The CPU solver's validation (and its initial state: masses, rest data, stable step, the connectivity of
    // a breakable mesh), then what the GPU path does not do.
    Result<fem::TetSolver> reference = fem::TetSolver::Create(inMesh, inMaterial, inSettings);
    if (reference.HasError())
        return reference.GetError();
    return CreateFromReference(std::move(inDevice), inMesh, inMaterial, inSettings, reference.Get());
}

Result<GpuTetSolver> GpuTetSolver::CreateFromReference(std::shared_ptr<ComputeDevice> inDevice,
                                                       const fem::TetMesh& inMesh,
                                                       const fem::FemMaterialSettings& inMaterial,
                                                       const fem::TetSolverSettings& inSettings,
                                                       const fem::TetSolver& inReference)
{
    if (!inDevice)
        return MakeError(EError::InvalidArgument, "GpuTetSolver: no compute device");
    if (inSettings.mGround.mEnabled)
        return MakeError(EError::InvalidArgument,
                         "GpuTetSolver: a ground (TetSolverSettings::mGround) is CPU-only");
    const fem::TetSolver& cpu = inReference;
    const fem::FemMaterial& material = cpu.GetMaterial();

    GpuTetSolver solver(inMesh);
    solver.mDevice = inDevice;
    solver.mRest = cpu.GetElementRest();
    solver.mSettings = inSettings;
    solver.mMaterial = inMaterial;
    solver.mLambda = static_cast<float>(material.GetLambda());
    solver.mMu = static_cast<float>(material.GetShearModulus());
    solver.mMaterialMatrix = material.GetMaterialMatrix();
    solver.mMasses = cpu.GetMasses();
    solver.mInverseMasses = cpu.GetInverseMasses();
    solver.mElementCount = static_cast<std::uint32_t>(inMesh.GetTetCount());
    solver.mStableTimeStep = cpu.GetStableTimeStep();
    solver.mMadeRestPositions = cpu.GetNodeRestPositions();
    solver.mBreakable = material.IsBreakable();
    solver.mPlastic = material.IsPlastic();
    if (solver.mBreakable)
    {
        solver.mLinks = cpu.GetFractureLinks();
        solver.mBroken = cpu.GetBrokenLinks();
        solver.mCrackSafeEnergy = cpu.GetCrackSafeEnergy();
    }

    // Programs.
    const struct
    {
        ComputeProgram* mProgram;
        const char* mName;
        std::string_view mSource;
    } programs[] = {{&solver.mElementPass, "TetElementForces", cShaderTetElementForces},
                    {&solver.mNodePass, "TetNodeUpdate", cShaderTetNodeUpdate},
                    {&solver.mStressPass, "TetElementStress", cShaderTetElementStress},
                    {&solver.mGroupPass, "TetGroupStress", cShaderTetGroupStress},
                    {&solver.mCrackPass, "TetOpenCracks", cShaderTetOpenCracks},
                    {&solver.mEnergyPass, "TetKineticEnergy", cShaderTetKineticEnergy}};
    for (const auto& program : programs)
        if (Status status = Compile(inDevice, *program.mProgram, program.mName, program.mSource); status.HasError())
            return status.GetError();
    if (solver.mPlastic)
        if (Status status = Compile(inDevice, solver.mPlasticPass, "TetPlasticFlow", cShaderTetPlasticFlow);
            status.HasError())
            return status.GetError();
    if (inSettings.mIntegrator == fem::EIntegrator::ImplicitEuler)
    {
        // intent: an explicit prop compiles and allocates nothing of the implicit step
        Result<GpuImplicitStep> implicit =
            GpuImplicitStep::Create(inDevice, inMaterial.mModel == fem::EElasticModel::StVenantKirchhoff);
        if (implicit.HasError())
            return implicit.GetError();
        solver.mImplicit = std::make_unique<GpuImplicitStep>(std::move(implicit.Get()));
    }

    // Per-element data that never changes.
    std::vector<Float4> rest, rotations(solver.mElementCount, Float4{0.0f, 0.0f, 0.0f, 1.0f});
    for (const fem::TetElementRest& element : solver.mRest)
    {
        rest.push_back(ToFloat4(element.mRestEdgeInverse.col(0), element.mRestVolume));
        rest.push_back(ToFloat4(element.mRestEdgeInverse.col(1)));
        rest.push_back(ToFloat4(element.mRestEdgeInverse.col(2)));
    }
    // divergence flag, links opened, kinetic energy bits, elements that flowed plastically
    const std::uint32_t status_words[4] = {0, 0, 0, 0};
    if (Status status = Assign(solver.mRestBuffer, MakeBuffer(inDevice, rest)); status.HasError())
        return status.GetError();
    if (Status status = Assign(solver.mRotations, MakeBuffer(inDevice, rotations)); status.HasError())
        return status.GetError();
    if (Status status = Assign(solver.mSavedRotations, MakeBuffer(inDevice, rotations)); status.HasError())
        return status.GetError();
    if (Status status = Assign(solver.mCorners, StorageBuffer::Create(inDevice, 4 * sizeof(Float4) * solver.mElementCount));
        status.HasError())
        return status.GetError();
    if (Status status = Assign(solver.mStatus, StorageBuffer::Create(inDevice, sizeof(status_words), status_words));
        status.HasError())
        return status.GetError();
    // Plastic strains, 3 columns per element, zero as made (one dummy element when the material has none).
    const std::size_t plastic_bytes =
        (solver.mPlastic ? 3 * static_cast<std::size_t>(solver.mElementCount) : 1) * sizeof(Float4);
    if (Status status = Assign(solver.mPlasticStrains, StorageBuffer::Create(inDevice, plastic_bytes));
        status.HasError())
        return status.GetError();
    if (Status status = Assign(solver.mSavedPlasticStrains, StorageBuffer::Create(inDevice, plastic_bytes));
        status.HasError())
        return status.GetError();

    // Fracture data: stresses, group membership, links, broken flags (dummies when unbreakable).
    std::vector<std::uint32_t> group_offsets(solver.mLinks.mGroupElementOffsets.begin(), solver.mLinks.mGroupElementOffsets.end());
    std::vector<std::uint32_t> group_elements(solver.mLinks.mGroupElements.begin(), solver.mLinks.mGroupElements.end());
    std::vector<Int4> links, faces;
    std::vector<Float4> normals;
    for (int link = 0; link < solver.mLinks.GetLinkCount(); ++link)
    {
        links.push_back({solver.mLinks.mLinkGroups[link][0], solver.mLinks.mLinkGroups[link][1],
                         solver.mLinks.mLinkFaceOffsets[link], solver.mLinks.mLinkFaceOffsets[link + 1]});
        normals.push_back(ToFloat4(solver.mLinks.mLinkRestNormals[link]));
    }
    for (const fem::FractureLinkFace& face : solver.mLinks.mLinkFaces)
        faces.push_back({face.mElement, face.mCorners[0], face.mCorners[1], face.mCorners[2]});
    const std::vector<std::uint32_t> broken(solver.mBroken.begin(), solver.mBroken.end());
    const std::size_t stress_count = solver.mBreakable ? 2 * static_cast<std::size_t>(solver.mElementCount) : 1;
    const std::size_t principal_count = std::max<std::size_t>(1, solver.mLinks.GetGroupCount());
    struct
    {
        StorageBuffer* mBuffer;
        Result<StorageBuffer> mResult;
    } fracture[] = {{&solver.mStress, StorageBuffer::Create(inDevice, stress_count * sizeof(Float4))},
                    {&solver.mGroupOffsets, MakeBuffer(inDevice, group_offsets)},
                    {&solver.mGroupElements, MakeBuffer(inDevice, group_elements)},
                    {&solver.mPrincipal, StorageBuffer::Create(inDevice, principal_count * sizeof(Float4))},
                    {&solver.mLinkBuffer, MakeBuffer(inDevice, links)},
                    {&solver.mLinkFaces, MakeBuffer(inDevice, faces)},
                    {&solver.mLinkNormals, MakeBuffer(inDevice, normals)},
                    {&solver.mBrokenBuffer, MakeBuffer(inDevice, broken)}};
    for (auto& buffer : fracture)
        if (Status status = Assign(*buffer.mBuffer, std::move(buffer.mResult)); status.HasError())
            return status.GetError();

    // Node state and connectivity (the CPU solver's: a breakable mesh may start with split edge joints).
    std::vector<Float4> positions, zeros(cpu.GetPositions().size(), Float4{});
    for (std::size_t node = 0; node < cpu.GetPositions().size(); ++node)
        positions.push_back(ToFloat4(cpu.GetPositions()[node], solver.mInverseMasses[node]));
    if (Status status = solver.UploadTopology(cpu.GetElementNodes(), positions, zeros, zeros); status.HasError())
        return status.GetError();
    return solver;
}

GpuTetSolver::GpuTetSolver(const fem::TetMesh& inMesh) : mMesh(inMesh) {}
GpuTetSolver::~GpuTetSolver() = default;
GpuTetSolver::GpuTetSolver(GpuTetSolver&& ioOther) noexcept = default;
GpuTetSolver& GpuTetSolver::operator=(GpuTetSolver&& ioOther) noexcept = default;

Status GpuTetSolver::UploadTopology(const std::vector<fem::TetIndices>& inElementNodes, const std::vector<Float4>& inPositions,
                                    const std::vector<Float4>& inVelocities, const std::vector<Float4>& inForces)
{
    std::vector<Int4> elements;
    for (const fem::TetIndices& nodes : inElementNodes)
        elements.push_back({nodes[0], nodes[1], nodes[2], nodes[3]});
    std::vector<std::uint32_t> offsets, incident;
    Adjacency(inElementNodes, inPositions.size(), offsets, incident);
    struct
    {
        StorageBuffer* mBuffer;
        Result<StorageBuffer> mResult;
    } uploads[] = {{&mElements, MakeBuffer(mDevice, elements)},
                   {&mOffsets, MakeBuffer(mDevice, offsets)},
                   {&mIncident, MakeBuffer(mDevice, incident)},
                   {&mPositions, MakeBuffer(mDevice, inPositions)},
                   {&mVelocities, MakeBuffer(mDevice, inVelocities)},
                   {&mExternal, MakeBuffer(mDevice, inForces)}};
    for (const auto& upload : uploads)
        if (upload.mResult.HasError())
            return upload.mResult.GetError(); // nothing replaced yet
    for (auto& upload : uploads)
        *upload.mBuffer = std::move(upload.mResult.Get());
    mElementNodes = inElementNodes;
    return Status::Ok();
}

Result<GpuTetSolver> GpuTetSolver::CreateFrom(std::shared_ptr<ComputeDevice> inDevice, const fem::TetSolver& inSolver)
{
    // inSolver is already a validated CPU solver of this mesh, material and settings: no second one is built.
    Result<GpuTetSolver> created = CreateFromReference(std::move(inDevice), inSolver.GetMesh(),
                                                       inSolver.GetMaterial().GetSettings(), inSolver.GetSettings(),
                                                       inSolver);
    if (created.HasError())
        return created;
    GpuTetSolver& solver = created.Get();

    // The CPU state, cracks included, packed as the shaders read it.
    solver.mMasses = inSolver.GetMasses();
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
    if (Status status = solver.UploadTopology(inSolver.GetElementNodes(), positions, velocities, forces); status.HasError())
        return status.GetError();
    solver.mRotations.Upload(0, rotations.size() * sizeof(Float4), rotations.data());
    solver.mElementWork = inSolver.GetElementWorkCount(); // a stepped prop stays one (recordings refuse it)
    if (solver.mPlastic)
    {
        // The CPU's plastic set, as the shaders read it (columns).
        std::vector<Float4> plastic;
        for (const Mat3& strain : inSolver.GetPlasticStrains())
        {
            for (int column = 0; column < 3; ++column)
                plastic.push_back(ToFloat4(strain.col(column)));
            solver.mPlasticSet = solver.mPlasticSet || !strain.isZero(0.0);
        }
        solver.mPlasticStrains.Upload(0, plastic.size() * sizeof(Float4), plastic.data());
    }
    if (solver.mBreakable)
    {
        solver.mBroken = inSolver.GetBrokenLinks();
        const std::vector<std::uint32_t> broken(solver.mBroken.begin(), solver.mBroken.end());
        if (!broken.empty())
            solver.mBrokenBuffer.Upload(0, broken.size() * sizeof(std::uint32_t), broken.data());
    }
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
    return FixNodes(std::span<const int>(&inNode, 1), inFixed, "SetNodeFixed");
}

Status GpuTetSolver::SetNodesFixed(std::span<const int> inNodes, bool inFixed)
{
    return FixNodes(inNodes, inFixed, "SetNodesFixed");
}

Status GpuTetSolver::FixNodes(std::span<const int> inNodes, bool inFixed, const char* inCaller)
{
    // intent: every node checked (and the device made current) before anything changes
    for (int node : inNodes)
        if (Status status = CheckNode(node, inCaller); status.HasError())
            return status;
    if (inNodes.empty())
        return Status::Ok();
    InputChanged();
    // intent: one read and one write of each node buffer over the range the nodes span (per node, each would
    // be a device sync); the positions' fourth lane holds the inverse mass, the range's other nodes go back as read
    const auto [low, high] = std::minmax_element(inNodes.begin(), inNodes.end());
    const auto first = static_cast<std::size_t>(*low);
    const std::size_t count = static_cast<std::size_t>(*high) - first + 1;
    std::vector<Float4> positions(count);
    mPositions.Download(first * sizeof(Float4), count * sizeof(Float4), positions.data());
    for (int node : inNodes)
    {
        const auto n = static_cast<std::size_t>(node);
        mInverseMasses[n] = inFixed ? 0.0 : 1.0 / mMasses[n];
        positions[n - first][3] = static_cast<float>(mInverseMasses[n]);
    }
    mPositions.Upload(first * sizeof(Float4), count * sizeof(Float4), positions.data());
    if (inFixed)
    {
        std::vector<Float4> velocities(count);
        mVelocities.Download(first * sizeof(Float4), count * sizeof(Float4), velocities.data());
        for (int node : inNodes)
            velocities[static_cast<std::size_t>(node) - first] = Float4{};
        mVelocities.Upload(first * sizeof(Float4), count * sizeof(Float4), velocities.data());
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
    const Vec3 changed = ToVec3(velocity) + mInverseMasses[inNode] * inImpulse;
    if (!IsFiniteAsFloat(changed))
        return MakeError(EError::NonFinite, "GpuTetSolver::ApplyImpulse: the impulse on node " + std::to_string(inNode) +
                                                " would leave it moving faster than a float holds");
    InputChanged();
    velocity = ToFloat4(changed);
    mVelocities.Upload(inNode * sizeof(Float4), sizeof(Float4), &velocity);
    return Status::Ok();
}

Status GpuTetSolver::SetExternalForce(int inNode, const Vec3& inForce)
{
    if (!IsFiniteAsFloat(inForce))
        return MakeError(EError::NonFinite, "GpuTetSolver::SetExternalForce: force on node " +
                                                std::to_string(inNode) + " must be finite (as a float)");
    if (Status status = CheckNode(inNode, "SetExternalForce"); status.HasError())
        return status;
    InputChanged();
    const Float4 force = ToFloat4(inForce);
    mExternal.Upload(inNode * sizeof(Float4), sizeof(Float4), &force);
    return Status::Ok();
}

Status GpuTetSolver::SetGravity(const Vec3& inGravity)
{
    if (!IsFiniteAsFloat(inGravity))
        return MakeError(EError::NonFinite, "GpuTetSolver::SetGravity: gravity must be finite (as a float)");
    mSettings.mGravity = inGravity;
    InputChanged();
    return Status::Ok();
}

Status GpuTetSolver::SetPositions(std::span<const Vec3> inPositions)
{
    if (inPositions.size() != mMasses.size())
        return MakeError(EError::InvalidArgument, "GpuTetSolver::SetPositions: " + std::to_string(inPositions.size()) +
                                                      " positions for " + std::to_string(mMasses.size()) + " nodes");
    for (const Vec3& position : inPositions)
        if (!IsFiniteAsFloat(position))
            return MakeError(EError::NonFinite, "GpuTetSolver::SetPositions: positions must be finite (as floats)");
    if (Status status = mDevice->MakeCurrent(); status.HasError())
        return status;
    std::vector<Float4> packed(inPositions.size());
    for (std::size_t node = 0; node < packed.size(); ++node)
        packed[node] = ToFloat4(inPositions[node], mInverseMasses[node]);
    mPositions.Upload(0, packed.size() * sizeof(Float4), packed.data());
    InputChanged();
    return Status::Ok();
}

void GpuTetSolver::InputChanged()
{
    mStepper.Wake();
}

void GpuTetSolver::WakeUp()
{
    InputChanged();
}

void GpuTetSolver::BindAll() const
{
    mPositions.Bind(0);
    mVelocities.Bind(1);
    mElements.Bind(2);
    mRestBuffer.Bind(3);
    mRotations.Bind(4);
    mCorners.Bind(5);
    mExternal.Bind(6);
    mOffsets.Bind(7);
    mIncident.Bind(8);
    mStatus.Bind(9);
    mStress.Bind(10);
    mGroupOffsets.Bind(11);
    mGroupElements.Bind(12);
    mPrincipal.Bind(13);
    mLinkBuffer.Bind(14);
    mLinkFaces.Bind(15);
    mLinkNormals.Bind(16);
    mBrokenBuffer.Bind(17);
    mPlasticStrains.Bind(31); // the implicit step's own buffers take 18-30
}

void GpuTetSolver::SetFractureUniforms() const
{
    // Uniforms belong to their program and stay set: once per Integrate, not per sub-step.
    mStressPass.Use();
    mStressPass.SetUInt("uElementCount", mElementCount);
    mStressPass.SetInt("uCorotated", mMaterial.mModel == fem::EElasticModel::CorotatedLinear ? 1 : 0);
    mStressPass.SetFloat("uLambda", mLambda);
    mStressPass.SetFloat("uMu", mMu);
    mStressPass.SetInt("uPlastic", mPlastic ? 1 : 0);
    mGroupPass.Use();
    mGroupPass.SetUInt("uGroupCount", static_cast<std::uint32_t>(mLinks.GetGroupCount()));
    mCrackPass.Use();
    mCrackPass.SetUInt("uLinkCount", static_cast<std::uint32_t>(mLinks.GetLinkCount()));
    mCrackPass.SetFloat("uStrength", static_cast<float>(mMaterial.mTensileStrength));
    mCrackPass.SetInt("uDetachGroup", mMaterial.mFractureMode == fem::EFractureMode::DetachGroup ? 1 : 0);
    mCrackPass.SetFloat("uCrackCosine", static_cast<float>(fem::cCrackFaceCosine));
}

int GpuTetSolver::Fracture()
{
    // Stress, group principal stress, links: the CPU's Fracture() in three passes (uniforms set by
    // SetFractureUniforms).
    mStressPass.Use();
    mStressPass.Dispatch(mElementCount);
    mGroupPass.Use();
    mGroupPass.Dispatch(static_cast<std::uint32_t>(mLinks.GetGroupCount()));
    mCrackPass.Use();
    mCrackPass.Dispatch(static_cast<std::uint32_t>(mLinks.GetLinkCount()));

    // The opened-link count (a sync point: see the class comment).
    std::uint32_t words[2] = {0, 0};
    mStatus.Download(0, sizeof(words), words);
    if (words[1] == 0)
        return 0;
    const std::uint32_t clear = 0;
    mStatus.Upload(sizeof(std::uint32_t), sizeof(clear), &clear);
    Reconnect();
    BindAll(); // the node buffers were replaced
    return static_cast<int>(words[1]);
}

// As fem::TetSolver::Reconnect: every new node copies the old node at the same element corner; masses are
// lumped anew; an external force is shared among the copies by mass; anchoring is inherited.
void GpuTetSolver::Reconnect()
{
    std::vector<std::uint32_t> broken(mBroken.size());
    mBrokenBuffer.Download(0, broken.size() * sizeof(std::uint32_t), broken.data());
    for (std::size_t link = 0; link < broken.size(); ++link)
        mBroken[link] = broken[link] != 0 ? 1 : 0;
    const Result<fem::FractureConnectivity> cracked = fem::FractureTopology(mMesh, mLinks, mBroken);
    CRUMPLE_ASSERT(cracked.IsValid(), "the solver's own links were refused");
    if (!cracked.IsValid())
        return; // cannot happen: the links are the mesh's own, the flags one per link
    const fem::FractureConnectivity& connectivity = cracked.Get();

    const std::size_t old_count = mMasses.size(), new_count = connectivity.mNodeOrigin.size();
    std::vector<Float4> positions(old_count), velocities(old_count), forces(old_count);
    mPositions.Download(0, old_count * sizeof(Float4), positions.data());
    mVelocities.Download(0, old_count * sizeof(Float4), velocities.data());
    mExternal.Download(0, old_count * sizeof(Float4), forces.data());
    std::vector<int> old_of_new(new_count, -1);
    for (std::size_t tet = 0; tet < mElementNodes.size(); ++tet)
        for (int corner = 0; corner < 4; ++corner)
            old_of_new[connectivity.mElementNodes[tet][corner]] = mElementNodes[tet][corner];
    Result<std::vector<double>> lumped =
        fem::LumpedNodeMass(connectivity.mElementNodes, mRest, static_cast<int>(new_count), mMaterial.mDensity);
    CRUMPLE_ASSERT(lumped.IsValid(), "FractureTopology's connectivity was refused");
    if (!lumped.IsValid())
        return; // cannot happen: FractureTopology numbers every node below its count
    const std::vector<double> masses = std::move(lumped).Get();
    std::vector<double> inverse_masses(new_count);
    std::vector<Float4> new_positions(new_count), new_velocities(new_count), new_forces(new_count);
    for (std::size_t node = 0; node < new_count; ++node)
    {
        const int old = old_of_new[node];
        inverse_masses[node] = mInverseMasses[old] == 0.0 ? 0.0 : 1.0 / masses[node];
        new_positions[node] = positions[old];
        new_positions[node][3] = static_cast<float>(inverse_masses[node]);
        new_velocities[node] = velocities[old];
        new_forces[node] = ToFloat4(ToVec3(forces[old]) * (masses[node] / mMasses[old]));
    }
    if (UploadTopology(connectivity.mElementNodes, new_positions, new_velocities, new_forces).IsValid())
    {
        mMasses = masses;
        mInverseMasses = inverse_masses;
    }
}

void GpuTetSolver::RefreshCoarseSpace(double inDeltaTime)
{
    if (mSettings.mPreconditioner == fem::EImplicitPreconditioner::BlockJacobi)
        return;
    std::vector<std::uint8_t> free_nodes(mInverseMasses.size());
    for (std::size_t node = 0; node < free_nodes.size(); ++node)
        free_nodes[node] = mInverseMasses[node] > 0.0 ? 1 : 0;
    // intent: turned with its aggregates once a solve since the last build or turn took more iterations than
    // mFactorRefreshIterations (the default 0: after any solve, i.e. before every step but the first)
    const bool turn = mLongestSolve > mSettings.mFactorRefreshIterations;
    if (inDeltaTime == mCoarseTimeStep && mElementNodes == mCoarseElementNodes && free_nodes == mCoarseFree)
    {
        if (turn)
            TurnCoarseSpace();
        return;
    }
    // intent: each current node's rest position through an element corner (cracks copy nodes, not rest
    // shapes)
    std::vector<Vec3> rest(mInverseMasses.size(), Vec3::Zero());
    for (std::size_t tet = 0; tet < mElementNodes.size(); ++tet)
        for (std::size_t corner = 0; corner < 4; ++corner)
            rest[static_cast<std::size_t>(mElementNodes[tet][corner])] =
                mMesh.GetRestPositions()[static_cast<std::size_t>(mMesh.GetTets()[tet][corner])];
    const double mass_scale = 1.0 + inDeltaTime * mMaterial.mMassDamping;
    const double stiffness_scale = inDeltaTime * inDeltaTime + inDeltaTime * mMaterial.mStiffnessDamping;
    Result<fem::TetCoarseSpace> space = fem::BuildTetCoarseSpace(
        mElementNodes, mRest, rest, mMasses, mInverseMasses, mMaterialMatrix, mass_scale, stiffness_scale);
    // intent: without a space (everything anchored, a degenerate system, too few aggregates, no memory on the
    // device) the solves precondition by block Jacobi alone
    const bool made = space.IsValid() && mImplicit->SetCoarseSpace(&space.Get()).IsValid();
    if (!made)
        (void)mImplicit->SetCoarseSpace(nullptr);
    mCoarseSpace = made ? std::move(space).Get() : fem::TetCoarseSpace{};
    mCoarseElementNodes = mElementNodes;
    mCoarseFree = std::move(free_nodes);
    mCoarseTimeStep = inDeltaTime;
    ++mCoarseBuilds;
    if (made && turn)
        TurnCoarseSpace(); // a prop bent before its cracks is turned at once
    mLongestSolve = 0;
}

void GpuTetSolver::TurnCoarseSpace()
{
    // intent: each aggregate's best rotation from its rest offsets to its nodes now (Kabsch: the polar factor
    // of sum (x - c) d^T)
    const int aggregates = mCoarseSpace.GetAggregateCount();
    if (aggregates <= 0)
        return;
    std::vector<Vec3> positions;
    ReadPositions(positions);
    if (positions.size() != mCoarseSpace.mNodeAggregate.size())
        return;
    std::vector<Mat3> turns(static_cast<std::size_t>(aggregates), Mat3::Identity());
    for (int aggregate = 0; aggregate < aggregates; ++aggregate)
    {
        const int begin = mCoarseSpace.mAggregateStart[static_cast<std::size_t>(aggregate)];
        const int end = mCoarseSpace.mAggregateStart[static_cast<std::size_t>(aggregate) + 1];
        Vec3 centre = Vec3::Zero();
        for (int entry = begin; entry < end; ++entry)
            centre += positions[static_cast<std::size_t>(
                mCoarseSpace.mAggregateNodes[static_cast<std::size_t>(entry)])];
        centre /= static_cast<double>(end - begin);
        Mat3 covariance = Mat3::Zero();
        for (int entry = begin; entry < end; ++entry)
        {
            const auto node =
                static_cast<std::size_t>(mCoarseSpace.mAggregateNodes[static_cast<std::size_t>(entry)]);
            covariance += (positions[node] - centre) * mCoarseSpace.mNodeOffset[node].transpose();
        }
        if (!covariance.allFinite() || covariance.isZero())
            continue;
        const Eigen::JacobiSVD<Mat3> svd(covariance, Eigen::ComputeFullU | Eigen::ComputeFullV);
        Mat3 reflect = Mat3::Identity();
        reflect(2, 2) = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0.0 ? -1.0 : 1.0;
        turns[static_cast<std::size_t>(aggregate)] = svd.matrixU() * reflect * svd.matrixV().transpose();
    }
    mImplicit->TurnCoarseSpace(turns);
    mLongestSolve = 0;
    ++mCoarseTurns;
}

void GpuTetSolver::SetElementPassUniforms(double inStiffnessDamping) const
{
    mElementPass.Use();
    mElementPass.SetUInt("uElementCount", mElementCount);
    mElementPass.SetInt("uCorotated", mMaterial.mModel == fem::EElasticModel::CorotatedLinear ? 1 : 0);
    mElementPass.SetFloat("uLambda", mLambda);
    mElementPass.SetFloat("uMu", mMu);
    mElementPass.SetFloat("uBeta", static_cast<float>(inStiffnessDamping));
    mElementPass.SetInt("uPlastic", mPlastic ? 1 : 0);
}

void GpuTetSolver::SetPlasticUniforms(double inDeltaTime) const
{
    mPlasticPass.Use();
    mPlasticPass.SetUInt("uElementCount", mElementCount);
    mPlasticPass.SetInt("uCorotated", mMaterial.mModel == fem::EElasticModel::CorotatedLinear ? 1 : 0);
    mPlasticPass.SetFloat("uMu", mMu);
    mPlasticPass.SetFloat("uYieldStress", static_cast<float>(mMaterial.mYieldStress));
    mPlasticPass.SetFloat("uCreepFraction",
                          static_cast<float>(std::min(1.0, mMaterial.mCreepRate * inDeltaTime)));
    mPlasticPass.SetFloat("uMaxPlasticStrain", static_cast<float>(mMaterial.mMaxPlasticStrain));
}

void GpuTetSolver::AfterSubStep(int& ioBrokenLinks)
{
    // intent: plastic flow, then fracture, on the state at the end of the (sub-)step, as the CPU's
    // AfterSubStep
    if (mPlastic)
    {
        mPlasticPass.Use();
        mPlasticPass.Dispatch(mElementCount);
        mElementWork += mElementCount;
    }
    if (!mBreakable)
        return;
    const int opened = Fracture();
    ioBrokenLinks += opened;
    if (opened > 0)
    {
        // Fracture added nodes (and used other programs): the node pass needs the new count.
        mNodePass.Use();
        mNodePass.SetUInt("uNodeCount", static_cast<std::uint32_t>(mMasses.size()));
    }
}

bool GpuTetSolver::Integrate(double inDeltaTime, int inSubSteps, fem::TetStepResult& ioResult,
                             fem::TetStepAttempt& ioAttempt)
{
    const double dt = inDeltaTime / inSubSteps;
    BindAll();
    const std::uint32_t zero[4] = {0, 0, 0, 0};
    mStatus.Upload(0, sizeof(zero), zero);
    if (mBreakable)
        SetFractureUniforms();
    if (mPlastic)
        SetPlasticUniforms(dt);
    bool stepped = true;
    if (IsImplicit())
    {
        // intent: inSubSteps implicit steps, each followed by the fracture passes
        SetElementPassUniforms(0.0);
        for (int piece = 0; piece < inSubSteps && stepped; ++piece)
        {
            RefreshCoarseSpace(dt);
            GpuImplicitStepInput input;
            input.mDeltaTime = dt;
            input.mMassDamping = mMaterial.mMassDamping;
            input.mStiffnessDamping = mMaterial.mStiffnessDamping;
            input.mLambda = mLambda;
            input.mMu = mMu;
            input.mGravity = mSettings.mGravity;
            input.mCorotated = mMaterial.mModel == fem::EElasticModel::CorotatedLinear;
            input.mPlastic = mPlastic;
            input.mSettings = &mSettings;
            input.mCrackSafeEnergy = mCrackSafeEnergy;
            input.mInverseMasses = mInverseMasses;
            input.mMasses = mMasses;
            input.mElementCount = mElementCount;
            input.mForcePass = &mElementPass;
            input.mPositions = &mPositions;
            input.mVelocities = &mVelocities;
            const GpuImplicitStepStats stats = mImplicit->Step(input);
            mCoarseUnknowns = stats.mCoarseUnknowns;
            mLongestSolve = std::max(mLongestSolve, stats.mMostSolveIterations);
            mElementWork += stats.mElementPasses * mElementCount;
            ioResult.mNewtonIterations += stats.mNewtonIterations;
            ioResult.mSolverIterations += stats.mSolverIterations;
            ioResult.mSolverResidual = std::max(ioResult.mSolverResidual, stats.mSolverResidual);
            if (!stats.mConverged)
                ioResult.mEvents = ioResult.mEvents | fem::ETetStepEvent::SolverNotConverged;
            stepped = stats.mAllocated && !stats.mDiverged;
            if (stepped)
                AfterSubStep(ioAttempt.mBrokenLinks); // rebinds the node buffers a crack replaced
        }
    }
    else
    {
        SetElementPassUniforms(mMaterial.mStiffnessDamping);
        const float damping_scale = static_cast<float>(1.0 / (1.0 + mMaterial.mMassDamping * dt));
        mNodePass.Use();
        mNodePass.SetFloat("uDeltaTime", static_cast<float>(dt));
        mNodePass.SetFloat("uDampingScale", damping_scale);
        mNodePass.SetVec3("uGravity", mSettings.mGravity);
        mNodePass.SetUInt("uNodeCount", static_cast<std::uint32_t>(mMasses.size()));
        for (int sub_step = 0; sub_step < inSubSteps; ++sub_step)
        {
            mElementPass.Use();
            mElementPass.Dispatch(mElementCount);
            mNodePass.Use();
            mNodePass.Dispatch(static_cast<std::uint32_t>(mMasses.size()));
            AfterSubStep(ioAttempt.mBrokenLinks);
        }
        mElementWork += static_cast<std::uint64_t>(inSubSteps) * mElementCount;
    }

    // The kinetic energy, then the step's one status read: divergence flag and energy.
    mEnergyPass.Use();
    mEnergyPass.SetUInt("uNodeCount", static_cast<std::uint32_t>(mMasses.size()));
    mEnergyPass.Dispatch(mEnergyPass.GetLocalSize()); // exactly one work group
    std::uint32_t words[4] = {0, 0, 0, 0};
    mStatus.Download(0, sizeof(words), words);
    float energy = 0.0f;
    std::memcpy(&energy, &words[2], sizeof(energy));
    ioAttempt.mKineticEnergy = energy;
    ioAttempt.mPlasticElements = static_cast<int>(words[3]);
    return stepped && words[0] == 0 && std::isfinite(energy);
}

// The GPU side of fem::TetStepper's policy: the node state saved and restored by buffer copies on the device
// (no readback), divergence detected as a non-finite state only.
class GpuTetSolver::StepBackend final : public fem::TetStepBackend
{
public:
    explicit StepBackend(GpuTetSolver& ioSolver) : mSolver(ioSolver) {}

    Result<int> SubStepsFor(double inDeltaTime) const override { return mSolver.SubStepCount(inDeltaTime); }

    bool IsExplicit() const override { return !mSolver.IsImplicit(); }

    Status SaveStepStart() override
    {
        GpuTetSolver& s = mSolver;
        if (Status status = s.mDevice->MakeCurrent(); status.HasError())
            return status;
        const auto save = [&](StorageBuffer& outCopy, const StorageBuffer& inSource) {
            if (outCopy.GetSize() != inSource.GetSize())
                (void)Assign(outCopy, StorageBuffer::Create(s.mDevice, inSource.GetSize()));
            outCopy.CopyFrom(inSource);
        };
        save(s.mSavedPositions, s.mPositions);
        save(s.mSavedVelocities, s.mVelocities);
        save(s.mSavedExternal, s.mExternal);
        save(s.mSavedRotations, s.mRotations);
        save(s.mSavedPlasticStrains, s.mPlasticStrains);
        s.mSavedElementNodes = s.mElementNodes;
        s.mSavedBroken = s.mBroken;
        s.mSavedMasses = s.mMasses;
        s.mSavedInverseMasses = s.mInverseMasses;
        return Status::Ok();
    }

    void RestoreStepStart() override
    {
        GpuTetSolver& s = mSolver;
        if (s.mElementNodes != s.mSavedElementNodes)
        {
            // A crack opened during the attempt: put the connectivity back first (buffer sizes follow it).
            std::vector<Float4> node_state(s.mSavedMasses.size());
            (void)s.UploadTopology(s.mSavedElementNodes, node_state, node_state, node_state);
            s.mBroken = s.mSavedBroken;
            const std::vector<std::uint32_t> broken(s.mSavedBroken.begin(), s.mSavedBroken.end());
            if (!broken.empty())
                s.mBrokenBuffer.Upload(0, broken.size() * sizeof(std::uint32_t), broken.data());
            s.mMasses = s.mSavedMasses;
            s.mInverseMasses = s.mSavedInverseMasses;
        }
        s.mPositions.CopyFrom(s.mSavedPositions);
        s.mVelocities.CopyFrom(s.mSavedVelocities);
        s.mExternal.CopyFrom(s.mSavedExternal);
        s.mRotations.CopyFrom(s.mSavedRotations);
        s.mPlasticStrains.CopyFrom(s.mSavedPlasticStrains);
    }

    fem::TetStepAttempt Attempt(double inDeltaTime, int inPieces, fem::TetStepResult& ioResult) override
    {
        fem::TetStepAttempt attempt;
        mSolver.mIntegrated = true; // what the step leaves is not known without a readback
        attempt.mDiverged = !mSolver.Integrate(inDeltaTime, inPieces, ioResult, attempt);
        return attempt;
    }

    // The restored start's energies would need a readback: left 0.
    void DescribeRestored(fem::TetStepResult&) const override {}

    // Before the first integration the state is read back and compared exactly (a rebuilt prop answers the
    // same); after it, knowing would need a readback per step, and the GPU solver counts quiet steps instead.
    bool IsAtRestUnloaded() const override
    {
        if (mSolver.mIntegrated || mSolver.mPlasticSet)
            return false; // a plastic set strains the rest positions
        const bool pulled = !mSolver.mSettings.mGravity.isZero(0.0) &&
                            std::any_of(mSolver.mInverseMasses.begin(), mSolver.mInverseMasses.end(),
                                        [](double inInverseMass) { return inInverseMass > 0.0; });
        return !pulled && mSolver.IsStillAndUnstrained(); // the readback last
    }

    double FreeMass() const override
    {
        double free_mass = 0.0;
        for (std::size_t node = 0; node < mSolver.mMasses.size(); ++node)
            free_mass += mSolver.mInverseMasses[node] > 0.0 ? mSolver.mMasses[node] : 0.0;
        return free_mass;
    }

    void FallAsleep() override
    {
        const std::vector<Float4> zeros(mSolver.mMasses.size(), Float4{});
        mSolver.mVelocities.Upload(0, zeros.size() * sizeof(Float4), zeros.data());
    }

private:
    GpuTetSolver& mSolver;
};

Result<int> GpuTetSolver::SubStepCount(double inDeltaTime) const
{
    if (IsImplicit())
        return 1;
    const double count = std::ceil(inDeltaTime / mStableTimeStep);
    if (!(count <= static_cast<double>(mSettings.mMaxSubSteps)))
    {
        std::ostringstream message;
        message << "GpuTetSolver::Step: " << inDeltaTime << " s needs " << count << " sub-steps of at most "
                << mStableTimeStep << " s, more than TetSolverSettings.mMaxSubSteps = " << mSettings.mMaxSubSteps;
        return MakeError(EError::InvalidArgument, message.str());
    }
    return std::max(1, static_cast<int>(count));
}

Status GpuTetSolver::CheckStep(double inDeltaTime) const
{
    if (Status valid = CheckTimeStep(inDeltaTime, "GpuTetSolver::Step"); !valid)
        return valid;
    Result<int> count = SubStepCount(inDeltaTime);
    return count.HasError() ? Status(count.GetError()) : Status::Ok();
}

Result<fem::TetStepResult> GpuTetSolver::Step(double inDeltaTime)
{
    StepBackend backend(*this);
    return mStepper.Step(backend, mSettings, inDeltaTime, "GpuTetSolver");
}

std::vector<fem::TetFragment> GpuTetSolver::ComputeFragments() const
{
    std::vector<Vec3> positions;
    ReadPositions(positions);
    std::vector<double> element_masses;
    for (const fem::TetElementRest& element : mRest)
        element_masses.push_back(mMaterial.mDensity * element.mRestVolume);
    if (mBreakable)
        return fem::TetFragments(mLinks, mElementNodes, element_masses, positions, mInverseMasses);
    return fem::TetFragments(fem::BuildFractureLinks(mMesh), mElementNodes, element_masses, positions, mInverseMasses);
}

Status GpuTetSolver::ReadNodeBuffer(const StorageBuffer& inBuffer, std::vector<Vec3>& outValues) const
{
    outValues.clear();
    if (Status status = mDevice->MakeCurrent(); status.HasError())
        return status;
    std::vector<Float4> packed(mMasses.size());
    inBuffer.Download(0, packed.size() * sizeof(Float4), packed.data());
    outValues.resize(packed.size());
    for (std::size_t node = 0; node < packed.size(); ++node)
        outValues[node] = ToVec3(packed[node]);
    return Status::Ok();
}

bool GpuTetSolver::IsStillAndUnstrained() const
{
    // intent: exact comparisons, as fem::TetSolver::IsStillAndUnstrained; velocities first
    std::vector<Vec3> values;
    const auto all_zero = [&values]
    { return std::all_of(values.begin(), values.end(), [](const Vec3& inValue) { return (inValue.array() == 0.0).all(); }); };
    if (ReadNodeBuffer(mVelocities, values).HasError() || !all_zero())
        return false;
    if (ReadNodeBuffer(mExternal, values).HasError() || !all_zero())
        return false;
    if (ReadNodeBuffer(mPositions, values).HasError())
        return false;
    return std::equal(values.begin(), values.end(), mMadeRestPositions.begin(), mMadeRestPositions.end(),
                      [](const Vec3& inRead, const Vec3& inRest)
                      { return (inRead.array() == inRest.cast<float>().cast<double>().array()).all(); });
}

void GpuTetSolver::ReadPositions(std::vector<Vec3>& outPositions) const
{
    if (ReadNodeBuffer(mPositions, outPositions).HasError())
        outPositions.assign(mMasses.size(), Vec3::Zero()); // as documented: callers index by node
}

void GpuTetSolver::ReadVelocities(std::vector<Vec3>& outVelocities) const
{
    if (ReadNodeBuffer(mVelocities, outVelocities).HasError())
        outVelocities.assign(mMasses.size(), Vec3::Zero());
}

void GpuTetSolver::ReadPlasticStrains(std::vector<Mat3>& outStrains) const
{
    outStrains.clear();
    if (!mPlastic || mDevice->MakeCurrent().HasError())
        return;
    std::vector<Float4> columns(3 * static_cast<std::size_t>(mElementCount));
    mPlasticStrains.Download(0, columns.size() * sizeof(Float4), columns.data());
    outStrains.resize(mElementCount);
    for (std::size_t element = 0; element < outStrains.size(); ++element)
        for (int column = 0; column < 3; ++column)
            outStrains[element].col(column) = ToVec3(columns[3 * element + static_cast<std::size_t>(column)]);
}

void GpuTetSolver::ReadExternalForces(std::vector<Vec3>& outForces) const
{
    if (ReadNodeBuffer(mExternal, outForces).HasError())
        outForces.assign(mMasses.size(), Vec3::Zero());
}

Status GpuTetSolver::ReadNodeState(std::vector<Vec3>& outPositions, std::vector<Vec3>& outVelocities,
                                   std::vector<Vec3>& outForces) const
{
    Status status = ReadNodeBuffer(mPositions, outPositions);
    if (status.IsValid())
        status = ReadNodeBuffer(mVelocities, outVelocities);
    if (status.IsValid())
        status = ReadNodeBuffer(mExternal, outForces);
    if (status.HasError())
    {
        outPositions.clear();
        outVelocities.clear();
        outForces.clear();
    }
    return status;
}

} // namespace crumple::gpu
