// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <compare>
#include <cstdint>

namespace crumple::plugin
{

/// Stable handle of a rigid body registered with a DamageWorld. Ids are handed out in creation order and
/// never reused, so ordering by id is deterministic across runs (unlike ordering by pointer).
struct BodyId
{
    static constexpr std::uint32_t cInvalid = 0xFFFFFFFFu;
    std::uint32_t mValue = cInvalid; ///< Index in creation order

    bool IsValid() const { return mValue != cInvalid; }
    auto operator<=>(const BodyId&) const = default;
};

/// Stable handle of a DeformableObject in a DamageWorld, in creation order.
struct ObjectId
{
    static constexpr std::uint32_t cInvalid = 0xFFFFFFFFu;
    std::uint32_t mValue = cInvalid; ///< Index in creation order

    bool IsValid() const { return mValue != cInvalid; }
    auto operator<=>(const ObjectId&) const = default;
};

} // namespace crumple::plugin
