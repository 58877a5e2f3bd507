// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "ContactBatches.h"

#include "BodyPairIndex.h"

#include <crumple/plugin/SurfaceContactPoints.h>

#include <cmath>

namespace crumple::plugin
{

OrientedContact CanonicalContact(const ContactEvent& inEvent)
{
    const SurfacePoints surface = SurfaceContactPoints(inEvent);
    const bool flip = inEvent.mBodyB < inEvent.mBodyA;
    OrientedContact oriented{
        flip ? inEvent.mBodyB : inEvent.mBodyA, flip ? inEvent.mBodyA : inEvent.mBodyB, {}};
    CollisionContact& contact = oriented.mContact;
    contact.mNormal = (flip ? -inEvent.mNormal : inEvent.mNormal).normalized();
    contact.mPointOnA = flip ? surface.mOnB : surface.mOnA;
    contact.mPointOnB = flip ? surface.mOnA : surface.mOnB;
    contact.mPenetrationDepth = inEvent.mPenetrationDepth;
    contact.mFriction = inEvent.mFriction;
    contact.mTime = inEvent.mTime;
    return oriented;
}

std::vector<ContactBatch> GroupContactBatches(std::span<const ContactEvent> inContacts, double inSameStepTime)
{
    constexpr std::uint32_t cNone = BodyPairIndex::cNone;
    std::vector<ContactBatch> batches;
    // intent: each pair's batches as a chain in order of creation (first batch in the index, the next one of
    // the same pair in next_of_pair), so a contact joins the batch a scan of all batches would find first
    BodyPairIndex first_of_pair;
    first_of_pair.Reset(inContacts.size());
    std::vector<std::uint32_t> next_of_pair;
    for (const ContactEvent& event : inContacts)
    {
        const auto [a, b, contact] = CanonicalContact(event);
        // intent: one engine step's contacts of a pair are one batch even when their times differ by
        // round-off (a game that computes each contact's time): solved apart, each would take the pair's
        // whole impulse
        const auto [first, is_new_pair] =
            first_of_pair.TryInsert(a, b, static_cast<std::uint32_t>(batches.size()));
        std::uint32_t index = first, last = cNone;
        if (!is_new_pair)
            for (; index != cNone; last = index, index = next_of_pair[index])
                if (std::abs(batches[index].mTime - event.mTime) <= inSameStepTime)
                    break;
        if (is_new_pair || index == cNone)
        {
            index = static_cast<std::uint32_t>(batches.size());
            batches.push_back(ContactBatch{a, b, event.mTime, {}});
            next_of_pair.push_back(cNone);
            if (last != cNone)
                next_of_pair[last] = index;
        }
        batches[index].mContacts.push_back(contact);
    }
    return batches;
}

} // namespace crumple::plugin
