// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// DamageWorldSettings::mDeferImpulses: the contacts' impulses solved on the dents' task. The collisions,
// their impulses and the dents are bitwise those of a world that solves them in SubmitContacts, one Update
// later, whatever the job system; ForgetImpacts keeps its place among the steps; Flush and RemoveBody solve
// what waits.
#include "DentsInFlight.h"
#include "SameBytes.h"
#include "ThreadJobSystem.h"
#include "WallCrashScene.h"
#include "WorldFixture.h"

#include <catch2/catch.hpp>

#include <cstring>
#include <limits>

using namespace crumple;
using namespace crumple::plugin;
using namespace crumple::common;

namespace
{

// What the listeners heard, collision by collision: sequence numbers, and each collision's contacts'
// impulses.
struct HeardListener : DamageListener
{
    void OnBeforeCollision(const Collision& inCollision) override
    {
        mBefore.push_back(inCollision.mSequence);
        std::vector<double> impulses;
        for (const CollisionContact& contact : inCollision.mContacts)
        {
            impulses.push_back(contact.mImpulse);
            impulses.push_back(contact.mFrictionImpulse.norm());
            impulses.push_back(contact.mAbsorbedEnergy);
        }
        mImpulses.push_back(impulses);
    }
    void OnCollision(const Collision& inCollision, std::span<const ObjectDent> inDents) override
    {
        mAfter.push_back(inCollision.mSequence);
        for (const ObjectDent& dent : inDents)
            mVertices += dent.mReport.mVerticesMoved;
    }
    std::vector<std::uint64_t> mBefore, mAfter;
    std::vector<std::vector<double>> mImpulses;
    std::uint64_t mVertices = 0;
};

} // namespace

TEST_CASE(
    "Deferred impulses: the wall crash's collisions and dents are bitwise those solved in SubmitContacts, on "
    "any thread count",
    "[plugin][determinism]")
{
    for (double yaw : {0.0, 30.0})
    {
        WallCrashSettings settings;
        settings.mYawDegrees = yaw;
        settings.mTriangles = 6000;
        WallCrashScene reference = WallCrashScene::Create(settings).Get();
        HeardListener heard;
        reference.GetWorld().AddListener(&heard);
        reference.Run();
        REQUIRE_FALSE(heard.mBefore.empty());
        const ffd::FfdDeformer& reference_car =
            reference.GetWorld().GetObject(reference.GetCarObject())->GetDeformer();

        for (int threads : {1, 2, 4})
        {
            INFO("yaw " << yaw << " degrees, " << threads << " thread(s)");
            const ThreadJobSystem jobs(threads);
            WallCrashSettings deferred = settings;
            deferred.mWorld.mJobs = &jobs.Get();
            deferred.mWorld.mDeferDents = true;
            deferred.mWorld.mDeferImpulses = true;
            WallCrashScene scene = WallCrashScene::Create(deferred).Get();
            HeardListener listener;
            scene.GetWorld().AddListener(&listener);
            // The first contacts go to a task at the Update of their step: nothing is grouped or dispatched
            // yet.
            REQUIRE(StepUntilDentsInFlight(scene));
            CHECK(listener.mBefore.empty());
            CHECK(scene.GetWorld().GetOpenCollisionCount() >
                  0); // waits for the task: its contacts are grouped
            scene.Run();
            const ffd::FfdDeformer& car = scene.GetWorld().GetObject(scene.GetCarObject())->GetDeformer();
            CHECK(SameBytes(car.GetPositions(), reference_car.GetPositions()));
            CHECK(SameBytes(car.GetNormals(), reference_car.GetNormals()));
            CHECK(scene.GetWorld().SaveDamage() == reference.GetWorld().SaveDamage());
            CHECK(listener.mBefore == heard.mBefore);
            CHECK(listener.mAfter == heard.mAfter);
            CHECK(listener.mImpulses == heard.mImpulses);
            CHECK(listener.mVertices == heard.mVertices);
        }
    }
}

namespace
{

// A car driven into the wall over five 1/120 s steps, each one's contacts submitted with the step (so a step
// after a pushing one is solved from the velocities its impulse left), ForgetImpacts of the car after the
// steps in inForgetAfter; then Flush. What the listeners heard.
HeardListener DriveIntoWall(const DamageWorldSettings& inSettings, const std::vector<int>& inForgetAfter)
{
    WorldFixture fixture(4000, {8, 6, 6}, inSettings);
    HeardListener heard;
    fixture.mWorld.AddListener(&heard);
    constexpr double cStep = 1.0 / 120.0;
    for (int step = 0; step < 5; ++step)
    {
        const double time = (step + 1) * cStep;
        REQUIRE(fixture.mWorld.SetBodyState(fixture.mCar, fixture.CarState(12.0 - step)));
        REQUIRE(
            fixture.mWorld.SubmitContacts(std::vector<ContactEvent>{fixture.FrontContact(-0.3, 0.1, time),
                                                                    fixture.FrontContact(0.4, -0.2, time)},
                                          cStep));
        const UpdateReport report = fixture.mWorld.Update(time);
        CHECK(report.mSubmissionsDropped == 0);
        if (std::find(inForgetAfter.begin(), inForgetAfter.end(), step) != inForgetAfter.end())
            REQUIRE(fixture.mWorld.ForgetImpacts(fixture.mCar));
    }
    fixture.mWorld.Flush();
    fixture.mWorld.RemoveListener(&heard);
    return heard;
}

} // namespace

TEST_CASE(
    "Deferred impulses: ForgetImpacts keeps its place among the steps' contacts, and Flush solves what waits",
    "[plugin]")
{
    const HeardListener remembered = DriveIntoWall({}, {});
    const HeardListener forgotten = DriveIntoWall({}, {1, 3});
    REQUIRE_FALSE(remembered.mImpulses.empty());
    // Not vacuous: forgetting after steps 1 and 3 solves steps 2 and 4 from the engine's velocities.
    CHECK(forgotten.mImpulses != remembered.mImpulses);
    for (int threads : {1, 2})
    {
        INFO(threads << " thread(s)");
        const ThreadJobSystem jobs(threads);
        DamageWorldSettings settings;
        settings.mJobs = &jobs.Get();
        settings.mDeferDents = true;
        settings.mDeferImpulses = true;
        const HeardListener deferred_remembered = DriveIntoWall(settings, {});
        const HeardListener deferred_forgotten = DriveIntoWall(settings, {1, 3});
        CHECK(deferred_remembered.mImpulses == remembered.mImpulses);
        CHECK(deferred_forgotten.mImpulses == forgotten.mImpulses);
        CHECK(deferred_forgotten.mAfter == forgotten.mAfter);
        CHECK(deferred_forgotten.mVertices == forgotten.mVertices);
    }
}

TEST_CASE(
    "Deferred impulses: refused without deferred dents, and a bad contact is refused at once with nothing left waiting",
    "[plugin]")
{
    const ThreadJobSystem jobs(2);
    DamageWorldSettings settings;
    settings.mJobs = &jobs.Get();
    settings.mDeferImpulses = true;
    CHECK(DamageWorld::Create(settings).GetError().mCode == EError::InvalidArgument);

    settings.mDeferDents = true;
    WorldFixture fixture(4000, {8, 6, 6}, settings);
    REQUIRE(fixture.mWorld.SetBodyState(fixture.mCar, fixture.CarState(10.0)));
    ContactEvent bad = fixture.FrontContact(0.0, 0.0, 0.01);
    bad.mNormal.x() = std::numeric_limits<double>::quiet_NaN();
    CHECK(fixture.mWorld
              .SubmitContacts(std::vector<ContactEvent>{fixture.FrontContact(0.2, 0.0, 0.01), bad}, 0.01)
              .GetError()
              .mCode == EError::NonFinite);
    fixture.mWorld.Update(0.01);
    CHECK_FALSE(fixture.mWorld.HasDentsInFlight()); // nothing was kept for a task
    CHECK(fixture.mWorld.GetOpenCollisionCount() == 0);

    // Contacts flushed without an Update: Flush solves them, dispatches their collision and lands its dent.
    REQUIRE(fixture.mWorld.SubmitContacts(std::vector<ContactEvent>{fixture.FrontContact(0.2, 0.0, 0.015)},
                                          0.01));
    const UpdateReport flushed_at_once = fixture.mWorld.Flush();
    CHECK(flushed_at_once.mCollisionsDispatched == 1);
    CHECK(flushed_at_once.mObjectsDented == 1);
    CHECK_FALSE(fixture.mWorld.HasDentsInFlight());

    // A body removed while its contacts wait: they are solved first, then go with it.
    REQUIRE(
        fixture.mWorld.SubmitContacts(std::vector<ContactEvent>{fixture.FrontContact(0.2, 0.0, 0.02)}, 0.01));
    REQUIRE(fixture.mWorld.RemoveBody(fixture.mCar));
    CHECK(fixture.mWorld.GetOpenCollisionCount() == 0);
    const UpdateReport flushed = fixture.mWorld.Flush();
    CHECK(flushed.mCollisionsDispatched == 0);
    CHECK(flushed.mSubmissionsDropped == 0);
}

TEST_CASE("Deferred impulses: a contact at exactly the end of a collision's window joins it, as when solved "
          "at once",
          "[plugin]")
{
    // Steps of 1/8 s and a window of 1/4 s (exact in binary): the contacts at 1/8, 1/4 and 3/8 s make one
    // collision (3/8 is its window's end); the Update at 3/8 s closes it only once that contact is in.
    const auto run = [](const DamageWorldSettings& inSettings)
    {
        DamageWorldSettings settings = inSettings;
        settings.mGrouping.mTimeWindow = 0.25;
        WorldFixture fixture(4000, {8, 6, 6}, settings);
        HeardListener heard;
        fixture.mWorld.AddListener(&heard);
        for (int step = 1; step <= 4; ++step)
        {
            const double time = 0.125 * step;
            REQUIRE(fixture.mWorld.SetBodyState(fixture.mCar, fixture.CarState(10.0)));
            if (step <= 3)
                REQUIRE(fixture.mWorld.SubmitContacts(
                    std::vector<ContactEvent>{fixture.FrontContact(0.1 * step, 0.0, time)}));
            fixture.mWorld.Update(time);
        }
        fixture.mWorld.Flush();
        fixture.mWorld.RemoveListener(&heard);
        return heard;
    };
    const HeardListener at_once = run({});
    REQUIRE(at_once.mImpulses.size() == 1);
    CHECK(at_once.mImpulses[0].size() == 3 * 3); // three contacts, three figures each
    const ThreadJobSystem jobs(2);
    DamageWorldSettings deferred;
    deferred.mJobs = &jobs.Get();
    deferred.mDeferDents = true;
    deferred.mDeferImpulses = true;
    const HeardListener later = run(deferred);
    CHECK(later.mImpulses == at_once.mImpulses);
    CHECK(later.mAfter == at_once.mAfter);
}
