// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// One engine step of hundreds of body pairs (a brick wall bursting): the pairs' impulses, solved inline or
// split over the host's workers, are the same bits whatever the number of workers, over two steps (the second
// continues from the impact memories the first left); with the impulses deferred, the job system's parallel
// for is called from the game's thread only, never from the task that solves them.
#include "BrickBurst.h"
#include "CountingJobs.h"
#include "SameBytes.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <thread>

using namespace crumple;
using namespace crumple::plugin;
using namespace crumple::common;

namespace
{

// Every collision the world dispatched, in order.
struct CollisionsHeard : DamageListener
{
    void OnCollision(const Collision& inCollision, std::span<const ObjectDent>) override
    {
        mCollisions.push_back(inCollision);
    }
    std::vector<Collision> mCollisions;
};

// The burst's first inSteps engine steps with inJobs, every collision flushed: the second step 1/240 s later,
// with the bricks' velocities as the first step's impulses left them (each pair continues from its impact
// memory).
std::vector<Collision> BurstCollisions(const JobSystem* inJobs, int inSteps = 2)
{
    DamageWorldSettings settings;
    settings.mJobs = inJobs;
    BrickBurst burst = MakeBrickBurst(16, 10, 7, settings);
    CollisionsHeard heard;
    burst.mWorld->AddListener(&heard);
    constexpr double cStep = 1.0 / 240.0;
    for (int step = 0; step < inSteps; ++step)
    {
        REQUIRE(burst.mWorld->SubmitContacts(burst.mContacts, cStep).IsValid());
        for (ContactEvent& contact : burst.mContacts)
            contact.mTime += cStep;
    }
    (void)burst.mWorld->Flush();
    return heard.mCollisions;
}

} // namespace

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
        const std::vector<Collision> solved = BurstCollisions(&jobs.Get());
        // intent: with more than one worker the burst's solves went to the job system (the second step's
        // pairs part from what the first left them, fewer closing)
        CHECK((workers > 1 ? jobs.GetCalls() >= 1 : jobs.GetCalls() == 0));
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
    settings.mJobs = &jobs.Get();
    BrickBurst burst = MakeBrickBurst(2, 1, 7, settings);
    REQUIRE(burst.mContacts.size() == 12u);
    REQUIRE(burst.mWorld->SubmitContacts(burst.mContacts, 1.0 / 240.0).IsValid());
    CHECK(jobs.GetCalls() == 0);
}

TEST_CASE("Deferred impulses call the job system from the game's thread only", "[plugin][burst]")
{
    // The burst's first step with the impulses deferred: solved on the dents' task (which must not call the
    // parallel for: a task never calls back into the job system) after an Update, or on the game's thread by
    // Flush (which may). Both give the inline world's collisions bit for bit.
    const std::vector<Collision> inline_solved = BurstCollisions(nullptr, 1);
    for (const bool on_task : {true, false})
    {
        INFO((on_task ? "solved on the task" : "solved by Flush"));
        CountingJobs jobs(2);
        DamageWorldSettings settings;
        settings.mJobs = &jobs.Get();
        settings.mDeferDents = true;
        settings.mDeferImpulses = true;
        BrickBurst burst = MakeBrickBurst(16, 10, 7, settings);
        CollisionsHeard heard;
        burst.mWorld->AddListener(&heard);
        REQUIRE(burst.mWorld->SubmitContacts(burst.mContacts, 1.0 / 240.0).IsValid());
        if (on_task)
            (void)burst.mWorld->Update(1.0); // hands the step to the task; Flush lands it
        (void)burst.mWorld->Flush();
        CHECK(jobs.GetOffThreadCalls() == 0);
        CHECK(jobs.GetCalls() == (on_task ? 0 : 1));
        REQUIRE(heard.mCollisions.size() == inline_solved.size());
        for (std::size_t i = 0; i < heard.mCollisions.size(); ++i)
        {
            REQUIRE(heard.mCollisions[i].mContacts.size() == inline_solved[i].mContacts.size());
            for (std::size_t c = 0; c < heard.mCollisions[i].mContacts.size(); ++c)
                CHECK(SameContact(heard.mCollisions[i].mContacts[c], inline_solved[i].mContacts[c]));
        }
    }
}

TEST_CASE("A job system that skips pieces gets the step refused, changing nothing", "[plugin][burst]")
{
    // A broken host: its parallel for returns without running anything. The step's pairs are then unsolved:
    // SubmitContacts refuses the whole step instead of reading impulses never made, and no collision comes of
    // it.
    JobSystem lazy;
    lazy.mParallelFor = [](void*, int, void (*)(void*, int), void*) {};
    lazy.mWorkerCount = 2;
    DamageWorldSettings settings;
    settings.mJobs = &lazy;
    BrickBurst burst = MakeBrickBurst(16, 10, 7, settings);
    CollisionsHeard heard;
    burst.mWorld->AddListener(&heard);
    const Status refused = burst.mWorld->SubmitContacts(burst.mContacts, 1.0 / 240.0);
    REQUIRE(refused.HasError());
    CHECK(refused.GetError().mCode == EError::InvalidArgument);
    (void)burst.mWorld->Flush();
    CHECK(heard.mCollisions.empty());
}
