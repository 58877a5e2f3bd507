// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/base/ByteReader.h>
#include <crumple/base/ByteWriter.h>
#include <crumple/base/ChecksumPolicy.h>
#include <crumple/base/Crc32.h>
#include <crumple/plugin/ReplayFormat.h>

#include <cmath>
#include <limits>
#include <string>

namespace crumple::plugin
{

namespace
{

constexpr std::string_view cMagic = "CRUMPREC";

void WriteMat3(ByteWriter& ioWriter, const Mat3& inM)
{
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            ioWriter.WriteDouble(inM(r, c));
}

Mat3 ReadMat3(ByteReader& ioReader)
{
    Mat3 m;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            m(r, c) = ioReader.ReadDouble();
    return m;
}

// A count read from a record, checked against the bytes that must follow it.
bool ReadCount(ByteReader& ioReader, std::size_t inBytesEach, std::uint32_t& outCount)
{
    outCount = ioReader.ReadU32();
    return !ioReader.Failed() && static_cast<std::uint64_t>(outCount) * inBytesEach <= ioReader.Remaining();
}

Result<RecordedObject> DecodeRecordedObject(std::span<const std::byte> inPayload, std::uint32_t inVersion)
{
    ByteReader reader(inPayload);
    RecordedObject object;
    object.mObject.mValue = reader.ReadU32();
    object.mObject.mGeneration = reader.ReadU32();
    object.mBody.mValue = reader.ReadU32();
    object.mBody.mGeneration = reader.ReadU32();
    object.mFirstCollision = reader.ReadU64();
    DeformableObjectSettings& settings = object.mSettings;
    settings.mMaterial.mDeformationFactor = reader.ReadDouble();
    settings.mMaterial.mMinDeformation = reader.ReadDouble();
    settings.mMaterial.mMaxInstantDeformation = reader.ReadDouble();
    settings.mMaterial.mImpulseThreshold = reader.ReadDouble();
    // An out-of-range model is left as read, for DeformableObject::Create to refuse with its message.
    settings.mMaterial.mModel = static_cast<ECrushModel>(reader.ReadU8());
    settings.mMaterial.mCrushA = reader.ReadDouble();
    settings.mMaterial.mCrushB = reader.ReadDouble();
    settings.mMaterial.mCrushG = reader.ReadDouble();
    settings.mMaterial.mMinCrushWidth = reader.ReadDouble();
    settings.mMaterial.mCrushedLengthFraction = reader.ReadDouble();
    settings.mUpAxis = reader.ReadVec3();
    settings.mInterpolateWideImpacts = reader.ReadU8() != 0;
    ffd::FfdDeformerSettings& deformer = settings.mDeformer;
    deformer.mRankTolerance = reader.ReadDouble();
    deformer.mMergeDistance = reader.ReadDouble();
    deformer.mCaptureDistance = reader.ReadDouble();
    deformer.mInverseIterations = static_cast<int>(reader.ReadU32());
    deformer.mMinControlSpacing = reader.ReadDouble();
    // An out-of-range prior is left as read, for FfdDeformer::Create to refuse with its message.
    deformer.mPrior = static_cast<ffd::EDirectManipulationPrior>(reader.ReadU32());
    deformer.mMaxControlGain = reader.ReadDouble();
    deformer.mOneSidedDents = reader.ReadU8() != 0;
    std::uint32_t zones = 0;
    if (!ReadCount(reader, 19 * 8, zones))
        return MakeError(EError::CorruptData, "object record: zone count is corrupt");
    for (std::uint32_t z = 0; z < zones; ++z)
    {
        ffd::FfdZoneSettings zone;
        zone.mLattice.mOrigin = reader.ReadVec3();
        zone.mLattice.mAxes = ReadMat3(reader);
        zone.mLattice.mSize = reader.ReadVec3();
        for (int& count : zone.mLattice.mControlCount)
            count = static_cast<int>(reader.ReadU32());
        zone.mMaxTotalDeformation = reader.ReadDouble();
        deformer.mZones.push_back(zone);
    }
    std::uint32_t vertices = 0, triangles = 0;
    if (!ReadCount(reader, 24, vertices))
        return MakeError(EError::CorruptData, "object record: vertex count is corrupt");
    settings.mMesh.mPositions.resize(vertices);
    for (Vec3& p : settings.mMesh.mPositions)
        p = reader.ReadVec3();
    if (!ReadCount(reader, 12, triangles))
        return MakeError(EError::CorruptData, "object record: triangle count is corrupt");
    settings.mMesh.mTriangles.resize(triangles);
    for (auto& t : settings.mMesh.mTriangles)
        for (std::uint32_t& index : t)
            index = reader.ReadU32();
    std::uint32_t control_zones = 0;
    if (!ReadCount(reader, 4, control_zones))
        return MakeError(EError::CorruptData, "object record: control state is corrupt");
    object.mInitialControls.resize(control_zones);
    for (std::vector<Vec3>& controls : object.mInitialControls)
    {
        std::uint32_t count = 0;
        if (!ReadCount(reader, 24, count))
            return MakeError(EError::CorruptData, "object record: control count is corrupt");
        controls.resize(count);
        for (Vec3& d : controls)
            d = reader.ReadVec3();
    }
    if (inVersion >= 8)
    {
        // Rigid parts: their indices are checked by FfdDeformer::Create when the object is rebuilt.
        std::uint32_t parts = 0;
        if (!ReadCount(reader, 4, parts))
            return MakeError(EError::CorruptData, "object record: rigid part count is corrupt");
        settings.mDeformer.mRigidParts.resize(parts);
        for (std::vector<std::uint32_t>& part : settings.mDeformer.mRigidParts)
        {
            std::uint32_t count = 0;
            if (!ReadCount(reader, 4, count))
                return MakeError(EError::CorruptData, "object record: rigid part size is corrupt");
            part.resize(count);
            for (std::uint32_t& vertex : part)
                vertex = reader.ReadU32();
        }
    }
    // Before version 10 no crush stopped at an occupant cell: 0.5 leaves none. An out-of-range value is left
    // as read, for DeformableObject::Create to refuse with its message.
    settings.mMaterial.mCrushZoneFraction = inVersion >= 10 ? reader.ReadDouble() : 0.5;
    // Before version 12 no material had the sides' own stiffness, before 13 the rear's (nor told its forward
    // axis). A flag other than 0 or 1 is corrupt; values out of range are left as read, for
    // DeformableObject::Create to refuse with its message.
    const auto read_zone = [&reader](bool& outHas, double& outA, double& outB, double& outG)
    {
        const std::uint8_t has = reader.ReadU8();
        outHas = has == 1;
        outA = reader.ReadDouble();
        outB = reader.ReadDouble();
        outG = reader.ReadDouble();
        return has <= 1;
    };
    DamageMaterial& material = settings.mMaterial;
    if (inVersion >= 12 && !read_zone(material.mHasSideStiffness, material.mSideCrushA, material.mSideCrushB,
                                      material.mSideCrushG))
        return MakeError(EError::CorruptData, "object record: the side stiffness flag is corrupt");
    if (inVersion >= 13)
    {
        if (!read_zone(material.mHasRearStiffness, material.mRearCrushA, material.mRearCrushB,
                       material.mRearCrushG))
            return MakeError(EError::CorruptData, "object record: the rear stiffness flag is corrupt");
        settings.mForwardAxis = reader.ReadVec3();
    }
    if (reader.Failed() || reader.Remaining() != 0)
        return MakeError(EError::CorruptData, "object record: length does not match its contents");
    // The lattices must be exactly as large as the control state the record carries, so a forged zone size
    // cannot make the replay allocate more than the file holds.
    if (object.mInitialControls.size() != deformer.mZones.size())
        return MakeError(EError::CorruptData, "object record: control state does not match its zones");
    for (std::size_t z = 0; z < deformer.mZones.size(); ++z)
    {
        const auto& n = deformer.mZones[z].mLattice.mControlCount;
        if (n[0] < 4 || n[1] < 4 || n[2] < 4 ||
            static_cast<std::uint64_t>(n[0]) * static_cast<std::uint64_t>(n[1]) * static_cast<std::uint64_t>(n[2]) !=
                object.mInitialControls[z].size())
            return MakeError(EError::CorruptData, "object record: zone " + std::to_string(z) + " size does not match its controls");
    }
    return object;
}

Result<Collision> DecodeCollision(std::span<const std::byte> inPayload, std::uint32_t inVersion)
{
    ByteReader reader(inPayload);
    Collision collision;
    collision.mBodyA.mValue = reader.ReadU32();
    collision.mBodyA.mGeneration = reader.ReadU32();
    collision.mBodyB.mValue = reader.ReadU32();
    collision.mBodyB.mGeneration = reader.ReadU32();
    collision.mStartTime = reader.ReadDouble();
    collision.mEndTime = reader.ReadDouble();
    collision.mSequence = reader.ReadU64();
    collision.mCrushEnergyA = reader.ReadDouble();
    collision.mCrushEnergyB = reader.ReadDouble();
    if (inVersion >= 11)
        for (ShapeBox* box : {&collision.mShapeOfBOnA, &collision.mShapeOfAOnB})
        {
            const std::uint8_t known = reader.ReadU8();
            box->mCenter = reader.ReadVec3();
            for (int c = 0; c < 3; ++c)
                box->mHalfAxes.col(c) = reader.ReadVec3();
            box->mKnown = known == 1;
            if (known > 1)
                return MakeError(EError::CorruptData, "collision record: a shape box has a bad flag");
        }
    std::uint32_t contacts = 0;
    const bool frictional = inVersion >= 9;
    if (!ReadCount(reader, (frictional ? 36 : 26) * 8, contacts))
        return MakeError(EError::CorruptData, "collision record: contact count is corrupt");
    collision.mContacts.resize(contacts);
    for (CollisionContact& c : collision.mContacts)
    {
        c.mPointOnA = reader.ReadVec3();
        c.mPointOnB = reader.ReadVec3();
        c.mLocalPointOnA = reader.ReadVec3();
        c.mLocalPointOnB = reader.ReadVec3();
        c.mNormal = reader.ReadVec3();
        c.mLocalNormalOnA = reader.ReadVec3();
        c.mLocalNormalOnB = reader.ReadVec3();
        c.mPenetrationDepth = reader.ReadDouble();
        c.mImpulse = reader.ReadDouble();
        c.mApproachSpeed = reader.ReadDouble();
        c.mAbsorbedEnergy = reader.ReadDouble();
        c.mTime = reader.ReadDouble();
        if (frictional)
        {
            c.mFriction = reader.ReadDouble();
            c.mFrictionImpulse = reader.ReadVec3();
            c.mLocalFrictionOnA = reader.ReadVec3();
            c.mLocalFrictionOnB = reader.ReadVec3();
        }
    }
    if (reader.Failed() || reader.Remaining() != 0)
        return MakeError(EError::CorruptData, "collision record: length does not match its contents");
    // intent: a record holds what a DamageWorld dispatches, nothing a hand-made collision could not pass
    // either
    if (Status valid = ValidateCollision(collision); !valid)
        return MakeError(EError::CorruptData, "collision record: " + valid.GetError().mMessage);
    return collision;
}

} // namespace

std::vector<std::byte> EncodeReplayHeader()
{
    ByteWriter writer;
    writer.WriteTag(cMagic);
    writer.WriteU32(cReplayVersion);
    return writer.TakeBytes();
}

std::vector<std::byte> EncodeReplayRecord(EReplayRecord inType, std::span<const std::byte> inPayload)
{
    ByteWriter writer;
    writer.WriteU8(static_cast<std::uint8_t>(inType));
    writer.WriteU32(static_cast<std::uint32_t>(inPayload.size()));
    writer.WriteBytes(inPayload);
    writer.WriteU32(Crc32(inPayload));
    return writer.TakeBytes();
}

std::vector<std::byte> EncodeRecordedObject(const RecordedObject& inObject)
{
    ByteWriter writer;
    const DeformableObjectSettings& settings = inObject.mSettings;
    writer.WriteU32(inObject.mObject.mValue);
    writer.WriteU32(inObject.mObject.mGeneration);
    writer.WriteU32(inObject.mBody.mValue);
    writer.WriteU32(inObject.mBody.mGeneration);
    writer.WriteU64(inObject.mFirstCollision);
    writer.WriteDouble(settings.mMaterial.mDeformationFactor);
    writer.WriteDouble(settings.mMaterial.mMinDeformation);
    writer.WriteDouble(settings.mMaterial.mMaxInstantDeformation);
    writer.WriteDouble(settings.mMaterial.mImpulseThreshold);
    writer.WriteU8(static_cast<std::uint8_t>(settings.mMaterial.mModel));
    writer.WriteDouble(settings.mMaterial.mCrushA);
    writer.WriteDouble(settings.mMaterial.mCrushB);
    writer.WriteDouble(settings.mMaterial.mCrushG);
    writer.WriteDouble(settings.mMaterial.mMinCrushWidth);
    writer.WriteDouble(settings.mMaterial.mCrushedLengthFraction);
    writer.WriteVec3(settings.mUpAxis);
    writer.WriteU8(settings.mInterpolateWideImpacts ? 1 : 0);
    writer.WriteDouble(settings.mDeformer.mRankTolerance);
    writer.WriteDouble(settings.mDeformer.mMergeDistance);
    writer.WriteDouble(settings.mDeformer.mCaptureDistance);
    writer.WriteU32(static_cast<std::uint32_t>(settings.mDeformer.mInverseIterations));
    writer.WriteDouble(settings.mDeformer.mMinControlSpacing);
    writer.WriteU32(static_cast<std::uint32_t>(settings.mDeformer.mPrior));
    writer.WriteDouble(settings.mDeformer.mMaxControlGain);
    writer.WriteU8(settings.mDeformer.mOneSidedDents ? 1 : 0);
    writer.WriteU32(static_cast<std::uint32_t>(settings.mDeformer.mZones.size()));
    for (const ffd::FfdZoneSettings& zone : settings.mDeformer.mZones)
    {
        writer.WriteVec3(zone.mLattice.mOrigin);
        WriteMat3(writer, zone.mLattice.mAxes);
        writer.WriteVec3(zone.mLattice.mSize);
        for (int count : zone.mLattice.mControlCount)
            writer.WriteU32(static_cast<std::uint32_t>(count));
        writer.WriteDouble(zone.mMaxTotalDeformation);
    }
    writer.WriteU32(static_cast<std::uint32_t>(settings.mMesh.mPositions.size()));
    for (const Vec3& p : settings.mMesh.mPositions)
        writer.WriteVec3(p);
    writer.WriteU32(static_cast<std::uint32_t>(settings.mMesh.mTriangles.size()));
    for (const auto& t : settings.mMesh.mTriangles)
        for (std::uint32_t index : t)
            writer.WriteU32(index);
    writer.WriteU32(static_cast<std::uint32_t>(inObject.mInitialControls.size()));
    for (const std::vector<Vec3>& controls : inObject.mInitialControls)
    {
        writer.WriteU32(static_cast<std::uint32_t>(controls.size()));
        for (const Vec3& d : controls)
            writer.WriteVec3(d);
    }
    writer.WriteU32(static_cast<std::uint32_t>(settings.mDeformer.mRigidParts.size()));
    for (const std::vector<std::uint32_t>& part : settings.mDeformer.mRigidParts)
    {
        writer.WriteU32(static_cast<std::uint32_t>(part.size()));
        for (std::uint32_t vertex : part)
            writer.WriteU32(vertex);
    }
    writer.WriteDouble(settings.mMaterial.mCrushZoneFraction);
    writer.WriteU8(settings.mMaterial.mHasSideStiffness ? 1 : 0);
    writer.WriteDouble(settings.mMaterial.mSideCrushA);
    writer.WriteDouble(settings.mMaterial.mSideCrushB);
    writer.WriteDouble(settings.mMaterial.mSideCrushG);
    writer.WriteU8(settings.mMaterial.mHasRearStiffness ? 1 : 0);
    writer.WriteDouble(settings.mMaterial.mRearCrushA);
    writer.WriteDouble(settings.mMaterial.mRearCrushB);
    writer.WriteDouble(settings.mMaterial.mRearCrushG);
    writer.WriteVec3(settings.mForwardAxis);
    return writer.TakeBytes();
}

std::vector<std::byte> EncodeCollision(const Collision& inCollision)
{
    ByteWriter writer;
    writer.WriteU32(inCollision.mBodyA.mValue);
    writer.WriteU32(inCollision.mBodyA.mGeneration);
    writer.WriteU32(inCollision.mBodyB.mValue);
    writer.WriteU32(inCollision.mBodyB.mGeneration);
    writer.WriteDouble(inCollision.mStartTime);
    writer.WriteDouble(inCollision.mEndTime);
    writer.WriteU64(inCollision.mSequence);
    writer.WriteDouble(inCollision.mCrushEnergyA);
    writer.WriteDouble(inCollision.mCrushEnergyB);
    for (const ShapeBox* box : {&inCollision.mShapeOfBOnA, &inCollision.mShapeOfAOnB})
    {
        writer.WriteU8(box->mKnown ? 1 : 0);
        writer.WriteVec3(box->mCenter);
        for (int c = 0; c < 3; ++c)
            writer.WriteVec3(box->mHalfAxes.col(c));
    }
    writer.WriteU32(static_cast<std::uint32_t>(inCollision.mContacts.size()));
    for (const CollisionContact& c : inCollision.mContacts)
    {
        writer.WriteVec3(c.mPointOnA);
        writer.WriteVec3(c.mPointOnB);
        writer.WriteVec3(c.mLocalPointOnA);
        writer.WriteVec3(c.mLocalPointOnB);
        writer.WriteVec3(c.mNormal);
        writer.WriteVec3(c.mLocalNormalOnA);
        writer.WriteVec3(c.mLocalNormalOnB);
        writer.WriteDouble(c.mPenetrationDepth);
        writer.WriteDouble(c.mImpulse);
        writer.WriteDouble(c.mApproachSpeed);
        writer.WriteDouble(c.mAbsorbedEnergy);
        writer.WriteDouble(c.mTime);
        writer.WriteDouble(c.mFriction);
        writer.WriteVec3(c.mFrictionImpulse);
        writer.WriteVec3(c.mLocalFrictionOnA);
        writer.WriteVec3(c.mLocalFrictionOnB);
    }
    return writer.TakeBytes();
}

Result<Replay> DecodeReplay(std::span<const std::byte> inBytes)
{
    ByteReader reader(inBytes);
    if (!reader.ReadTag(cMagic))
        return MakeError(EError::CorruptData, "not a Crumple replay file (bad magic)");
    const std::uint32_t version = reader.ReadU32();
    if (reader.Failed())
        return MakeError(EError::CorruptData, "replay file is truncated in its header");
    if (version < cOldestReplayVersion || version > cReplayVersion)
        return MakeError(EError::VersionMismatch, "replay file version " + std::to_string(version) +
                                                      ", this library reads versions " + std::to_string(cOldestReplayVersion) +
                                                      " to " + std::to_string(cReplayVersion));
    Replay replay;
    for (std::size_t index = 0;; ++index)
    {
        const std::string where = "record " + std::to_string(index) + ": ";
        if (reader.Remaining() == 0)
            return MakeError(EError::CorruptData, where + "the file ends without its end record (truncated)");
        const auto type = static_cast<EReplayRecord>(reader.ReadU8());
        const std::uint32_t length = reader.ReadU32();
        if (reader.Failed() || static_cast<std::uint64_t>(length) + 4 > reader.Remaining())
            return MakeError(EError::CorruptData, where + "truncated");
        const std::span<const std::byte> payload = inBytes.subspan(inBytes.size() - reader.Remaining(), length);
        reader.Skip(length);
        if (reader.ReadU32() != Crc32(payload) && cVerifyChecksums)
            return MakeError(EError::CorruptData, where + "checksum mismatch (corrupt)");
        switch (type)
        {
        case EReplayRecord::Object:
        {
            Result<RecordedObject> object = DecodeRecordedObject(payload, version);
            if (!object)
                return MakeError(object.GetError().mCode, where + object.GetError().mMessage);
            replay.mObjects.push_back(std::move(object).Get());
            break;
        }
        case EReplayRecord::Collision:
        {
            Result<Collision> collision = DecodeCollision(payload, version);
            if (!collision)
                return MakeError(collision.GetError().mCode, where + collision.GetError().mMessage);
            replay.mCollisions.push_back(std::move(collision).Get());
            break;
        }
        case EReplayRecord::Extension:
        {
            ByteReader extension(payload);
            RecordedExtension recorded;
            recorded.mAfterCollisions = replay.mCollisions.size();
            recorded.mTag = extension.ReadU32();
            if (extension.Failed())
                return MakeError(EError::CorruptData, where + "an extension record without its tag");
            recorded.mPayload.assign(payload.begin() + 4, payload.end());
            replay.mExtensions.push_back(std::move(recorded));
            break;
        }
        case EReplayRecord::End:
        {
            ByteReader end(payload);
            const std::uint32_t objects = end.ReadU32();
            const std::uint64_t collisions = end.ReadU64();
            if (end.Failed() || objects != replay.mObjects.size() || collisions != replay.mCollisions.size())
                return MakeError(EError::CorruptData, where + "the end record's counts do not match the file");
            if (reader.Remaining() != 0)
                return MakeError(EError::CorruptData, where + "data after the end record");
            return replay;
        }
        default:
            return MakeError(EError::CorruptData, where + "unknown record type " + std::to_string(static_cast<int>(type)));
        }
    }
}

} // namespace crumple::plugin
