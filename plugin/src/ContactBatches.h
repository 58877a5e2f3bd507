// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

// One engine step's contacts of a body pair, grouped for the joint impulse solve. Private to the plugin.

#include <crumple/plugin/Collision.h>
#include <crumple/plugin/ContactEvent.h>
#include <crumple/plugin/Ids.h>

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace crumple::plugin
{

/// The contacts of one body pair at one time, A the lower id.
struct ContactBatch
{
    BodyId mA, mB;
    double mTime = 0.0; ///< The first contact's time (s)
    std::vector<CollisionContact>
        mContacts; ///< In arrival order, normals from B to A, points on the surfaces
};

/// Groups inContacts into batches: each contact turned to the canonical orientation (A = lower id), moved
/// onto the bodies' surfaces (SurfaceContactPoints), and added to the first batch, in order of creation, of
/// its pair whose time is within inSameStepTime of its own, or to a new one. The batches come in the order of
/// their first contacts. A pair's batches are found through an index (hash of the pair), not by scanning
/// every batch: a brick wall bursting reports hundreds of pairs in one step.
std::vector<ContactBatch> GroupContactBatches(std::span<const ContactEvent> inContacts,
                                              double inSameStepTime);

/// Body pairs to small integers (a batch's or an impact memory's index) in one flat table (open addressing,
/// linear probing): built per engine step with one allocation, not one per pair as a node-based map makes.
class BodyPairIndex
{
  public:
    static constexpr std::uint32_t cNone = 0xFFFFFFFFu;

    /// Empties the index, sized for up to inPairs pairs (at most half full).
    void Reset(std::size_t inPairs);
    /// The value stored for the pair (A, B), or cNone.
    std::uint32_t Find(BodyId inA, BodyId inB) const;
    /// Stores inValue for (A, B) unless the pair has a value; returns the pair's value and whether it is new.
    /// At most the Reset's inPairs pairs.
    std::pair<std::uint32_t, bool> TryInsert(BodyId inA, BodyId inB, std::uint32_t inValue);

  private:
    struct Slot
    {
        BodyId mA, mB;
        std::uint32_t mValue = cNone; // cNone: empty
    };
    std::size_t SlotOf(BodyId inA, BodyId inB) const;

    std::vector<Slot> mSlots;
    std::size_t mMask = 0;
};

} // namespace crumple::plugin
