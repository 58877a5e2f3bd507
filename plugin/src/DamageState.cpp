// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/base/ByteReader.h>
#include <crumple/base/ByteWriter.h>
#include <crumple/plugin/DamageState.h>

#include <string>

namespace crumple::plugin
{

namespace
{

constexpr std::string_view cMagic = "CRUMPLED";

} // namespace

std::vector<std::byte> EncodeDamageState(const DamageState& inState)
{
    ByteWriter writer;
    writer.WriteTag(cMagic);
    writer.WriteU32(cDamageStateVersion);
    writer.WriteU32(static_cast<std::uint32_t>(inState.mObjects.size()));
    for (const ObjectDamage& object : inState.mObjects)
    {
        writer.WriteU32(object.mObject.mValue);
        writer.WriteU32(static_cast<std::uint32_t>(object.mZones.size()));
        for (const std::vector<Vec3>& zone : object.mZones)
        {
            writer.WriteU32(static_cast<std::uint32_t>(zone.size()));
            for (const Vec3& d : zone)
                writer.WriteVec3(d);
        }
    }
    writer.WriteChecksum();
    return writer.TakeBytes();
}

Result<DamageState> DecodeDamageState(std::span<const std::byte> inBytes)
{
    ByteReader reader(inBytes);
    // Magic and version first, so a foreign or newer file gets the right message.
    if (!reader.ReadTag(cMagic))
        return MakeError(EError::CorruptData, "not a Crumple damage state (bad magic)");
    const std::uint32_t version = reader.ReadU32();
    if (reader.Failed())
        return MakeError(EError::CorruptData, "damage state is truncated in its header");
    if (version != cDamageStateVersion)
        return MakeError(EError::VersionMismatch, "damage state version " + std::to_string(version) +
                                                      ", this library reads version " +
                                                      std::to_string(cDamageStateVersion));
    ByteReader body(inBytes);
    if (Status checksum = body.VerifyAndStripChecksum(); !checksum)
        return checksum.GetError();
    body.ReadTag(cMagic);
    body.ReadU32();

    DamageState state;
    const std::uint32_t object_count = body.ReadU32();
    // Each count is checked against the bytes left, so a corrupt count cannot allocate gigabytes.
    if (body.Failed() || object_count > body.Remaining() / 8)
        return MakeError(EError::CorruptData, "damage state object count is corrupt");
    for (std::uint32_t o = 0; o < object_count; ++o)
    {
        ObjectDamage object;
        object.mObject.mValue = body.ReadU32();
        const std::uint32_t zone_count = body.ReadU32();
        if (body.Failed() || zone_count > body.Remaining() / 4)
            return MakeError(EError::CorruptData, "damage state is truncated at object " + std::to_string(o));
        object.mZones.resize(zone_count);
        for (std::vector<Vec3>& zone : object.mZones)
        {
            const std::uint32_t control_count = body.ReadU32();
            if (body.Failed() || control_count > body.Remaining() / 24)
                return MakeError(EError::CorruptData, "damage state is truncated at object " + std::to_string(o));
            zone.resize(control_count);
            for (Vec3& d : zone)
            {
                d = body.ReadVec3();
                if (!IsFinite(d))
                    return MakeError(EError::CorruptData, "damage state holds a non-finite displacement");
            }
        }
        state.mObjects.push_back(std::move(object));
    }
    if (body.Failed() || body.Remaining() != 0)
        return MakeError(EError::CorruptData, "damage state length does not match its contents");
    return state;
}

} // namespace crumple::plugin
