// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/plugin/DamageRecorder.h>
#include <crumple/plugin/DamageWorld.h>
#include <crumple/plugin/ReplayFormat.h>

#include <crumple/base/ByteWriter.h>
#include <crumple/base/FileBytes.h>

#include <limits>
#include <string>

namespace crumple::plugin
{

Result<std::unique_ptr<DamageRecorder>> DamageRecorder::Create(const std::filesystem::path& inPath, DamageWorld& inWorld)
{
    std::FILE* file = std::fopen(PartialFilePath(inPath).string().c_str(), "wb");
    if (file == nullptr)
        return MakeError(EError::IoError, "cannot write " + PartialFilePath(inPath).string());
    // Deferred dents started before the recording belong to the damage it starts from.
    inWorld.LandDents();
    std::unique_ptr<DamageRecorder> recorder(new DamageRecorder(file, inPath, inWorld));
    recorder->Write(EncodeReplayHeader());
    recorder->RecordNewObjects();
    if (!recorder->mStatus)
        return recorder->mStatus.GetError();
    inWorld.AddListener(recorder.get());
    return recorder;
}

DamageRecorder::~DamageRecorder()
{
    (void)Close();
}

void DamageRecorder::Write(std::span<const std::byte> inBytes)
{
    if (!mStatus || mFile == nullptr)
        return;
    if (std::fwrite(inBytes.data(), 1, inBytes.size(), mFile) != inBytes.size() || std::fflush(mFile) != 0)
        mStatus = MakeError(EError::IoError, "write failed: " + PartialFilePath(mPath).string());
}

void DamageRecorder::RecordNewObjects()
{
    // Objects appear in the file before any collision that can dent them, with the damage they have now.
    for (ObjectId id : mWorld->GetObjectIds())
    {
        // A slot reused by a new object (next generation) is a new object of the recording.
        if (mRecorded.size() <= id.mValue)
            mRecorded.resize(id.mValue + 1, 0);
        if (mRecorded[id.mValue] == id.mGeneration + 1)
            continue;
        mRecorded[id.mValue] = id.mGeneration + 1;
        const DeformableObject& object = *mWorld->GetObject(id);
        RecordedObject record;
        record.mObject = id;
        record.mBody = mWorld->GetObjectBody(id);
        record.mFirstCollision = mCollisions;
        record.mSettings.mMesh = object.GetDeformer().GetRestMesh();
        record.mSettings.mMaterial = object.GetMaterial();
        record.mSettings.mDeformer = object.GetDeformer().GetSettings();
        record.mSettings.mInterpolateWideImpacts = object.GetInterpolateWideImpacts();
        record.mSettings.mUpAxis = object.GetUpAxis();
        record.mSettings.mForwardAxis = object.GetCrushBody().mForward;
        for (const ffd::FfdLattice& zone : object.GetDeformer().GetZones())
            record.mInitialControls.push_back(zone.GetControlDisplacements());
        Write(EncodeReplayRecord(EReplayRecord::Object, EncodeRecordedObject(record)));
        ++mObjects;
    }
}

void DamageRecorder::OnBeforeCollision(const Collision& inCollision)
{
    if (mFile == nullptr)
        return;
    RecordNewObjects();
    // The collision is final here (the world shared its crush energy before the call); recorded now rather
    // than when its dents land, so deferred dents change nothing in the file (class comment).
    Write(EncodeReplayRecord(EReplayRecord::Collision, EncodeCollision(inCollision)));
    ++mCollisions;
}

Status DamageRecorder::WriteExtension(std::uint32_t inTag, std::span<const std::byte> inPayload)
{
    return WriteExtensionRecords(inTag, std::span<const std::span<const std::byte>>(&inPayload, 1));
}

Status DamageRecorder::WriteExtensions(std::uint32_t inTag, std::span<const std::vector<std::byte>> inPayloads)
{
    const std::vector<std::span<const std::byte>> payloads(inPayloads.begin(), inPayloads.end());
    return WriteExtensionRecords(inTag, payloads);
}

Status DamageRecorder::WriteExtensionRecords(std::uint32_t inTag, std::span<const std::span<const std::byte>> inPayloads)
{
    if (mFile == nullptr)
        return MakeError(EError::InvalidArgument, "DamageRecorder::WriteExtension: the recorder is closed");
    if (mStatus.HasError())
        return mStatus;
    // intent: a record's length field is 32 bits; a longer payload would be cut and the file lost. All are
    // checked before any is written.
    for (const std::span<const std::byte> payload : inPayloads)
        if (payload.size() > std::numeric_limits<std::uint32_t>::max() - sizeof(std::uint32_t))
            return MakeError(EError::InvalidArgument, "DamageRecorder::WriteExtension: a payload of " + std::to_string(payload.size()) +
                                                          " bytes is longer than a record holds (4 GiB)");
    // intent: the records' bytes one after the other, written and flushed once (a write is a system call:
    // 35 pieces that break loose at once cost 35 of them otherwise)
    std::vector<std::byte> bytes;
    for (const std::span<const std::byte> payload : inPayloads)
    {
        ByteWriter writer;
        writer.Reserve(sizeof(std::uint32_t) + payload.size());
        writer.WriteU32(inTag);
        writer.WriteBytes(payload);
        const std::vector<std::byte> record = EncodeReplayRecord(EReplayRecord::Extension, writer.GetBytes());
        bytes.insert(bytes.end(), record.begin(), record.end());
    }
    if (!bytes.empty())
        Write(bytes);
    return mStatus;
}

void DamageRecorder::OnCollision(const Collision&, std::span<const ObjectDent>)
{
}

Status DamageRecorder::Close()
{
    if (mFile == nullptr)
        return mStatus;
    if (mWorld != nullptr)
    {
        mWorld->LandDents(); // the recorded collisions' deferred dents land before the recording ends
        mWorld->RemoveListener(this);
    }
    ByteWriter end;
    end.WriteU32(mObjects);
    end.WriteU64(mCollisions);
    Write(EncodeReplayRecord(EReplayRecord::End, end.GetBytes()));
    if (std::fclose(mFile) != 0 && mStatus)
        mStatus = MakeError(EError::IoError, "close failed: " + PartialFilePath(mPath).string());
    mFile = nullptr;
    // Complete: rename over mPath. A failed rename keeps the partial file, which holds the whole recording.
    if (mStatus)
        mStatus = CommitPartialFile(mPath, "DamageRecorder");
    return mStatus;
}

} // namespace crumple::plugin
