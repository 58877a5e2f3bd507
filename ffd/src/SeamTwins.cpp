// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "SeamTwins.h"

#include <crumple/base/MixBits64.h>

#include <array>
#include <bit>
#include <cstring>

namespace crumple::ffd
{

namespace
{

// A position's bits, with -0.0 read as 0.0 so that positions equal by == have equal keys.
using PositionKey = std::array<std::uint64_t, 3>;

PositionKey KeyOf(const Vec3& inPosition)
{
    PositionKey key;
    for (int axis = 0; axis < 3; ++axis)
    {
        const double value = inPosition[axis] == 0.0 ? 0.0 : inPosition[axis];
        std::memcpy(&key[static_cast<std::size_t>(axis)], &value, sizeof(double));
    }
    return key;
}

struct PositionKeyHash
{
    std::size_t operator()(const PositionKey& inKey) const
    {
        // intent: mix the three words (splitmix64's finalizer), so grid-aligned coordinates spread
        return static_cast<std::size_t>(
            MixBits64(inKey[0] * 0x9E3779B97F4A7C15ull ^ std::rotl(inKey[1], 21) ^ std::rotl(inKey[2], 42)));
    }
};

} // namespace

std::vector<std::uint32_t> SeamTwins(const std::vector<Vec3>& inPositions)
{
    // intent: in index order, each vertex takes the first index seen at its position, the lowest: an
    // open-addressed table of vertex indices (linear probing, at most half full) instead of a sort by
    // position, the same answer in linear time with one allocation (it runs once per flip or split pass)
    constexpr std::uint32_t cEmpty = 0xFFFFFFFFu;
    std::size_t capacity = 16;
    while (capacity < 2 * inPositions.size())
        capacity *= 2;
    std::vector<std::uint32_t> table(capacity, cEmpty);
    std::vector<PositionKey> keys(inPositions.size());
    std::vector<std::uint32_t> twin(inPositions.size());
    const PositionKeyHash hash;
    for (std::size_t v = 0; v < inPositions.size(); ++v)
    {
        keys[v] = KeyOf(inPositions[v]);
        std::size_t slot = hash(keys[v]) & (capacity - 1);
        while (table[slot] != cEmpty && keys[table[slot]] != keys[v])
            slot = (slot + 1) & (capacity - 1);
        if (table[slot] == cEmpty)
            table[slot] = static_cast<std::uint32_t>(v);
        twin[v] = table[slot];
    }
    return twin;
}

} // namespace crumple::ffd
