// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "GpuImplicitStep.h"

#include "EmbeddedShaders.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace crumple::gpu
{

namespace
{

// The shaders' binding points of the step's own buffers (GpuTetSolver binds 0-17).
enum EBinding : std::uint32_t
{
    cStartPositions = 18,
    cStartVelocities = 19,
    cResidual = 20,
    cPreconditioned = 21,
    cDirection = 22,
    cOperatorProduct = 23,
    cSolution = 24,
    cBlocks = 25,
    cProducts = 26,
    cScalars = 27,
    cProductInput = 28,
    cDotA = 29,
    cDotB = 30,
    // TetCoarseCorrection's node modes, members and coarse values: bindings the product (28) and the dots
    // (29, 30) rebind for themselves
    cCoarseNodes = 28,
    cCoarseMembers = 29,
    cCoarseValues = 30,
    // TetStvkLinearization's output, read by the product and the Jacobi blocks: TetDot's first operand
    // binding, which every dot rebinds for itself
    cLinearization = 29,
};

// TetConjugateGradient's operations and TetDot's modes.
enum EOperation : std::uint32_t
{
    cStart = 0,
    cOperator = 1,
    cUpdate = 2,
    cAdvance = 4,
};
enum EDotMode : std::uint32_t
{
    cSolveStarts = 0,
    cCurvature = 1,
    cNewResidual = 2,
};

// The scalars TetDot and TetImplicitScale write (floats; slots 1-3, the first r.z and the step lengths, are
// the shaders' own).
constexpr std::size_t cScalarCount = 16;
constexpr std::size_t cRz = 0, cNoCurvature = 4, cKinetic = 5, cMomentum = 6, cLoad = 9;

// Energy added to the step's scale so a body at rest has one (J), the CPU's.
constexpr double cEnergyFloor = 1.0e-12;

// A solve reads its residual back at these iterations: 1, 2, 4, 8, then every 8th.
bool ChecksAt(int inIteration)
{
    return inIteration <= 8 ? (inIteration & (inIteration - 1)) == 0 : inIteration % 8 == 0;
}

using Float4 = std::array<float, 4>;

} // namespace

Result<GpuImplicitStep> GpuImplicitStep::Create(std::shared_ptr<ComputeDevice> inDevice,
                                                bool inStVenantKirchhoff)
{
    GpuImplicitStep step;
    step.mDevice = inDevice;
    step.mStVenantKirchhoff = inStVenantKirchhoff;
    const struct
    {
        ComputeProgram* mProgram;
        const char* mName;
        std::string_view mSource;
    } programs[] = {{&step.mProduct, "TetStiffnessProduct", cShaderTetStiffnessProduct},
                    {&step.mResidual, "TetImplicitResidual", cShaderTetImplicitResidual},
                    {&step.mJacobi, "TetJacobiBlocks", cShaderTetJacobiBlocks},
                    {&step.mConjugateGradient, "TetConjugateGradient", cShaderTetConjugateGradient},
                    {&step.mDot, "TetDot", cShaderTetDot},
                    {&step.mScale, "TetImplicitScale", cShaderTetImplicitScale},
                    {&step.mCoarse, "TetCoarseCorrection", cShaderTetCoarseCorrection}};
    for (const auto& program : programs)
    {
        Result<ComputeProgram> compiled = ComputeProgram::Create(inDevice, program.mName, program.mSource);
        if (compiled.HasError())
            return compiled.GetError();
        *program.mProgram = std::move(compiled.Get());
    }
    if (inStVenantKirchhoff)
    {
        Result<ComputeProgram> compiled =
            ComputeProgram::Create(inDevice, "TetStvkLinearization", cShaderTetStvkLinearization);
        if (compiled.HasError())
            return compiled.GetError();
        step.mLinearize = std::move(compiled.Get());
    }
    const std::array<float, cScalarCount> zeros{};
    Result<StorageBuffer> scalars = StorageBuffer::Create(inDevice, sizeof(zeros), zeros.data());
    if (scalars.HasError())
        return scalars.GetError();
    step.mScalars = std::move(scalars.Get());
    return step;
}

Status GpuImplicitStep::Reserve(std::size_t inNodes, std::size_t inElements)
{
    // intent: made anew only when a crack changed the node count (or on the first step); all or nothing
    if (inNodes == mNodeCount && inElements == mElementCount)
        return Status::Ok();
    const std::size_t node_bytes = std::max<std::size_t>(1, inNodes) * sizeof(Float4);
    // F and S+ per element for St. Venant-Kirchhoff (TetStvkLinearization), else a one-vector dummy
    const std::size_t linearization_bytes =
        (mStVenantKirchhoff ? 6 * std::max<std::size_t>(1, inElements) : 1) * sizeof(Float4);
    struct
    {
        StorageBuffer* mBuffer;
        Result<StorageBuffer> mResult;
    } made[] = {{&mStartPositions, StorageBuffer::Create(mDevice, node_bytes)},
                {&mStartVelocities, StorageBuffer::Create(mDevice, node_bytes)},
                {&mResidualVector, StorageBuffer::Create(mDevice, node_bytes)},
                {&mPreconditioned, StorageBuffer::Create(mDevice, node_bytes)},
                {&mDirection, StorageBuffer::Create(mDevice, node_bytes)},
                {&mOperatorProduct, StorageBuffer::Create(mDevice, node_bytes)},
                {&mSolution, StorageBuffer::Create(mDevice, node_bytes)},
                {&mBlocks, StorageBuffer::Create(mDevice, 3 * node_bytes)},
                {&mProducts,
                 StorageBuffer::Create(mDevice, 4 * std::max<std::size_t>(1, inElements) * sizeof(Float4))},
                {&mLinearization, StorageBuffer::Create(mDevice, linearization_bytes)}};
    for (const auto& buffer : made)
        if (buffer.mResult.HasError())
            return buffer.mResult.GetError();
    for (auto& buffer : made)
        *buffer.mBuffer = std::move(buffer.mResult.Get());
    mNodeCount = inNodes;
    mElementCount = inElements;
    return Status::Ok();
}

Status GpuImplicitStep::SetCoarseSpace(const fem::TetCoarseSpace* inSpace)
{
    if (inSpace == nullptr || inSpace->GetAggregateCount() <= 0)
    {
        mCoarseAggregates = 0;
        mCoarseNodeCount = 0;
        return Status::Ok();
    }
    const auto aggregates = static_cast<std::size_t>(inSpace->GetAggregateCount());
    const std::size_t node_count = inSpace->mNodeAggregate.size();
    const std::size_t unknowns = 6 * aggregates;
    std::vector<Float4> nodes(node_count);
    for (std::size_t node = 0; node < node_count; ++node)
    {
        const Vec3& offset = inSpace->mNodeOffset[node];
        nodes[node] = {static_cast<float>(offset.x()), static_cast<float>(offset.y()),
                       static_cast<float>(offset.z()), static_cast<float>(inSpace->mNodeAggregate[node])};
    }
    // intent: the members' offsets count from the buffer's start, past the A + 1 offsets themselves
    std::vector<std::uint32_t> members;
    members.reserve(aggregates + 1 + inSpace->mAggregateNodes.size());
    for (int start : inSpace->mAggregateStart)
        members.push_back(static_cast<std::uint32_t>(aggregates + 1 + static_cast<std::size_t>(start)));
    for (int node : inSpace->mAggregateNodes)
        members.push_back(static_cast<std::uint32_t>(node));
    std::vector<float> values(2 * unknowns + unknowns * unknowns + 9 * aggregates, 0.0f);
    for (std::size_t aggregate = 0; aggregate < aggregates; ++aggregate)
        for (std::size_t axis = 0; axis < 3; ++axis)
            values[2 * unknowns + unknowns * unknowns + 9 * aggregate + 4 * axis] = 1.0f; // unturned
    for (std::size_t row = 0; row < unknowns; ++row)
        for (std::size_t column = 0; column < unknowns; ++column)
            values[2 * unknowns + row * unknowns + column] = static_cast<float>(
                inSpace->mInverse(static_cast<Eigen::Index>(row), static_cast<Eigen::Index>(column)));
    Result<StorageBuffer> node_buffer =
        StorageBuffer::Create(mDevice, nodes.size() * sizeof(Float4), nodes.data());
    Result<StorageBuffer> member_buffer =
        StorageBuffer::Create(mDevice, members.size() * sizeof(std::uint32_t), members.data());
    Result<StorageBuffer> value_buffer =
        StorageBuffer::Create(mDevice, values.size() * sizeof(float), values.data());
    for (const Result<StorageBuffer>* made : {&node_buffer, &member_buffer, &value_buffer})
        if (made->HasError())
            return made->GetError(); // the previous space stays
    mCoarseNodes = std::move(node_buffer.Get());
    mCoarseMembers = std::move(member_buffer.Get());
    mCoarseValues = std::move(value_buffer.Get());
    mCoarseAggregates = static_cast<std::uint32_t>(aggregates);
    mCoarseNodeCount = node_count;
    mCoarseOffsets = inSpace->mNodeOffset;
    mCoarseNodeAggregate = inSpace->mNodeAggregate;
    return Status::Ok();
}

void GpuImplicitStep::TurnCoarseSpace(std::span<const Mat3> inTurns)
{
    if (mCoarseAggregates == 0 || inTurns.size() != mCoarseAggregates)
        return;
    const std::size_t unknowns = 6 * static_cast<std::size_t>(mCoarseAggregates);
    std::vector<float> turns(9 * inTurns.size());
    for (std::size_t aggregate = 0; aggregate < inTurns.size(); ++aggregate)
        for (int column = 0; column < 3; ++column)
            for (int row = 0; row < 3; ++row)
                turns[9 * aggregate + 3 * static_cast<std::size_t>(column) + static_cast<std::size_t>(row)] =
                    static_cast<float>(inTurns[aggregate](row, column));
    mCoarseValues.Upload((2 * unknowns + unknowns * unknowns) * sizeof(float), turns.size() * sizeof(float),
                         turns.data());
    std::vector<Float4> nodes(mCoarseOffsets.size());
    for (std::size_t node = 0; node < nodes.size(); ++node)
    {
        const int aggregate = mCoarseNodeAggregate[node];
        const Vec3 offset = aggregate < 0
                                ? Vec3::Zero()
                                : Vec3(inTurns[static_cast<std::size_t>(aggregate)] * mCoarseOffsets[node]);
        nodes[node] = {static_cast<float>(offset.x()), static_cast<float>(offset.y()),
                       static_cast<float>(offset.z()), static_cast<float>(aggregate)};
    }
    mCoarseNodes.Upload(0, nodes.size() * sizeof(Float4), nodes.data());
}

void GpuImplicitStep::CoarseCorrection() const
{
    if (!mCoarseActive)
        return;
    mCoarseNodes.Bind(cCoarseNodes);
    mCoarseMembers.Bind(cCoarseMembers);
    mCoarseValues.Bind(cCoarseValues);
    mCoarse.Use();
    const std::uint32_t unknowns = 6 * mCoarseAggregates;
    const std::uint32_t counts[] = {mCoarseAggregates, unknowns, mRunNodeCount};
    for (std::uint32_t operation = 0; operation < 3; ++operation)
    {
        mCoarse.SetUInt("uOperation", operation);
        mCoarse.SetUInt("uCount", counts[operation]);
        mCoarse.Dispatch(counts[operation]);
    }
}

void GpuImplicitStep::Dot(const StorageBuffer& inA, const StorageBuffer& inB, std::uint32_t inMode) const
{
    inA.Bind(cDotA);
    inB.Bind(cDotB);
    mDot.Use();
    mDot.SetUInt("uMode", inMode);
    mDot.Dispatch(mDot.GetLocalSize()); // exactly one work group
}

void GpuImplicitStep::NodeOperation(std::uint32_t inOperation) const
{
    mConjugateGradient.Use();
    mConjugateGradient.SetUInt("uOperation", inOperation);
    mConjugateGradient.Dispatch(mRunNodeCount);
}

void GpuImplicitStep::BindLinearization() const
{
    if (mStVenantKirchhoff)
        mLinearization.Bind(cLinearization);
}

void GpuImplicitStep::StiffnessProduct(const StorageBuffer& inDirection, bool inNewDirection) const
{
    inDirection.Bind(cProductInput);
    BindLinearization();
    mProduct.Use();
    mProduct.SetInt("uNewDirection", inNewDirection ? 1 : 0);
    mProduct.Dispatch(mRunElementCount);
}

// fem::TetSolver::StepImplicit's iteration (see there for the derivation), the vectors on the GPU.
GpuImplicitStepStats GpuImplicitStep::Step(const GpuImplicitStepInput& inInput)
{
    GpuImplicitStepStats stats;
    const std::size_t node_count = inInput.mMasses.size();
    if (Reserve(node_count, inInput.mElementCount).HasError())
    {
        stats.mAllocated = false;
        stats.mConverged = false;
        return stats;
    }
    const fem::TetSolverSettings& settings = *inInput.mSettings;
    const double h = inInput.mDeltaTime;
    const double mass_scale = 1.0 + h * inInput.mMassDamping;
    const double stiffness_scale = h * h + h * inInput.mStiffnessDamping;
    mRunNodeCount = static_cast<std::uint32_t>(node_count);
    mRunElementCount = inInput.mElementCount;

    // intent: the step's buffers bound, its start kept, its programs' uniforms set once
    const struct
    {
        const StorageBuffer* mBuffer;
        std::uint32_t mBinding;
    } bindings[] = {{&mStartPositions, cStartPositions},
                    {&mStartVelocities, cStartVelocities},
                    {&mResidualVector, cResidual},
                    {&mPreconditioned, cPreconditioned},
                    {&mDirection, cDirection},
                    {&mOperatorProduct, cOperatorProduct},
                    {&mSolution, cSolution},
                    {&mBlocks, cBlocks},
                    {&mProducts, cProducts},
                    {&mScalars, cScalars}};
    for (const auto& binding : bindings)
        binding.mBuffer->Bind(binding.mBinding);
    mStartPositions.CopyFrom(*inInput.mPositions);
    mStartVelocities.CopyFrom(*inInput.mVelocities);
    const auto h_float = static_cast<float>(h);
    mProduct.Use();
    mProduct.SetUInt("uElementCount", mRunElementCount);
    mProduct.SetFloat("uLambda", inInput.mLambda);
    mProduct.SetFloat("uMu", inInput.mMu);
    mProduct.SetInt("uCorotated", inInput.mCorotated ? 1 : 0);
    mResidual.Use();
    mResidual.SetUInt("uNodeCount", mRunNodeCount);
    mResidual.SetFloat("uDeltaTime", h_float);
    mResidual.SetFloat("uMassDamping", static_cast<float>(inInput.mMassDamping));
    mResidual.SetVec3("uGravity", inInput.mGravity);
    mJacobi.Use();
    mJacobi.SetUInt("uNodeCount", mRunNodeCount);
    mJacobi.SetFloat("uMassScale", static_cast<float>(mass_scale));
    mJacobi.SetFloat("uStiffnessScale", static_cast<float>(stiffness_scale));
    mJacobi.SetFloat("uLambda", inInput.mLambda);
    mJacobi.SetFloat("uMu", inInput.mMu);
    mJacobi.SetInt("uCorotated", inInput.mCorotated ? 1 : 0);
    if (mStVenantKirchhoff)
    {
        mLinearize.Use();
        mLinearize.SetUInt("uElementCount", mRunElementCount);
        mLinearize.SetFloat("uLambda", inInput.mLambda);
        mLinearize.SetFloat("uMu", inInput.mMu);
        mLinearize.SetInt("uPlastic", inInput.mPlastic ? 1 : 0);
    }
    mConjugateGradient.Use();
    mConjugateGradient.SetUInt("uNodeCount", mRunNodeCount);
    mConjugateGradient.SetFloat("uDeltaTime", h_float);
    mConjugateGradient.SetFloat("uMassScale", static_cast<float>(mass_scale));
    mConjugateGradient.SetFloat("uStiffnessScale", static_cast<float>(stiffness_scale));
    mDot.Use();
    mDot.SetUInt("uNodeCount", mRunNodeCount);
    mScale.Use();
    mScale.SetUInt("uNodeCount", mRunNodeCount);
    mScale.SetFloat("uDeltaTime", h_float);
    mScale.SetVec3("uGravity", inInput.mGravity);
    mScale.Dispatch(mScale.GetLocalSize()); // one work group, read back with the first residual
    mCoarseActive = mCoarseAggregates > 0 && mCoarseNodeCount == node_count;
    if (mCoarseActive)
    {
        mCoarse.Use();
        mCoarse.SetUInt("uUnknowns", 6 * mCoarseAggregates);
        stats.mCoarseUnknowns = static_cast<int>(6 * mCoarseAggregates);
    }

    double energy_scale = cEnergyFloor;
    bool converged = false;
    std::array<float, cScalarCount> scalars{};
    for (int iteration = 0; iteration <= settings.mImplicitMaxIterations; ++iteration)
    {
        // intent: forces, frames and residual at the current iterate (x0 on the first pass, which also
        // carries the -h K v0 term of the linearisation at x0)
        const bool first = iteration == 0;
        inInput.mForcePass->Use();
        inInput.mForcePass->Dispatch(mRunElementCount);
        ++stats.mElementPasses;
        if (mStVenantKirchhoff)
        {
            // intent: F and S+ of this iterate once, for every product and Jacobi block that follows
            BindLinearization();
            mLinearize.Use();
            mLinearize.Dispatch(mRunElementCount);
            ++stats.mElementPasses;
        }
        const double kv_scale = (first ? h : 0.0) + inInput.mStiffnessDamping;
        if (kv_scale > 0.0)
        {
            StiffnessProduct(*inInput.mVelocities, false);
            ++stats.mElementPasses;
        }
        mResidual.Use();
        mResidual.SetFloat("uKvScale", static_cast<float>(kv_scale));
        mResidual.Dispatch(mRunNodeCount);
        BindLinearization();
        mJacobi.Use();
        mJacobi.Dispatch(mRunNodeCount);
        ++stats.mElementPasses;
        NodeOperation(cStart);
        CoarseCorrection();
        Dot(mResidualVector, mPreconditioned, cSolveStarts);

        // intent: the Newton test on the energy of the remaining correction, 1/2 r.Br (one readback)
        mScalars.Download(0, sizeof(scalars), scalars.data());
        if (first)
        {
            // Kinetic energy relative to the free centre of mass when nothing is anchored, plus the load's.
            double free_mass = 0.0;
            bool anchored = false;
            for (std::size_t node = 0; node < node_count; ++node)
            {
                anchored = anchored || inInput.mInverseMasses[node] == 0.0;
                free_mass += inInput.mInverseMasses[node] > 0.0 ? inInput.mMasses[node] : 0.0;
            }
            double start_energy = scalars[cKinetic];
            const Vec3 momentum(scalars[cMomentum], scalars[cMomentum + 1], scalars[cMomentum + 2]);
            if (!anchored && free_mass > 0.0)
                start_energy = std::max(0.0, start_energy - 0.5 * momentum.squaredNorm() / free_mass);
            energy_scale = start_energy + scalars[cLoad] + cEnergyFloor;
        }
        const double rz = scalars[cRz];
        if (!std::isfinite(rz))
        {
            stats.mDiverged = true;
            stats.mConverged = false;
            return stats;
        }
        if (!first &&
            0.5 * rz <= std::min(settings.mImplicitTolerance * energy_scale, inInput.mCrackSafeEnergy))
        {
            converged = true;
            break;
        }
        if (iteration == settings.mImplicitMaxIterations)
            break;

        // intent: A dv = r by conjugate gradient from dv = 0 (a zero right-hand side is solved by dv = 0)
        int cg_iterations = 0;
        double relative = 0.0;
        bool solved = !(rz > 0.0);
        while (!solved && cg_iterations < settings.mCgMaxIterations)
        {
            // intent: the next direction z + beta p made inside the product and operator passes
            StiffnessProduct(mDirection, true);
            NodeOperation(cOperator);
            Dot(mDirection, mOperatorProduct, cCurvature);
            NodeOperation(cUpdate);
            CoarseCorrection();
            Dot(mResidualVector, mPreconditioned, cNewResidual);
            ++cg_iterations;
            if (ChecksAt(cg_iterations) || cg_iterations == settings.mCgMaxIterations)
            {
                mScalars.Download(0, 5 * sizeof(float), scalars.data());
                relative = std::sqrt(std::max(static_cast<double>(scalars[cRz]), 0.0) / rz);
                solved = relative <= settings.mCgRelativeTolerance;
                if (solved || scalars[cNoCurvature] != 0.0f || !std::isfinite(relative))
                    break;
            }
        }
        stats.mElementPasses += static_cast<std::uint64_t>(cg_iterations);
        stats.mSolverIterations += cg_iterations;
        stats.mMostSolveIterations = std::max(stats.mMostSolveIterations, cg_iterations);
        stats.mSolverResidual = std::max(stats.mSolverResidual, relative);
        if (!solved)
            stats.mConverged = false;
        NodeOperation(cAdvance);
        ++stats.mNewtonIterations;
    }
    if (!converged)
        stats.mConverged = false;
    return stats;
}

} // namespace crumple::gpu
