// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Math.h>

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace crumple
{

/// Appends little-endian integers and IEEE-754 doubles to a byte buffer, so that saved files are the
/// same bytes on every platform.
class CRUMPLE_API ByteWriter
{
public:
    void WriteU8(std::uint8_t inValue);
    void WriteU32(std::uint32_t inValue);
    void WriteU64(std::uint64_t inValue);
    void WriteDouble(double inValue);
    void WriteVec3(const Vec3& inValue);
    void WriteBytes(std::span<const std::byte> inBytes);
    void WriteTag(std::string_view inTag); ///< Raw ASCII, no length prefix (magic numbers)
    /// Room for inBytes more bytes, for a writer that knows its record's size (no reallocation while writing)
    void Reserve(std::size_t inBytes);

    /// Appends the CRC-32 of everything written so far.
    void WriteChecksum();

    const std::vector<std::byte>& GetBytes() const { return mBytes; }
    std::vector<std::byte>&& TakeBytes() { return std::move(mBytes); }

private:
    // inBytes more bytes at the end (zeroed), returned for writing
    std::byte* Grow(std::size_t inBytes);

    std::vector<std::byte> mBytes;
};

} // namespace crumple
