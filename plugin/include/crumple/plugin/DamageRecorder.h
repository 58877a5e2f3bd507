// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Result.h>
#include <crumple/plugin/DamageListener.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <span>
#include <vector>

namespace crumple::plugin
{

class DamageWorld;

/// Records a damage world to a replay file as it runs (see ReplayFormat.h): each object's setup (mesh,
/// material, zones, current damage) before the first collision that involves it, then every dispatched
/// collision, written when the world dispatches it (OnBeforeCollision), so that with deferred dents
/// (DamageWorldSettings::mDeferDents) the records come in the same order, and the file has the same bytes,
/// as with dents on the caller's thread: a layer that records beside the collisions (crumple::props) sees
/// them at the same Update either way. Records are written and flushed as they come (WriteExtensions writes its records in one write); nothing is buffered for the whole run. The
/// file is written as "<path>.partial" and renamed to <path> by Close(), so an interrupted run never
/// leaves a file that looks complete. A game replicates damage over a network the same way: send these
/// records, not meshes.
class CRUMPLE_API DamageRecorder : public DamageListener
{
public:
    /// Opens the file and registers with inWorld (which must outlive the recorder or Close it first).
    static Result<std::unique_ptr<DamageRecorder>> Create(const std::filesystem::path& inPath, DamageWorld& inWorld);
    ~DamageRecorder() override;

    /// Writes the end record, closes and renames the file, unregisters from the world. Idempotent.
    Status Close();

    /// Records the objects of the collision's bodies not recorded yet (their damage before it), then it.
    void OnBeforeCollision(const Collision& inCollision) override;
    /// Nothing: the collision was recorded when it was dispatched.
    void OnCollision(const Collision& inCollision, std::span<const ObjectDent> inDents) override;

    /// Writes a record of a layer above the core (EReplayRecord::Extension: inTag, then inPayload) now, after
    /// the collisions recorded so far; DecodeReplay hands it back in Replay::mExtensions. Refused after
    /// Close() or a write error, and for a payload longer than a record holds (2^32 - 5 bytes), writing nothing.
    Status WriteExtension(std::uint32_t inTag, std::span<const std::byte> inPayload);
    /// WriteExtension for each payload in turn, with one write and flush of the file for all (the same bytes):
    /// for a layer that records many at once. Refused as a whole, writing nothing, for any payload it refuses.
    Status WriteExtensions(std::uint32_t inTag, std::span<const std::vector<std::byte>> inPayloads);

    /// Records written so far.
    std::uint64_t GetCollisionCount() const { return mCollisions; }
    /// The first write error, if any (later records are dropped after one).
    const Status& GetStatus() const { return mStatus; }
    /// False once Close() was called
    bool IsOpen() const { return mFile != nullptr; }

private:
    DamageRecorder(std::FILE* inFile, std::filesystem::path inPath, DamageWorld& inWorld)
        : mFile(inFile), mPath(std::move(inPath)), mWorld(&inWorld) {}
    void Write(std::span<const std::byte> inBytes);
    // WriteExtension(s): every payload checked, then their records in one write
    Status WriteExtensionRecords(std::uint32_t inTag, std::span<const std::span<const std::byte>> inPayloads);
    void RecordNewObjects();

    std::FILE* mFile = nullptr;
    std::filesystem::path mPath;
    DamageWorld* mWorld = nullptr;
    std::vector<std::uint32_t> mRecorded; ///< Per object slot: 1 + the generation whose setup is written, 0: none
    std::uint32_t mObjects = 0;
    std::uint64_t mCollisions = 0;
    Status mStatus;
};

} // namespace crumple::plugin
