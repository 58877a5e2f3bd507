// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

// Body pairs to small integers, for one engine step's solve. Private to the plugin.

#include <crumple/plugin/Ids.h>

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace crumple::plugin
{

/// Body pairs (A, B), ordered, to small integers (a batch's or an impact memory's index) in one flat table:
/// open addressing, linear probing, at most half full. Made for each SolveContacts call with one allocation,
/// not one per pair as a node-based map makes (that cost the racing sessions' median frame about 0.05 ms).
class BodyPairIndex
{
  public:
    /// What Find answers for a pair it does not hold; not a value TryInsert takes.
    static constexpr std::uint32_t cNone = 0xFFFFFFFFu;

    /// Empties the index, sized for up to inPairs pairs.
    void Reset(std::size_t inPairs);
    /// The value stored for the pair (A, B), or cNone (also before the first Reset).
    std::uint32_t Find(BodyId inA, BodyId inB) const;
    /// Stores inValue (not cNone) for (A, B) unless the pair has a value; returns the pair's value and
    /// whether it is new. Asserts that the pairs stay within the Reset's inPairs.
    std::pair<std::uint32_t, bool> TryInsert(BodyId inA, BodyId inB, std::uint32_t inValue);

  private:
    struct Slot
    {
        BodyId mA; ///< The pair held, where mValue is not cNone
        BodyId mB;
        std::uint32_t mValue = cNone; ///< cNone: an empty slot
    };
    /// The slot that holds (A, B), or the empty one where it would go
    std::size_t SlotOf(BodyId inA, BodyId inB) const;

    std::vector<Slot> mSlots;
    std::size_t mMask = 0;  ///< mSlots.size() - 1 (a power of two minus one)
    std::size_t mBound = 0; ///< The Reset's inPairs
    std::size_t mHeld = 0;  ///< Pairs inserted since the Reset
};

} // namespace crumple::plugin
