// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// GroupContactBatches: a step's contacts group into the batches a scan of every batch makes (DamageWorld's
// grouping before the index), in the same order, with the same contacts.
#include "ContactBatches.h"
#include "DrawVec3.h"
#include "SameBytes.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>

using namespace crumple;
using namespace crumple::plugin;
using namespace crumple::common;

namespace
{

// The grouping as DamageWorld did it before the index: each contact (oriented as the grouping does it) scans
// every batch made so far for the first one of its pair within inSameStepTime of its time.
std::vector<ContactBatch> GroupByScan(std::span<const ContactEvent> inContacts, double inSameStepTime)
{
    std::vector<ContactBatch> batches;
    for (const ContactEvent& event : inContacts)
    {
        const auto [a, b, contact] = CanonicalContact(event);
        auto batch = std::find_if(batches.begin(), batches.end(),
                                  [&](const ContactBatch& x) {
                                      return x.mA == a && x.mB == b &&
                                             std::abs(x.mTime - event.mTime) <= inSameStepTime;
                                  });
        if (batch == batches.end())
            batch = batches.insert(batches.end(), ContactBatch{a, b, event.mTime, {}});
        batch->mContacts.push_back(contact);
    }
    return batches;
}

} // namespace

TEST_CASE("A step's contacts group into the batches a scan of every batch makes", "[plugin][burst]")
{
    // Six bodies named either way round, step times round-off apart from another (within the same-step
    // tolerance), just outside it, and one within it of two batches of its pair (2.0 and 2.0 + 1.5e-9 are
    // two batches; 2.0 + 0.75e-9 joins the first made), contacts of a pair interleaved with other pairs'.
    std::mt19937 random(11);
    std::uniform_int_distribution<int> body(0, 5), time(0, 6);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const double times[] = {1.0, 1.0 + 1.0e-12, 2.0, 2.0 + 0.5e-9, 2.0 + 3.0e-9, 2.0 + 1.5e-9, 2.0 + 0.75e-9};
    for (int set = 0; set < 20; ++set)
    {
        std::vector<ContactEvent> contacts;
        for (int i = 0; i < 200; ++i)
        {
            ContactEvent contact;
            const int a = body(random);
            int b = body(random);
            if (b == a)
                b = (a + 1) % 6;
            contact.mBodyA = BodyId{static_cast<std::uint32_t>(a), static_cast<std::uint32_t>(a % 2)};
            contact.mBodyB = BodyId{static_cast<std::uint32_t>(b), static_cast<std::uint32_t>(b % 2)};
            contact.mPointOnA = DrawVec3([&] { return unit(random); });
            contact.mPointOnB = DrawVec3([&] { return unit(random); });
            contact.mNormal = DrawVec3([&] { return unit(random); }).normalized();
            contact.mPenetrationDepth = 0.01 * unit(random);
            contact.mFriction = 0.5;
            contact.mTime = times[time(random)];
            contacts.push_back(contact);
        }
        const std::vector<ContactBatch> indexed = GroupContactBatches(contacts, 1.0e-9);
        const std::vector<ContactBatch> scanned = GroupByScan(contacts, 1.0e-9);
        INFO("set " << set);
        REQUIRE(indexed.size() == scanned.size());
        // intent: the sets do exercise several batches of one pair (different steps)
        CHECK(indexed.size() > 30u);
        for (std::size_t b = 0; b < indexed.size(); ++b)
        {
            CHECK(indexed[b].mA == scanned[b].mA);
            CHECK(indexed[b].mB == scanned[b].mB);
            CHECK(indexed[b].mTime == scanned[b].mTime);
            REQUIRE(indexed[b].mContacts.size() == scanned[b].mContacts.size());
            for (std::size_t c = 0; c < indexed[b].mContacts.size(); ++c)
                CHECK(SameContact(indexed[b].mContacts[c], scanned[b].mContacts[c]));
        }
    }
}
