// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/props/PropRecording.h>

#include <crumple/base/ByteReader.h>
#include <crumple/base/ByteWriter.h>
#include <crumple/props/CollisionImpulses.h>

#if defined(CRUMPLE_PROPS_WITH_GPU)
#include <crumple/gpu/GpuTetSolver.h>
#endif

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace crumple::props
{

namespace
{

// Marks the settings written after the first recordings ("RFSH"), so that a record cut short or padded is
// not read as an older one.
constexpr std::uint32_t cRefreshSettingsTag = 0x48534652u;
// Marks a contact spread radius (FemProp::SetContactSpread, "SPRD"), written after the refresh settings only
// when it is not 0, so that a prop that does not spread records the same bytes as before it existed.
constexpr std::uint32_t cContactSpreadTag = 0x44525053u;
// Marks the crack stress tolerance (TetSolverSettings::mCrackStressTolerance, "CRCK"), written after the
// refresh settings and the spread only when it is finite: a record without it was made before the Newton test
// had that bound, and replays with none.
constexpr std::uint32_t cCrackToleranceTag = 0x4B435243u;
// Marks the factor refreshed by cost (TetSolverSettings::mFactorRefreshByCost, "RCST", then 1.0 as a double
// so that every optional setting but the ground takes 12 bytes), written after the crack stress tolerance
// only when on: a record without it was made before that policy, and replays without it.
constexpr std::uint32_t cRefreshByCostTag = 0x54534352u;
// Marks a ground (TetSolverSettings::mGround, "GRND": normal, offset, friction), written last and only when
// the prop has one: a record without it replays with none, as it ran.
constexpr std::uint32_t cGroundTag = 0x444E5247u;
// Bytes of the ground's record after its tag: three doubles of normal, the offset, the friction.
constexpr std::size_t cGroundBytes = 5 * 8;

// Refuses a count that the remaining bytes cannot hold at inBytesEach bytes per item.
bool ReadCount(ByteReader& ioReader, std::size_t inBytesEach, std::uint32_t& outCount)
{
    outCount = ioReader.ReadU32();
    return !ioReader.Failed() && static_cast<std::size_t>(outCount) <= ioReader.Remaining() / inBytesEach;
}

void WriteMaterial(ByteWriter& ioWriter, const fem::FemMaterialSettings& inMaterial)
{
    ioWriter.WriteDouble(inMaterial.mYoungsModulus);
    ioWriter.WriteDouble(inMaterial.mPoissonRatio);
    ioWriter.WriteDouble(inMaterial.mDensity);
    ioWriter.WriteDouble(inMaterial.mMassDamping);
    ioWriter.WriteDouble(inMaterial.mStiffnessDamping);
    ioWriter.WriteU32(static_cast<std::uint32_t>(inMaterial.mModel));
    ioWriter.WriteDouble(inMaterial.mYieldStress);
    ioWriter.WriteDouble(inMaterial.mCreepRate);
    ioWriter.WriteDouble(inMaterial.mMaxPlasticStrain);
    ioWriter.WriteDouble(inMaterial.mTensileStrength);
    ioWriter.WriteU32(static_cast<std::uint32_t>(inMaterial.mFractureMode));
}

// Out-of-range enums are left as read, for the solver's Create to refuse with its message.
void ReadMaterial(ByteReader& ioReader, fem::FemMaterialSettings& outMaterial)
{
    outMaterial.mYoungsModulus = ioReader.ReadDouble();
    outMaterial.mPoissonRatio = ioReader.ReadDouble();
    outMaterial.mDensity = ioReader.ReadDouble();
    outMaterial.mMassDamping = ioReader.ReadDouble();
    outMaterial.mStiffnessDamping = ioReader.ReadDouble();
    outMaterial.mModel = static_cast<fem::EElasticModel>(ioReader.ReadU32());
    outMaterial.mYieldStress = ioReader.ReadDouble();
    outMaterial.mCreepRate = ioReader.ReadDouble();
    outMaterial.mMaxPlasticStrain = ioReader.ReadDouble();
    outMaterial.mTensileStrength = ioReader.ReadDouble();
    outMaterial.mFractureMode = static_cast<fem::EFractureMode>(ioReader.ReadU32());
}

void WriteSettings(ByteWriter& ioWriter, const fem::TetSolverSettings& inSettings)
{
    ioWriter.WriteU32(static_cast<std::uint32_t>(inSettings.mIntegrator));
    ioWriter.WriteVec3(inSettings.mGravity);
    ioWriter.WriteDouble(inSettings.mStabilitySafetyFactor);
    ioWriter.WriteU32(static_cast<std::uint32_t>(inSettings.mMaxSubSteps));
    ioWriter.WriteU32(static_cast<std::uint32_t>(inSettings.mPreconditioner));
    ioWriter.WriteDouble(inSettings.mCgRelativeTolerance);
    ioWriter.WriteU32(static_cast<std::uint32_t>(inSettings.mCgMaxIterations));
    ioWriter.WriteU32(static_cast<std::uint32_t>(inSettings.mImplicitMaxIterations));
    ioWriter.WriteDouble(inSettings.mImplicitTolerance);
    ioWriter.WriteDouble(inSettings.mSleepSpeed);
    ioWriter.WriteU32(static_cast<std::uint32_t>(inSettings.mSleepStepCount));
    ioWriter.WriteDouble(inSettings.mDivergenceEnergyRatio);
    ioWriter.WriteU32(static_cast<std::uint32_t>(inSettings.mMaxStepSplits));
}

void ReadSettings(ByteReader& ioReader, fem::TetSolverSettings& outSettings)
{
    outSettings.mIntegrator = static_cast<fem::EIntegrator>(ioReader.ReadU32());
    outSettings.mGravity = ioReader.ReadVec3();
    outSettings.mStabilitySafetyFactor = ioReader.ReadDouble();
    outSettings.mMaxSubSteps = static_cast<int>(ioReader.ReadU32());
    outSettings.mPreconditioner = static_cast<fem::EImplicitPreconditioner>(ioReader.ReadU32());
    outSettings.mCgRelativeTolerance = ioReader.ReadDouble();
    outSettings.mCgMaxIterations = static_cast<int>(ioReader.ReadU32());
    outSettings.mImplicitMaxIterations = static_cast<int>(ioReader.ReadU32());
    outSettings.mImplicitTolerance = ioReader.ReadDouble();
    outSettings.mSleepSpeed = ioReader.ReadDouble();
    outSettings.mSleepStepCount = static_cast<int>(ioReader.ReadU32());
    outSettings.mDivergenceEnergyRatio = ioReader.ReadDouble();
    outSettings.mMaxStepSplits = static_cast<int>(ioReader.ReadU32());
}

} // namespace

Result<PropSetup> MakePropSetup(plugin::BodyId inBody, EFemBackend inBackend, const fem::TetSolver& inSolver)
{
    const fem::TetMesh& mesh = inSolver.GetMesh();
    if (inSolver.GetElementWorkCount() != 0)
        return MakeError(EError::InvalidArgument,
                         "MakePropSetup: the prop has already stepped; record a prop before its first step (add it "
                         "to a recording PropWorld when it is made)");
    PropSetup setup;
    setup.mBody = inBody;
    setup.mBackend = inBackend;
    setup.mRestPositions = mesh.GetRestPositions();
    setup.mTets = mesh.GetTets();
    setup.mGroups = mesh.GetGroups();
    setup.mMaterial = inSolver.GetMaterial().GetSettings();
    setup.mSettings = inSolver.GetSettings();
    setup.mPositions = inSolver.GetPositions();
    setup.mVelocities = inSolver.GetVelocities();
    setup.mExternalForces = inSolver.GetExternalForces();
    setup.mAnchored.resize(setup.mPositions.size());
    for (std::size_t node = 0; node < setup.mAnchored.size(); ++node)
        setup.mAnchored[node] = inSolver.GetInverseMasses()[node] == 0.0 ? 1 : 0;
    return setup;
}

namespace
{

#if defined(CRUMPLE_PROPS_WITH_GPU)
// The setup of a GPU prop's solver (its state read back), refused once it has stepped.
Result<PropSetup> GpuPropSetup(plugin::BodyId inBody, const gpu::GpuTetSolver& inSolver)
{
    if (inSolver.GetElementWorkCount() != 0)
        return MakeError(EError::InvalidArgument,
                         "MakePropSetup: the GPU prop has already stepped; record a prop before its first step (add it "
                         "to a recording PropWorld when it is made)");
    const fem::TetMesh& mesh = inSolver.GetMesh();
    PropSetup setup;
    setup.mBody = inBody;
    setup.mBackend = EFemBackend::Gpu;
    setup.mRestPositions = mesh.GetRestPositions();
    setup.mTets = mesh.GetTets();
    setup.mGroups = mesh.GetGroups();
    setup.mMaterial = inSolver.GetMaterialSettings();
    setup.mSettings = inSolver.GetSettings();
    if (Status read = inSolver.ReadNodeState(setup.mPositions, setup.mVelocities, setup.mExternalForces); read.HasError())
        return MakeError(EError::IoError, "MakePropSetup: the GPU prop's state could not be read back: " + read.GetError().mMessage);
    const std::size_t nodes = static_cast<std::size_t>(inSolver.GetNodeCount());
    // intent: positions still where the solver was made (the GPU got them as floats) are recorded as the
    // double ones they came from, so the rebuilt CPU solver is the very one the live GPU solver was made from
    // (both then answer IsStillAndUnstrained alike: a prop made still sleeps at its first step in both)
    const std::vector<Vec3>& made = inSolver.GetMadeRestPositions();
    bool unmoved = made.size() == nodes;
    for (std::size_t node = 0; unmoved && node < nodes; ++node)
        unmoved = setup.mPositions[node] == made[node].cast<float>().cast<double>();
    if (unmoved)
        setup.mPositions = made;
    setup.mAnchored.resize(setup.mPositions.size());
    for (std::size_t node = 0; node < setup.mAnchored.size(); ++node)
        setup.mAnchored[node] = inSolver.GetInverseMasses()[node] == 0.0 ? 1 : 0;
    return setup;
}
#endif

// The node lists of a prop's pieces (FemProp::ComputeFragments), kept while its broken links are: a
// hand-over records each of its loose pieces in a record of its own, and the pieces' nodes change only where
// links break (fixing a piece's nodes changes no connectivity).
struct PieceNodes
{
    int mBrokenLinks = -1;
    std::vector<std::vector<int>> mNodes;
};

// True when inNodes (a recorded loose piece, in the order it was recorded) are exactly the nodes of one of
// inProp's pieces now (FemProp::ComputeFragments, which TakeLooseFragments recorded them from).
bool IsFragmentOf(const FemProp& inProp, const std::vector<int>& inNodes, PieceNodes& ioPieces)
{
    if (ioPieces.mBrokenLinks != inProp.GetBrokenLinkCount())
    {
        ioPieces.mNodes.clear();
        for (fem::TetFragment& fragment : inProp.ComputeFragments())
            ioPieces.mNodes.push_back(std::move(fragment.mNodes));
        ioPieces.mBrokenLinks = inProp.GetBrokenLinkCount();
    }
    return std::find(ioPieces.mNodes.begin(), ioPieces.mNodes.end(), inNodes) != ioPieces.mNodes.end();
}

} // namespace

Result<PropSetup> MakePropSetup(plugin::BodyId inBody, const FemProp& inProp)
{
    const fem::TetSolver* cpu = inProp.GetCpuSolver();
#if defined(CRUMPLE_PROPS_WITH_GPU)
    Result<PropSetup> setup = cpu != nullptr ? MakePropSetup(inBody, EFemBackend::Cpu, *cpu) : GpuPropSetup(inBody, *inProp.GetGpuSolver());
#else
    if (cpu == nullptr)
        return MakeError(EError::InvalidArgument, "MakePropSetup: the prop has no solver");
    Result<PropSetup> setup = MakePropSetup(inBody, EFemBackend::Cpu, *cpu);
#endif
    if (setup.IsValid())
        setup.Get().mContactSpread = inProp.GetContactSpread();
    return setup;
}

Status ValidatePropSetupSizes(const PropSetup& inSetup)
{
    const std::size_t nodes = inSetup.mPositions.size();
    if (inSetup.mVelocities.size() != nodes || inSetup.mAnchored.size() != nodes || inSetup.mExternalForces.size() != nodes)
        return MakeError(EError::InvalidArgument, "PropSetup: " + std::to_string(nodes) + " positions but " +
                                                      std::to_string(inSetup.mVelocities.size()) + " velocities, " +
                                                      std::to_string(inSetup.mAnchored.size()) + " anchor flags and " +
                                                      std::to_string(inSetup.mExternalForces.size()) + " external forces");
    if (!inSetup.mGroups.empty() && inSetup.mGroups.size() != inSetup.mTets.size())
        return MakeError(EError::InvalidArgument, "PropSetup: " + std::to_string(inSetup.mGroups.size()) + " groups for " +
                                                      std::to_string(inSetup.mTets.size()) + " elements (none, or one each)");
    return Status::Ok();
}

Result<std::vector<std::byte>> EncodePropSetup(const PropSetup& inSetup)
{
    if (Status valid = ValidatePropSetupSizes(inSetup); valid.HasError())
        return valid.GetError();
    if (Status radius = CheckContactSpreadRadius(inSetup.mContactSpread, "PropSetup"); radius.HasError())
        return radius.GetError();
    // intent: what the reader would refuse is not written (infinity is written as no tag)
    if (!(inSetup.mSettings.mCrackStressTolerance > 0.0))
        return MakeError(EError::InvalidArgument,
                         "PropSetup: crack stress tolerance " +
                             std::to_string(inSetup.mSettings.mCrackStressTolerance) +
                             " must be > 0 (infinity for no bound)");
    ByteWriter writer;
    writer.WriteU32(inSetup.mBody.mValue);
    writer.WriteU32(inSetup.mBody.mGeneration);
    writer.WriteU32(static_cast<std::uint32_t>(inSetup.mBackend));
    WriteMaterial(writer, inSetup.mMaterial);
    WriteSettings(writer, inSetup.mSettings);
    writer.WriteU32(static_cast<std::uint32_t>(inSetup.mRestPositions.size()));
    for (const Vec3& rest : inSetup.mRestPositions)
        writer.WriteVec3(rest);
    writer.WriteU32(static_cast<std::uint32_t>(inSetup.mPositions.size()));
    for (std::size_t node = 0; node < inSetup.mPositions.size(); ++node)
    {
        writer.WriteVec3(inSetup.mPositions[node]);
        writer.WriteVec3(inSetup.mVelocities[node]);
        writer.WriteVec3(inSetup.mExternalForces[node]);
        writer.WriteU8(inSetup.mAnchored[node]);
    }
    writer.WriteU32(static_cast<std::uint32_t>(inSetup.mTets.size()));
    for (std::size_t tet = 0; tet < inSetup.mTets.size(); ++tet)
    {
        for (int corner : inSetup.mTets[tet])
            writer.WriteU32(static_cast<std::uint32_t>(corner));
        writer.WriteU32(static_cast<std::uint32_t>(inSetup.mGroups.empty() ? static_cast<int>(tet) : inSetup.mGroups[tet]));
    }
    // Settings added after the first recordings, at the end behind a tag: a record without them is an older
    // one.
    writer.WriteU32(cRefreshSettingsTag);
    writer.WriteU32(static_cast<std::uint32_t>(inSetup.mSettings.mFactorRefreshIterations));
    if (inSetup.mContactSpread != 0.0)
    {
        writer.WriteU32(cContactSpreadTag);
        writer.WriteDouble(inSetup.mContactSpread);
    }
    if (std::isfinite(inSetup.mSettings.mCrackStressTolerance))
    {
        writer.WriteU32(cCrackToleranceTag);
        writer.WriteDouble(inSetup.mSettings.mCrackStressTolerance);
    }
    if (inSetup.mSettings.mFactorRefreshByCost)
    {
        writer.WriteU32(cRefreshByCostTag);
        writer.WriteDouble(1.0);
    }
    if (const fem::GroundPlane& ground = inSetup.mSettings.mGround; ground.mEnabled)
    {
        writer.WriteU32(cGroundTag);
        writer.WriteVec3(ground.mNormal);
        writer.WriteDouble(ground.mOffset);
        writer.WriteDouble(ground.mFriction);
    }
    return writer.TakeBytes();
}

Result<PropSetup> DecodePropSetup(std::span<const std::byte> inBytes)
{
    ByteReader reader(inBytes);
    PropSetup setup;
    setup.mBody.mValue = reader.ReadU32();
    setup.mBody.mGeneration = reader.ReadU32();
    setup.mBackend = static_cast<EFemBackend>(reader.ReadU32());
    ReadMaterial(reader, setup.mMaterial);
    ReadSettings(reader, setup.mSettings);
    std::uint32_t rest_nodes = 0, nodes = 0, tets = 0;
    if (!ReadCount(reader, 24, rest_nodes))
        return MakeError(EError::CorruptData, "prop record: rest node count is corrupt");
    for (std::uint32_t node = 0; node < rest_nodes; ++node)
        setup.mRestPositions.push_back(reader.ReadVec3());
    if (!ReadCount(reader, 3 * 24 + 1, nodes))
        return MakeError(EError::CorruptData, "prop record: node count is corrupt");
    for (std::uint32_t node = 0; node < nodes; ++node)
    {
        setup.mPositions.push_back(reader.ReadVec3());
        setup.mVelocities.push_back(reader.ReadVec3());
        setup.mExternalForces.push_back(reader.ReadVec3());
        setup.mAnchored.push_back(reader.ReadU8() != 0 ? 1 : 0);
    }
    if (!ReadCount(reader, 5 * 4, tets))
        return MakeError(EError::CorruptData, "prop record: element count is corrupt");
    for (std::uint32_t tet = 0; tet < tets; ++tet)
    {
        fem::TetIndices corners;
        for (int& corner : corners)
            corner = static_cast<int>(reader.ReadU32());
        setup.mTets.push_back(corners);
        setup.mGroups.push_back(static_cast<int>(reader.ReadU32()));
    }
    // intent: a record that ends here was written before mFactorRefreshIterations existed, when the factor
    // was never refreshed, and before the crack stress tolerance, when Newton had no such bound; 0 and
    // infinity replay it as it ran
    setup.mSettings.mFactorRefreshIterations = 0;
    setup.mSettings.mCrackStressTolerance = std::numeric_limits<double>::infinity();
    setup.mSettings.mFactorRefreshByCost = false;
    if (!reader.Failed() && reader.Remaining() >= 8 &&
        reader.Remaining() <= 8 + 12 + 12 + 12 + 4 + cGroundBytes)
    {
        if (reader.ReadU32() != cRefreshSettingsTag)
            return MakeError(EError::CorruptData, "prop record: unknown trailing settings");
        const std::uint32_t refresh = reader.ReadU32();
        if (refresh > static_cast<std::uint32_t>(std::numeric_limits<int>::max()))
            return MakeError(EError::CorruptData, "prop record: factor refresh iterations out of range");
        setup.mSettings.mFactorRefreshIterations = static_cast<int>(refresh);
        // intent: the optional tagged settings in the order they are written (spread, crack tolerance,
        // refresh by cost: each 12 bytes; the ground 44 and last). A record cut by exactly their bytes reads
        // as one without them; the replay file's CRC per record is what catches such a cut.
        std::uint32_t last_tag = cRefreshSettingsTag;
        while (!reader.Failed() && reader.Remaining() >= 12 && last_tag != cGroundTag)
        {
            const std::uint32_t tag = reader.ReadU32();
            if (tag == cGroundTag && reader.Remaining() == cGroundBytes)
            {
                fem::GroundPlane& ground = setup.mSettings.mGround;
                ground.mEnabled = true;
                ground.mNormal = reader.ReadVec3();
                ground.mOffset = reader.ReadDouble();
                ground.mFriction = reader.ReadDouble();
                // the solver's Create refuses a ground out of range with its own message
                last_tag = tag;
                continue;
            }
            const double value = reader.ReadDouble();
            if (tag == cContactSpreadTag && last_tag == cRefreshSettingsTag)
            {
                if (!std::isfinite(value) || value <= 0.0)
                    return MakeError(EError::CorruptData, "prop record: contact spread radius out of range");
                setup.mContactSpread = value;
            }
            else if (tag == cCrackToleranceTag && last_tag != cCrackToleranceTag &&
                     last_tag != cRefreshByCostTag)
            {
                if (!std::isfinite(value) || value <= 0.0)
                    return MakeError(EError::CorruptData, "prop record: crack stress tolerance out of range");
                setup.mSettings.mCrackStressTolerance = value;
            }
            else if (tag == cRefreshByCostTag && last_tag != cRefreshByCostTag)
            {
                if (value != 1.0)
                    return MakeError(EError::CorruptData, "prop record: factor refresh by cost is corrupt");
                setup.mSettings.mFactorRefreshByCost = true;
            }
            else
                return MakeError(EError::CorruptData, "prop record: unknown trailing settings");
            last_tag = tag;
        }
    }
    if (reader.Failed() || reader.Remaining() != 0)
        return MakeError(EError::CorruptData, "prop record: wrong length");
    if (setup.mBackend != EFemBackend::Cpu && setup.mBackend != EFemBackend::Gpu)
        return MakeError(EError::CorruptData, "prop record: unknown backend");
    return setup;
}

Result<fem::TetSolver> RebuildProp(const PropSetup& inSetup)
{
    // The mesh, material and settings are validated by their own Create; the state by the setters.
    if (Status valid = ValidatePropSetupSizes(inSetup); valid.HasError())
        return valid.GetError();
    Result<fem::TetMesh> mesh = fem::TetMesh::Create(inSetup.mRestPositions, inSetup.mTets, inSetup.mGroups);
    if (mesh.HasError())
        return mesh.GetError();
    Result<fem::TetSolver> solver = fem::TetSolver::Create(mesh.Get(), inSetup.mMaterial, inSetup.mSettings);
    if (solver.HasError())
        return solver.GetError();
    fem::TetSolver& rebuilt = solver.Get();
    if (rebuilt.GetNodeCount() != static_cast<int>(inSetup.mPositions.size()))
        return MakeError(EError::CorruptData, "prop record: the breakable mesh has a different node count than recorded");
    for (int node = 0; node < rebuilt.GetNodeCount(); ++node)
        if (inSetup.mAnchored[static_cast<std::size_t>(node)] != 0)
            if (Status status = rebuilt.SetNodeFixed(node, true); status.HasError())
                return status.GetError();
    if (Status status = rebuilt.SetPositions(inSetup.mPositions); status.HasError())
        return status.GetError();
    if (Status status = rebuilt.SetVelocities(inSetup.mVelocities); status.HasError())
        return status.GetError();
    for (int node = 0; node < rebuilt.GetNodeCount(); ++node)
        if (Status status = rebuilt.SetExternalForce(node, inSetup.mExternalForces[static_cast<std::size_t>(node)]);
            status.HasError())
            return status.GetError();
    return solver;
}

Result<std::vector<ReplayedProp>> ReplayProps(const plugin::Replay& inReplay,
                                              gpu::ComputeDeviceProvider* ioProvider, const JobSystem* inJobs)
{
    std::vector<ReplayedProp> props;
    std::vector<std::size_t> added_after; // per prop: the collisions recorded before it joined
    std::vector<PieceNodes> pieces;       // per prop: its pieces' nodes, for the loose records' check
    std::size_t next_collision = 0;
    // The collisions before an extension record reach the props that existed when they were dispatched, in
    // dispatch order.
    const auto apply_collisions_until = [&](std::size_t inEnd) -> Status
    {
        for (; next_collision < inEnd; ++next_collision)
        {
            const plugin::Collision& collision = inReplay.mCollisions[next_collision];
            for (std::size_t index = 0; index < props.size(); ++index)
                if (ReplayedProp& prop = props[index];
                    !prop.mRemoved && added_after[index] <= next_collision &&
                    (prop.mBody == collision.mBodyA || prop.mBody == collision.mBodyB))
                    if (Status status = prop.mProp.ApplyCollision(collision, prop.mBody); status.HasError())
                        return status;
        }
        return Status::Ok();
    };
    // Stepped off the game's thread (a Queued record): collisions reach the props at the next step.
    bool queued = false;
    bool any_prop_record = false;
    for (std::size_t index = 0; index < inReplay.mExtensions.size(); ++index)
    {
        const plugin::RecordedExtension& extension = inReplay.mExtensions[index];
        const std::string where = "prop record " + std::to_string(index) + ": ";
        if (extension.mAfterCollisions > inReplay.mCollisions.size())
            return MakeError(EError::CorruptData, where + "placed after more collisions than the file has");
        if (extension.mAfterCollisions < next_collision)
            return MakeError(EError::CorruptData, where + "placed before collisions an earlier record follows");
        const bool step_record = extension.mTag == static_cast<std::uint32_t>(EPropRecord::Step);
        if (!queued || step_record)
            if (Status status = apply_collisions_until(static_cast<std::size_t>(extension.mAfterCollisions)); status.HasError())
                return MakeError(status.GetError().mCode, where + status.GetError().mMessage);
        if (extension.mTag == static_cast<std::uint32_t>(EPropRecord::Queued))
        {
            if (!extension.mPayload.empty() || any_prop_record)
                return MakeError(EError::CorruptData, where + "a queued-collisions record with a payload or after other prop records");
            queued = true;
            continue;
        }
        const bool prop_record = extension.mTag == static_cast<std::uint32_t>(EPropRecord::Added) ||
                                 step_record ||
                                 extension.mTag == static_cast<std::uint32_t>(EPropRecord::Loose) ||
                                 extension.mTag == static_cast<std::uint32_t>(EPropRecord::Removed);
        any_prop_record = any_prop_record || prop_record;
        if (extension.mTag == static_cast<std::uint32_t>(EPropRecord::Added))
        {
            Result<PropSetup> setup = DecodePropSetup(extension.mPayload);
            if (setup.HasError())
                return MakeError(setup.GetError().mCode, where + setup.GetError().mMessage);
            if (std::any_of(props.begin(), props.end(),
                            [&](const ReplayedProp& p)
                            { return !p.mRemoved && p.mBody == setup.Get().mBody; }))
                return MakeError(EError::CorruptData, where + "a second prop for the same body");
            Result<fem::TetSolver> solver = RebuildProp(setup.Get());
            if (solver.HasError())
                return MakeError(solver.GetError().mCode, where + solver.GetError().mMessage);
            FemPropSettings backend;
            backend.mBackend = setup.Get().mBackend;
            FemProp prop = FemProp::FromSolver(ioProvider, std::move(solver.Get()), backend);
            if (fem::TetSolver* cpu = prop.GetCpuSolver(); cpu != nullptr)
                cpu->SetJobSystem(inJobs);
            if (Status spread = prop.SetContactSpread(setup.Get().mContactSpread); spread.HasError())
                return MakeError(EError::CorruptData, where + spread.GetError().mMessage);
            props.push_back({setup.Get().mBody, setup.Get().mBackend, std::move(prop), false});
            added_after.push_back(static_cast<std::size_t>(extension.mAfterCollisions));
            pieces.emplace_back();
        }
        else if (extension.mTag == static_cast<std::uint32_t>(EPropRecord::Step))
        {
            ByteReader reader(extension.mPayload);
            const double step = reader.ReadDouble();
            if (reader.Failed() || reader.Remaining() != 0)
                return MakeError(EError::CorruptData, where + "a step record of the wrong length");
            for (ReplayedProp& prop : props)
            {
                if (prop.mRemoved)
                    continue;
                if (Result<fem::TetStepResult> result = prop.mProp.Step(step); result.HasError())
                    return MakeError(result.GetError().mCode, where + result.GetError().mMessage);
            }
        }
        else if (extension.mTag == static_cast<std::uint32_t>(EPropRecord::Loose))
        {
            ByteReader reader(extension.mPayload);
            const std::uint32_t prop = reader.ReadU32();
            const std::uint32_t count = reader.ReadU32();
            if (reader.Failed() || prop >= props.size() || props[prop].mRemoved ||
                reader.Remaining() != 4 * static_cast<std::size_t>(count))
                return MakeError(
                    EError::CorruptData,
                    where + "a loose-piece record of no known prop, of a removed one or of the wrong length");
            FemProp& solver = props[prop].mProp;
            // intent: every node checked before any is fixed
            std::vector<int> nodes(count);
            for (int& node : nodes)
            {
                const std::uint32_t value = reader.ReadU32();
                if (value >= static_cast<std::uint32_t>(solver.GetNodeCount()))
                    return MakeError(EError::CorruptData, where + "a loose piece's node is not a node of its prop");
                node = static_cast<int>(value);
            }
            // intent: a piece recorded loose must be a piece of the prop as replayed; a CPU prop replays bit
            // for bit, so anything else means its FEM broke otherwise than live: a recording made by a build
            // whose FEM gives other results (fixing those nodes would tear the prop apart where it never
            // broke). A GPU prop is not checked: on another device or driver, or on the CPU, it replays
            // close, not bitwise.
            if (props[prop].mRecordedBackend == EFemBackend::Cpu && solver.GetBackend() == EFemBackend::Cpu &&
                !IsFragmentOf(solver, nodes, pieces[prop]))
                return MakeError(
                    EError::CorruptData,
                    where + "a loose piece of prop " + std::to_string(prop) +
                        " is none of its pieces as replayed: its FEM broke otherwise than when recorded "
                        "(a recording made by a build of Crumple whose FEM gives other results cannot "
                        "replay its props)");
            if (Status fixed = solver.SetNodesLeft(nodes); fixed.HasError())
                return MakeError(fixed.GetError().mCode, where + fixed.GetError().mMessage);
        }
        else if (extension.mTag == static_cast<std::uint32_t>(EPropRecord::Removed))
        {
            ByteReader reader(extension.mPayload);
            const std::uint32_t prop = reader.ReadU32();
            if (reader.Failed() || reader.Remaining() != 0 || prop >= props.size() || props[prop].mRemoved)
                return MakeError(EError::CorruptData,
                                 where +
                                     "a removal of no known prop, of a removed one or of the wrong length");
            props[prop].mRemoved = true;
        }
        // Other tags belong to other layers.
    }
    if (!queued)
        if (Status status = apply_collisions_until(inReplay.mCollisions.size()); status.HasError())
            return status.GetError();
    // intent: the props handed back keep no pointer to the caller's job system (they may step after it is
    // gone)
    for (ReplayedProp& prop : props)
        if (fem::TetSolver* cpu = prop.mProp.GetCpuSolver(); cpu != nullptr)
            cpu->SetJobSystem(nullptr);
    return props;
}

} // namespace crumple::props
