// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>

namespace crumple
{

/// SplitMix64's finaliser (Steele, Lea and Flood, OOPSLA 2014; Vigna's splitmix64.c): 64 bits mixed so that
/// every input bit reaches every output bit. The output step of fem::SplitMix64, and the hash of the tables
/// keyed by small dense integers (ffd::SeamTwins' positions, the plugin's body pairs), which it spreads over
/// the table.
constexpr std::uint64_t MixBits64(std::uint64_t inBits)
{
    inBits = (inBits ^ (inBits >> 30)) * 0xBF58476D1CE4E5B9ull;
    inBits = (inBits ^ (inBits >> 27)) * 0x94D049BB133111EBull;
    return inBits ^ (inBits >> 31);
}

} // namespace crumple
