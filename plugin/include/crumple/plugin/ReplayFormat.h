// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Result.h>
#include <crumple/plugin/Collision.h>
#include <crumple/plugin/DeformableObjectSettings.h>
#include <crumple/plugin/Ids.h>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace crumple::plugin
{

/// A deformable object as recorded: enough to rebuild it, including the damage it already had.
struct CRUMPLE_API RecordedObject
{
    ObjectId mObject;                          ///< Its id in the live world (index and generation)
    BodyId mBody;                              ///< The body it is attached to (a later body may reuse its index)
    std::uint64_t mFirstCollision = 0;         ///< Collisions recorded before it: only later ones can dent it
    DeformableObjectSettings mSettings;        ///< Mesh, material and the resolved zones (never empty)
    std::vector<std::vector<Vec3>> mInitialControls; ///< Control displacements when recording began (m)
};

/// A record a layer above the core wrote into the recording (DamageRecorder::WriteExtension): the core keeps
/// its bytes and where it stood among the collisions; the layer that wrote it reads it (crumple::props records
/// its props this way).
struct CRUMPLE_API RecordedExtension
{
    std::uint64_t mAfterCollisions = 0; ///< Collisions recorded before it
    std::uint32_t mTag = 0;             ///< The writer's record kind
    std::vector<std::byte> mPayload;    ///< The writer's bytes, CRC-checked like every record
};

/// A whole recording: objects and collisions, in the order the live world dispatched them.
struct CRUMPLE_API Replay
{
    std::vector<RecordedObject> mObjects;       ///< In the order they were recorded
    std::vector<Collision> mCollisions;         ///< In dispatch order
    std::vector<RecordedExtension> mExtensions; ///< In the order they were written
};

/// Replay file format version. Readers refuse other versions. 2: the material's impulse threshold.
/// 3: the deformer's minimum control spacing. 4: the deformer's direct-manipulation prior and control gain
/// bound. 5: the crush model (material: model, Campbell A, B, G, minimum width, crushed fraction; the up
/// axis; per contact the absorbed energy; per collision the crush energy of each side). 6: the deformer's
/// one-sided dents flag; extension records. 7: ids carry their generation (u32 after each object and body
/// index). 8: the deformer's rigid parts (after the object's control state: u32 parts, each u32 count and its
/// u32 vertices). 9: per contact the friction coefficient and the friction impulse (world, on A's body frame,
/// on B's body frame) after the time. 10: the material's crush zone fraction (f64 after the rigid parts). 11:
/// per collision, after the crush energies, the shape boxes of B on A and of A on B (each u8 known, the
/// centre and three half axes as f64 Vec3s).
/// 12: the material's side stiffness (u8 flag, then A, B and G as f64, after the crush zone fraction).
/// 13: the material's rear stiffness (u8 flag, then A, B and G as f64) and the object's forward axis (a f64
/// Vec3), after the side stiffness.
/// Written: 13. Read: 13 down to 7 (whose contacts are frictionless, objects have no rigid parts before 8,
/// no occupant cell (fraction 0.5) before 10, collisions no shape boxes before 11, materials no side
/// stiffness before 12 and no rear stiffness before 13, so their recordings still replay as they were made).
constexpr std::uint32_t cReplayVersion = 13;
/// The oldest version DecodeReplay still reads.
constexpr std::uint32_t cOldestReplayVersion = 7;

/// The replay file layout (little-endian, IEEE-754):
///   "CRUMPREC" magic, u32 version, then records: u8 type, u32 payload length, payload, u32 CRC-32 of the
///   payload. Types: 1 object, 2 collision, 3 end (u32 objects, u64 collisions), 4 extension (u32 tag, then
///   the writer's bytes). A file without its end record (a run that crashed, a truncated copy) is refused.
enum class EReplayRecord : std::uint8_t
{
    Object = 1,
    Collision = 2,
    End = 3,
    Extension = 4,
};

/// The file header (magic and version).
CRUMPLE_API std::vector<std::byte> EncodeReplayHeader();
/// One framed record.
CRUMPLE_API std::vector<std::byte> EncodeReplayRecord(EReplayRecord inType, std::span<const std::byte> inPayload);
CRUMPLE_API std::vector<std::byte> EncodeRecordedObject(const RecordedObject& inObject);
CRUMPLE_API std::vector<std::byte> EncodeCollision(const Collision& inCollision);

/// Parses and checks a whole replay file: magic, version, every record's CRC and length, the end record's
/// counts, and each collision's values (finite, unit normals, impulses and energies within their bounds).
/// Refused with a message naming the record on any problem. The objects' meshes, materials and lattices are
/// checked when they are built (CreateReplayedObjects, by DeformableObject::Create), not here.
CRUMPLE_API Result<Replay> DecodeReplay(std::span<const std::byte> inBytes);

} // namespace crumple::plugin
