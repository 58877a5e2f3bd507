// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Math.h>
#include <crumple/base/Result.h>
#include <crumple/plugin/Ids.h>

#include <cstddef>
#include <span>
#include <vector>

namespace crumple::plugin
{

/// The damage of one object: its FFD control displacements, one vector per zone (body frame, m).
struct CRUMPLE_API ObjectDamage
{
    ObjectId mObject;                          ///< Which object: its slot index (saved and matched; not its generation)
    std::vector<std::vector<Vec3>> mZones;     ///< Per zone, per control (FfdLattice::ControlIndex order)
};

/// The damage of a whole world: everything needed to rebuild every deformed mesh from the rest meshes.
struct CRUMPLE_API DamageState
{
    std::vector<ObjectDamage> mObjects; ///< In ObjectId order
};

/// Current damage file format version. Readers refuse other versions. 2: controls that reach no vertex are
/// zero (version 1 files could hold values there).
constexpr std::uint32_t cDamageStateVersion = 2;

/// Encodes a damage state: "CRUMPLED" magic, u32 version, u32 object count, then per object u32 id,
/// u32 zone count, per zone u32 control count and 3 doubles per control; all little-endian, IEEE-754;
/// a CRC-32 of everything before it closes the file.
CRUMPLE_API std::vector<std::byte> EncodeDamageState(const DamageState& inState);

/// Decodes and checks a damage state (magic, version, checksum, lengths, finite values). A truncated or
/// corrupt buffer is refused with EError::CorruptData, another version with EError::VersionMismatch.
CRUMPLE_API Result<DamageState> DecodeDamageState(std::span<const std::byte> inBytes);

} // namespace crumple::plugin
