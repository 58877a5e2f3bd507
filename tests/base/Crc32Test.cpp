// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/base/Crc32.h>

#include <catch2/catch.hpp>

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
