// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Math.h>
#include <crumple/base/Result.h>

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

namespace crumple
{

/// Reads what ByteWriter wrote. Every read checks the remaining length; after the first failure all
/// reads fail and Failed() is true, so a parser can read a whole record and check once.
class CRUMPLE_API ByteReader
{
public:
    explicit ByteReader(std::span<const std::byte> inBytes) : mBytes(inBytes) {}

    /// Checks that the last 4 bytes are the CRC-32 of all bytes before them, and hides them from reads.
    Status VerifyAndStripChecksum();

    std::uint8_t ReadU8();
    std::uint32_t ReadU32();
    std::uint64_t ReadU64();
    double ReadDouble();
    Vec3 ReadVec3();
    bool ReadTag(std::string_view inTag); ///< True when the next bytes equal inTag
    void Skip(std::size_t inCount);       ///< Moves past inCount bytes (fails when fewer remain)

    bool Failed() const { return mFailed; }
    std::size_t Remaining() const { return mBytes.size() - mOffset; }

private:
    bool Take(std::size_t inCount, const std::byte*& outData);

    std::span<const std::byte> mBytes;
    std::size_t mOffset = 0;
    bool mFailed = false;
};

} // namespace crumple
