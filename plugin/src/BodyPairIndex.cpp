// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "BodyPairIndex.h"

#include <crumple/base/Assert.h>
#include <crumple/base/MixBits64.h>

namespace crumple::plugin
{

void BodyPairIndex::Reset(std::size_t inPairs)
{
    // intent: at most half full, so a probe always meets an empty slot soon
    std::size_t capacity = 16;
    while (capacity < 2 * inPairs)
        capacity *= 2;
    mSlots.assign(capacity, Slot{});
    mMask = capacity - 1;
    mBound = inPairs;
    mHeld = 0;
}

std::size_t BodyPairIndex::SlotOf(BodyId inA, BodyId inB) const
{
    // intent: the four 32-bit words mixed into 64 bits (splitmix64's finaliser spreads the slot indices,
    // which are small and dense, over the table), then probed linearly to the pair or an empty slot
    std::size_t slot =
        static_cast<std::size_t>(
            MixBits64((std::uint64_t{inA.mValue} << 32 | inB.mValue) ^
                      (std::uint64_t{inA.mGeneration} << 32 | inB.mGeneration) * 0x9E3779B97F4A7C15ull)) &
        mMask;
    while (mSlots[slot].mValue != cNone && !(mSlots[slot].mA == inA && mSlots[slot].mB == inB))
        slot = (slot + 1) & mMask;
    return slot;
}

std::uint32_t BodyPairIndex::Find(BodyId inA, BodyId inB) const
{
    return mSlots.empty() ? cNone : mSlots[SlotOf(inA, inB)].mValue;
}

std::pair<std::uint32_t, bool> BodyPairIndex::TryInsert(BodyId inA, BodyId inB, std::uint32_t inValue)
{
    CRUMPLE_ASSERT(!mSlots.empty() && inValue != cNone, "BodyPairIndex: an insert before Reset, or of cNone");
    Slot& slot = mSlots[SlotOf(inA, inB)];
    if (slot.mValue != cNone)
        return {slot.mValue, false};
    CRUMPLE_ASSERT(mHeld < mBound, "BodyPairIndex: more pairs than its Reset was sized for");
    ++mHeld;
    slot = Slot{inA, inB, inValue};
    return {inValue, true};
}

} // namespace crumple::plugin
