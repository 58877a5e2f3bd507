// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/base/Crc32.h>

#include <array>

namespace crumple
{

namespace
{

using CrcTables = std::array<std::array<std::uint32_t, 256>, 8>;

// Slice-by-8 tables, built at compile time (no mutable global state): table 0 is the classic byte table,
// table k advances a byte's contribution by k more zero bytes, so eight bytes fold in one step.
constexpr CrcTables MakeCrcTables()
{
    CrcTables tables{};
    for (std::uint32_t i = 0; i < 256; ++i)
    {
        std::uint32_t c = i;
        for (int bit = 0; bit < 8; ++bit)
            c = (c & 1u) != 0 ? 0xEDB88320u ^ (c >> 1) : c >> 1;
        tables[0][i] = c;
    }
    for (std::size_t k = 1; k < 8; ++k)
        for (std::uint32_t i = 0; i < 256; ++i)
            tables[k][i] = (tables[k - 1][i] >> 8) ^ tables[0][tables[k - 1][i] & 0xFFu];
    return tables;
}

constexpr CrcTables cCrcTables = MakeCrcTables();

} // namespace

std::uint32_t Crc32(std::span<const std::byte> inBytes, std::uint32_t inSeed)
{
    std::uint32_t crc = ~inSeed;
    const std::byte* p = inBytes.data();
    std::size_t left = inBytes.size();
    // intent: eight bytes per step (byte order fixed here, so the result does not depend on the host's)
    auto byte = [&](std::size_t inIndex) { return static_cast<std::uint32_t>(p[inIndex]); };
    for (; left >= 8; p += 8, left -= 8)
    {
        const std::uint32_t low = crc ^ (byte(0) | byte(1) << 8 | byte(2) << 16 | byte(3) << 24);
        crc = cCrcTables[7][low & 0xFFu] ^ cCrcTables[6][(low >> 8) & 0xFFu] ^ cCrcTables[5][(low >> 16) & 0xFFu] ^
              cCrcTables[4][low >> 24] ^ cCrcTables[3][byte(4)] ^ cCrcTables[2][byte(5)] ^ cCrcTables[1][byte(6)] ^
              cCrcTables[0][byte(7)];
    }
    for (; left > 0; ++p, --left)
        crc = cCrcTables[0][(crc ^ byte(0)) & 0xFFu] ^ (crc >> 8);
    return ~crc;
}

} // namespace crumple
