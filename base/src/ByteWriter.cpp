// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/base/ByteWriter.h>
#include <crumple/base/Crc32.h>

#include <bit>

namespace crumple
{

void ByteWriter::WriteU8(std::uint8_t inValue)
{
    mBytes.push_back(static_cast<std::byte>(inValue));
}

void ByteWriter::WriteU32(std::uint32_t inValue)
{
    // Little-endian byte by byte: the file is the same on any host. Grown once, not by four push_backs
    // (a recording writes every contact's and every loose piece's fields through here).
    std::byte* const out = Grow(4);
    for (int i = 0; i < 4; ++i)
        out[i] = static_cast<std::byte>((inValue >> (8 * i)) & 0xFFu);
}

void ByteWriter::WriteU64(std::uint64_t inValue)
{
    std::byte* const out = Grow(8);
    for (int i = 0; i < 8; ++i)
        out[i] = static_cast<std::byte>((inValue >> (8 * i)) & 0xFFu);
}

void ByteWriter::WriteDouble(double inValue)
{
    WriteU64(std::bit_cast<std::uint64_t>(inValue));
}

void ByteWriter::WriteVec3(const Vec3& inValue)
{
    for (int i = 0; i < 3; ++i)
        WriteDouble(inValue[i]);
}

void ByteWriter::WriteBytes(std::span<const std::byte> inBytes)
{
    mBytes.insert(mBytes.end(), inBytes.begin(), inBytes.end());
}

void ByteWriter::WriteTag(std::string_view inTag)
{
    for (char c : inTag)
        mBytes.push_back(static_cast<std::byte>(c));
}

void ByteWriter::Reserve(std::size_t inBytes)
{
    mBytes.reserve(mBytes.size() + inBytes);
}

std::byte* ByteWriter::Grow(std::size_t inBytes)
{
    const std::size_t at = mBytes.size();
    mBytes.resize(at + inBytes);
    return mBytes.data() + at;
}

void ByteWriter::WriteChecksum()
{
    WriteU32(Crc32(mBytes));
}

} // namespace crumple
