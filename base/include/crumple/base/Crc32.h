// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <cstddef>
#include <cstdint>
#include <span>

namespace crumple
{

/// CRC-32 (IEEE 802.3, reflected polynomial 0xEDB88320, as zlib's crc32) of a byte range.
/// @param[in] inBytes  the data
/// @param[in] inSeed   the CRC of the preceding bytes, to continue a running checksum (0 to start)
CRUMPLE_API std::uint32_t Crc32(std::span<const std::byte> inBytes, std::uint32_t inSeed = 0);

} // namespace crumple
