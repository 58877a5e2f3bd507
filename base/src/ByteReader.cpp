// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/base/ByteReader.h>
#include <crumple/base/ChecksumPolicy.h>
#include <crumple/base/Crc32.h>

#include <bit>
#include <string>

namespace crumple
{

Status ByteReader::VerifyAndStripChecksum()
{
    if (mBytes.size() < 4)
        return MakeError(EError::CorruptData, "data is truncated: " + std::to_string(mBytes.size()) +
                                                  " bytes cannot hold a checksum");
    const std::span<const std::byte> body = mBytes.first(mBytes.size() - 4);
    ByteReader tail(mBytes.last(4));
    const std::uint32_t stored = tail.ReadU32();
    if (cVerifyChecksums && Crc32(body) != stored)
        return MakeError(EError::CorruptData, "checksum mismatch: the data is corrupt or truncated");
    mBytes = body;
    return Status::Ok();
}

bool ByteReader::Take(std::size_t inCount, const std::byte*& outData)
{
    if (mFailed || Remaining() < inCount)
    {
        mFailed = true;
        return false;
    }
    outData = mBytes.data() + mOffset;
    mOffset += inCount;
    return true;
}

std::uint8_t ByteReader::ReadU8()
{
    const std::byte* data = nullptr;
    return Take(1, data) ? static_cast<std::uint8_t>(data[0]) : 0;
}

std::uint32_t ByteReader::ReadU32()
{
    const std::byte* data = nullptr;
    if (!Take(4, data))
        return 0;
    std::uint32_t value = 0;
    for (int i = 0; i < 4; ++i)
        value |= static_cast<std::uint32_t>(data[i]) << (8 * i);
    return value;
}

std::uint64_t ByteReader::ReadU64()
{
    const std::byte* data = nullptr;
    if (!Take(8, data))
        return 0;
    std::uint64_t value = 0;
    for (int i = 0; i < 8; ++i)
        value |= static_cast<std::uint64_t>(data[i]) << (8 * i);
    return value;
}

double ByteReader::ReadDouble()
{
    return std::bit_cast<double>(ReadU64());
}

Vec3 ByteReader::ReadVec3()
{
    Vec3 v;
    for (int i = 0; i < 3; ++i)
        v[i] = ReadDouble();
    return v;
}

void ByteReader::Skip(std::size_t inCount)
{
    const std::byte* data = nullptr;
    (void)Take(inCount, data);
}

bool ByteReader::ReadTag(std::string_view inTag)
{
    const std::byte* data = nullptr;
    if (!Take(inTag.size(), data))
        return false;
    for (std::size_t i = 0; i < inTag.size(); ++i)
        if (static_cast<char>(data[i]) != inTag[i])
            return false;
    return true;
}

} // namespace crumple
