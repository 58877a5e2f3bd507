// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/ByteReader.h>
#include <crumple/base/ByteWriter.h>
#include <crumple/base/Result.h>

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace crumple
{

/// A triangle mesh as bytes (u64 #V, #V Vec3, u64 #F, 3 #F u32), how a mesh parsed in a child process
/// (RunIsolated) comes back. Index is the mesh type's index (int or std::uint32_t), stored as u32.
template <class Index>
std::vector<std::byte> EncodeMeshBytes(std::span<const Vec3> inPositions, std::span<const std::array<Index, 3>> inTriangles)
{
    ByteWriter writer;
    writer.WriteU64(inPositions.size());
    for (const Vec3& position : inPositions)
        writer.WriteVec3(position);
    writer.WriteU64(inTriangles.size());
    for (const std::array<Index, 3>& triangle : inTriangles)
        for (Index index : triangle)
            writer.WriteU32(static_cast<std::uint32_t>(index));
    return writer.GetBytes();
}

/// Reads EncodeMeshBytes' layout back; EError::CorruptData (naming inWhat) when the counts do not match the
/// bytes. Indices are not checked against the positions: the mesh type's validation does that.
template <class Index>
Status DecodeMeshBytes(std::span<const std::byte> inBytes, const std::string& inWhat, std::vector<Vec3>& outPositions,
                       std::vector<std::array<Index, 3>>& outTriangles)
{
    ByteReader reader(inBytes);
    const std::uint64_t vertices = reader.ReadU64();
    if (reader.Failed() || vertices > reader.Remaining() / 24)
        return MakeError(EError::CorruptData, inWhat + ": the isolated reader's mesh is truncated");
    outPositions.resize(static_cast<std::size_t>(vertices));
    for (Vec3& position : outPositions)
        position = reader.ReadVec3();
    const std::uint64_t triangles = reader.ReadU64();
    if (reader.Failed() || reader.Remaining() % 12 != 0 || triangles != reader.Remaining() / 12)
        return MakeError(EError::CorruptData, inWhat + ": the isolated reader's mesh is truncated");
    outTriangles.resize(static_cast<std::size_t>(triangles));
    for (std::array<Index, 3>& triangle : outTriangles)
        for (Index& index : triangle)
            index = static_cast<Index>(reader.ReadU32());
    return Status::Ok();
}

} // namespace crumple
