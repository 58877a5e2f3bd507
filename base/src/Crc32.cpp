// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/base/Crc32.h>

#include <array>

namespace crumple
{

namespace
{

// The 256-entry table, built at compile time (no mutable global state).
constexpr std::array<std::uint32_t, 256> MakeCrcTable()
{
    std::array<std::uint32_t, 256> table{};
    for (std::uint32_t i = 0; i < 256; ++i)
    {
        std::uint32_t c = i;
        for (int bit = 0; bit < 8; ++bit)
            c = (c & 1u) != 0 ? 0xEDB88320u ^ (c >> 1) : c >> 1;
        table[i] = c;
    }
    return table;
}

constexpr std::array<std::uint32_t, 256> cCrcTable = MakeCrcTable();

} // namespace

std::uint32_t Crc32(std::span<const std::byte> inBytes, std::uint32_t inSeed)
{
    std::uint32_t crc = ~inSeed;
    for (std::byte b : inBytes)
        crc = cCrcTable[(crc ^ static_cast<std::uint32_t>(b)) & 0xFFu] ^ (crc >> 8);
    return ~crc;
}

} // namespace crumple
