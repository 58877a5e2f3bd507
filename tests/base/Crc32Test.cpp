// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/base/Crc32.h>

#include <catch2/catch.hpp>

#include <span>
#include <string_view>
#include <vector>

namespace
{

std::vector<std::byte> Bytes(std::string_view inText)
{
    std::vector<std::byte> bytes;
    for (char c : inText)
        bytes.push_back(static_cast<std::byte>(c));
    return bytes;
}

} // namespace

TEST_CASE("Crc32 matches the standard check value", "[base]")
{
    // The CRC-32/ISO-HDLC check value of "123456789" (zlib's crc32).
    CHECK(crumple::Crc32(Bytes("123456789")) == 0xCBF43926u);
    CHECK(crumple::Crc32(Bytes("")) == 0u);
}

TEST_CASE("Crc32 can be computed in pieces", "[base]")
{
    const std::vector<std::byte> all = Bytes("The quick brown fox jumps over the lazy dog");
    const std::span<const std::byte> bytes(all);
    const std::uint32_t running = crumple::Crc32(bytes.subspan(10), crumple::Crc32(bytes.first(10)));
    CHECK(running == crumple::Crc32(bytes));
    CHECK(running == 0x414FA339u);
}

TEST_CASE("Crc32 eight bytes at a time equals the bit-by-bit definition at every length and offset", "[base]")
{
    // The reflected polynomial 0xEDB88320 applied one bit at a time: an independent computation.
    auto bitwise = [](std::span<const std::byte> inBytes) {
        std::uint32_t crc = 0xFFFFFFFFu;
        for (std::byte b : inBytes)
        {
            crc ^= static_cast<std::uint32_t>(b);
            for (int bit = 0; bit < 8; ++bit)
                crc = (crc & 1u) != 0 ? 0xEDB88320u ^ (crc >> 1) : crc >> 1;
        }
        return ~crc;
    };
    std::vector<std::byte> bytes(300);
    std::uint32_t state = 12345u;
    for (std::byte& b : bytes)
    {
        state = state * 1664525u + 1013904223u;
        b = static_cast<std::byte>(state >> 24);
    }
    const std::span<const std::byte> all(bytes);
    for (std::size_t offset = 0; offset < 9; ++offset)
        for (std::size_t length = 0; length + offset <= 80; ++length)
            CHECK(crumple::Crc32(all.subspan(offset, length)) == bitwise(all.subspan(offset, length)));
    CHECK(crumple::Crc32(all) == bitwise(all));
}
