// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// One engine step of hundreds of body pairs (a brick wall bursting): the contacts group into the same batches
// as a scan of every batch would make, and the pairs' impulses, solved inline or split over the host's
// workers, are the same bits whatever the number of workers, over two steps (the second continues from the
// impact memories the first left).
#include "BrickBurst.h"
#include "ContactBatches.h"
#include "DrawVec3.h"
#include "ThreadJobSystem.h"

#include <crumple/plugin/SurfaceContactPoints.h>

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

// The grouping as DamageWorld did it before the index: each contact scans every batch made so far for the
// first one of its pair within inSameStepTime of its time.
std::vector<ContactBatch> GroupByScan(std::span<const ContactEvent> inContacts, double inSameStepTime)
{
    std::vector<ContactBatch> batches;
    for (const ContactEvent& event : inContacts)
    {
        const SurfacePoints surface = SurfaceContactPoints(event);
        const bool flip = event.mBodyB < event.mBodyA;
        CollisionContact contact;
        contact.mNormal = (flip ? -event.mNormal : event.mNormal).normalized();
        contact.mPointOnA = flip ? surface.mOnB : surface.mOnA;
        contact.mPointOnB = flip ? surface.mOnA : surface.mOnB;
        contact.mPenetrationDepth = event.mPenetrationDepth;
        contact.mFriction = event.mFriction;
        contact.mTime = event.mTime;
        const BodyId a = flip ? event.mBodyB : event.mBodyA;
        const BodyId b = flip ? event.mBodyA : event.mBodyB;
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

bool SameContact(const CollisionContact& inA, const CollisionContact& inB)
{
    return std::memcmp(inA.mPointOnA.data(), inB.mPointOnA.data(), sizeof(Vec3)) == 0 &&
           std::memcmp(inA.mPointOnB.data(), inB.mPointOnB.data(), sizeof(Vec3)) == 0 &&
           std::memcmp(inA.mNormal.data(), inB.mNormal.data(), sizeof(Vec3)) == 0 &&
           std::memcmp(inA.mFrictionImpulse.data(), inB.mFrictionImpulse.data(), sizeof(Vec3)) == 0 &&
           std::memcmp(&inA.mImpulse, &inB.mImpulse, sizeof(double)) == 0 &&
           std::memcmp(&inA.mApproachSpeed, &inB.mApproachSpeed, sizeof(double)) == 0 &&
           std::memcmp(&inA.mAbsorbedEnergy, &inB.mAbsorbedEnergy, sizeof(double)) == 0 &&
           inA.mTime == inB.mTime;
}

// Every collision the world dispatched, in order.
struct CollisionsHeard : DamageListener
{
    void OnCollision(const Collision& inCollision, std::span<const ObjectDent>) override
    {
        mCollisions.push_back(inCollision);
    }
    std::vector<Collision> mCollisions;
};

// A host job system that counts its parallel-for calls and hands them to inWorkers threads.
struct CountingJobs
{
    explicit CountingJobs(int inWorkers) : mThreads(inWorkers)
    {
        mJobs = mThreads.Get();
        mJobs.mHost = this;
        mJobs.mParallelFor = [](void* inHost, int inCount, void (*inTask)(void*, int), void* inContext)
        {
            auto* self = static_cast<CountingJobs*>(inHost);
            ++self->mCalls;
            const JobSystem& threads = self->mThreads.Get();
            threads.mParallelFor(threads.mHost, inCount, inTask, inContext);
        };
    }
    ThreadJobSystem mThreads;
    JobSystem mJobs;
    int mCalls = 0;
};

// The burst's two steps (the second 1/240 s later, the bricks' velocities as the first step's impulses left
// them, so each pair continues from its impact memory) with inJobs, every collision flushed.
std::vector<Collision> BurstCollisions(const JobSystem* inJobs)
{
    DamageWorldSettings settings;
    settings.mJobs = inJobs;
    BrickBurst burst = MakeBrickBurst(16, 10, 7, settings);
    CollisionsHeard heard;
    burst.mWorld->AddListener(&heard);
    constexpr double cStep = 1.0 / 240.0;
    REQUIRE(burst.mWorld->SubmitContacts(burst.mContacts, cStep).IsValid());
    for (ContactEvent& contact : burst.mContacts)
        contact.mTime += cStep;
    REQUIRE(burst.mWorld->SubmitContacts(burst.mContacts, cStep).IsValid());
    (void)burst.mWorld->Flush();
    return heard.mCollisions;
}

} // namespace

TEST_CASE("A step's contacts group into the batches a scan of every batch makes", "[plugin][burst]")
{
    // Six bodies named either way round, four step times (two of them round-off apart from another, within
    // the same-step tolerance; one just outside it), contacts of a pair interleaved with other pairs'.
    std::mt19937 random(11);
    std::uniform_int_distribution<int> body(0, 5), time(0, 4);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const double times[] = {1.0, 1.0 + 1.0e-12, 2.0, 2.0 + 0.5e-9, 2.0 + 3.0e-9};
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

TEST_CASE("A body pair index finds every pair it holds and no other", "[plugin][burst]")
{
    // 2,000 pairs filling the table to its bound (half its slots), ids dense and sparse, pairs i and i + 1,000
    // of the same slots told apart only by their generations; the pairs turned round, and pairs never
    // inserted, are not found
    BodyPairIndex index;
    constexpr std::uint32_t cPairs = 2000;
    index.Reset(cPairs);
    const auto pair_of = [](std::uint32_t inI) {
        return std::pair{BodyId{inI % 50, inI / 1000}, BodyId{50 + (inI % 1000u) * 7919u % 100000u, inI % 3}};
    };
    for (std::uint32_t i = 0; i < cPairs; ++i)
    {
        const auto [a, b] = pair_of(i);
        const auto [value, inserted] = index.TryInsert(a, b, i);
        REQUIRE(inserted);
        CHECK(value == i);
    }
    std::uint32_t found = 0, misplaced = 0, turned = 0;
    for (std::uint32_t i = 0; i < cPairs; ++i)
    {
        const auto [a, b] = pair_of(i);
        found += index.Find(a, b) == i ? 1 : 0;
        misplaced += index.TryInsert(a, b, cPairs + i).first == i ? 0 : 1;
        turned += index.Find(b, a) == BodyPairIndex::cNone ? 0 : 1;
    }
    CHECK(found == cPairs);
    CHECK(misplaced == 0);
    CHECK(turned == 0);
    CHECK(index.Find(BodyId{0, 7}, BodyId{50, 0}) == BodyPairIndex::cNone);
    CHECK(BodyPairIndex().Find(BodyId{0, 0}, BodyId{1, 0}) == BodyPairIndex::cNone);
}

TEST_CASE("A burst's impulses are the same bits inline and on 1, 2 and 4 workers", "[plugin][burst]")
{
    const std::vector<Collision> inline_solved = BurstCollisions(nullptr);
    // intent: the burst is what it stands for: 1,240 contacts of 310 pairs, over half the pairs pushed apart
    // (the others part without an impulse and make no collision)
    REQUIRE(inline_solved.size() > 150u);
    std::size_t pushing = 0;
    for (const Collision& collision : inline_solved)
        pushing += collision.mContacts.size();
    CHECK(pushing > 500u);
    for (int workers : {1, 2, 4})
    {
        INFO(workers << " workers");
        CountingJobs jobs(workers);
        const std::vector<Collision> solved = BurstCollisions(&jobs.mJobs);
        // intent: with more than one worker the burst's solves went to the job system (the second step's
        // pairs part from what the first left them, fewer closing)
        CHECK((workers > 1 ? jobs.mCalls >= 1 : jobs.mCalls == 0));
        REQUIRE(solved.size() == inline_solved.size());
        for (std::size_t i = 0; i < solved.size(); ++i)
        {
            CHECK(solved[i].mBodyA == inline_solved[i].mBodyA);
            CHECK(solved[i].mBodyB == inline_solved[i].mBodyB);
            REQUIRE(solved[i].mContacts.size() == inline_solved[i].mContacts.size());
            for (std::size_t c = 0; c < solved[i].mContacts.size(); ++c)
                CHECK(SameContact(solved[i].mContacts[c], inline_solved[i].mContacts[c]));
        }
    }
}

TEST_CASE("A step of few closing contacts solves without the job system", "[plugin][burst]")
{
    // Two bricks of the burst only: a handful of pairs, not worth handing over
    CountingJobs jobs(2);
    DamageWorldSettings settings;
    settings.mJobs = &jobs.mJobs;
    BrickBurst burst = MakeBrickBurst(2, 1, 7, settings);
    REQUIRE(burst.mContacts.size() == 12u);
    REQUIRE(burst.mWorld->SubmitContacts(burst.mContacts, 1.0 / 240.0).IsValid());
    CHECK(jobs.mCalls == 0);
}
