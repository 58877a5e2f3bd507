// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <compare>
#include <cstdint>

namespace crumple::plugin
{

/// Handle of a rigid body registered with a DamageWorld: a slot index and the slot's generation (as Box2D's
/// ids). A removed body's slot is reused by a later body with the next generation, so a session that keeps
/// spawning and removing debris holds only as many slots as bodies live at once, and the removed body's id
/// (same index, older generation) is refused everywhere. The world hands out the same ids for the same
/// sequence of calls, so ordering by id (index, then generation) is deterministic across runs (unlike
/// ordering by pointer).
struct CRUMPLE_API BodyId
{
    static constexpr std::uint32_t cInvalid = 0xFFFFFFFFu;
    std::uint32_t mValue = cInvalid; ///< Slot index
    std::uint32_t mGeneration = 0;   ///< How many bodies held the slot before this one

    bool IsValid() const { return mValue != cInvalid; }
    auto operator<=>(const BodyId&) const = default;
};

/// Handle of a DeformableObject in a DamageWorld: a slot index and generation, reused as BodyId's.
struct CRUMPLE_API ObjectId
{
    static constexpr std::uint32_t cInvalid = 0xFFFFFFFFu;
    std::uint32_t mValue = cInvalid; ///< Slot index
    std::uint32_t mGeneration = 0;   ///< How many objects held the slot before this one

    bool IsValid() const { return mValue != cInvalid; }
    auto operator<=>(const ObjectId&) const = default;
};

} // namespace crumple::plugin
