// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// Body and object ids are {slot index, generation}: a session that spawns and removes debris holds as many
// slots as bodies live at once, a removed body's id is refused, and recordings across reused slots replay
// bit for bit.
#include "BoxMesh.h"
#include "ScratchDirectory.h"
#include "WorldFixture.h"

#include <crumple/base/FileBytes.h>
#include <crumple/plugin/DamageRecorder.h>
#include <crumple/plugin/ReplayDamage.h>

#include <catch2/catch.hpp>

using namespace crumple;
using namespace crumple::plugin;
using crumple::common::WorldFixture;

namespace
{

std::vector<ContactEvent> FrontCorners(const WorldFixture& inFixture, double inTime)
{
    return {inFixture.FrontContact(-0.8, -0.6, inTime), inFixture.FrontContact(0.8, -0.6, inTime),
            inFixture.FrontContact(-0.8, 0.6, inTime), inFixture.FrontContact(0.8, 0.6, inTime)};
}

// A fresh car body and deformable object in place of the fixture's (which must have been removed).
void RespawnCar(WorldFixture& ioFixture, int inTriangles)
{
    ioFixture.mCar = ioFixture.mWorld.CreateBody(ioFixture.CarState(0.0)).Get();
    DeformableObjectSettings car;
    car.mMesh = common::MakeBoxMesh(ioFixture.mHalfExtents, common::BoxSegmentsForTriangles(ioFixture.mHalfExtents, inTriangles));
    car.mFittedControlCount = {8, 6, 6};
    ioFixture.mCarObject = ioFixture.mWorld.CreateDeformableObject(ioFixture.mCar, car).Get();
}

void HitWall(WorldFixture& ioFixture, double inTime)
{
    REQUIRE(ioFixture.mWorld.SetBodyState(ioFixture.mCar, ioFixture.CarState(15.0)));
    REQUIRE(ioFixture.mWorld.SubmitContacts(FrontCorners(ioFixture, inTime)));
    ioFixture.mWorld.Flush();
}

} // namespace

TEST_CASE("Removed bodies leave their slots to new bodies, and their ids are refused", "[plugin]")
{
    WorldFixture fixture;
    BodyState debris = fixture.CarState(3.0);
    debris.mMass = 20.0;
    const BodyId first = fixture.mWorld.CreateBody(debris).Get();
    REQUIRE(fixture.mWorld.RemoveBody(first));
    BodyId last = first;
    for (int i = 0; i < 10000; ++i)
    {
        last = fixture.mWorld.CreateBody(debris).Get();
        REQUIRE(fixture.mWorld.RemoveBody(last));
    }
    // 10,001 debris bodies came and went through one slot.
    CHECK(fixture.mWorld.GetBodySlotCount() == 4);
    CHECK(last.mValue == first.mValue);
    CHECK(last.mGeneration == first.mGeneration + 10000);

    // The removed debris' ids are refused everywhere, and nothing changes.
    const BodyId live = fixture.mWorld.CreateBody(debris).Get();
    CHECK(live.mValue == first.mValue);
    for (BodyId stale : {first, last})
    {
        CHECK(fixture.mWorld.GetBodyState(stale) == nullptr);
        CHECK(fixture.mWorld.SetBodyState(stale, debris).GetError().mCode == EError::OutOfRange);
        CHECK(fixture.mWorld.RemoveBody(stale).GetError().mCode == EError::OutOfRange);
        DeformableObjectSettings panel;
        panel.mMesh = common::MakeBoxMesh(Vec3(0.2, 0.2, 0.2), {2, 2, 2});
        CHECK(fixture.mWorld.CreateDeformableObject(stale, panel).GetError().mCode == EError::OutOfRange);
        ContactEvent contact = fixture.FrontContact(0.0, 0.0, 0.0);
        contact.mBodyB = stale;
        CHECK(fixture.mWorld.SubmitContacts(std::span(&contact, 1)).HasError());
        CHECK(fixture.mWorld.GetOpenCollisionCount() == 0);
    }
    CHECK(fixture.mWorld.GetBodyState(live) != nullptr);
    CHECK(fixture.mWorld.GetObjectIds().size() == 1);
}

TEST_CASE("A respawned car reuses the removed car's slots, the old object's id is refused", "[plugin]")
{
    WorldFixture fixture;
    const BodyId old_car = fixture.mCar;
    const ObjectId old_object = fixture.mCarObject;
    for (int life = 0; life < 3; ++life)
    {
        REQUIRE(fixture.mWorld.RemoveBody(fixture.mCar));
        RespawnCar(fixture, 4000);
    }
    CHECK(fixture.mWorld.GetBodySlotCount() == 3);
    CHECK(fixture.mWorld.GetObjectSlotCount() == 1);
    CHECK(fixture.mCar.mValue == old_car.mValue);
    CHECK(fixture.mCar.mGeneration == old_car.mGeneration + 3);
    CHECK(fixture.mCarObject.mValue == old_object.mValue);
    CHECK(fixture.mCarObject.mGeneration == old_object.mGeneration + 3);

    CHECK(fixture.mWorld.GetObject(old_object) == nullptr);
    CHECK_FALSE(fixture.mWorld.GetObjectBody(old_object).IsValid());
    CHECK(fixture.mWorld.TakeDirtyRanges(old_object).empty());
    CHECK(fixture.mWorld.GetObjectIds() == std::vector<ObjectId>{fixture.mCarObject});
    CHECK(fixture.mWorld.GetObjectBody(fixture.mCarObject) == fixture.mCar);

    // The respawned car is dented by its own hit.
    HitWall(fixture, 0.0);
    const ffd::FfdDeformer& car = fixture.mWorld.GetObject(fixture.mCarObject)->GetDeformer();
    CHECK(car.GetPositions() != car.GetRestMesh().mPositions);
}

TEST_CASE("A recording across a reused slot replays each object's own dents bit for bit", "[plugin][replay]")
{
    const std::filesystem::path path = common::ScratchDirectory() / "respawn.crumple";
    WorldFixture fixture;
    std::unique_ptr<DamageRecorder> recorder = std::move(DamageRecorder::Create(path, fixture.mWorld).Get());
    HitWall(fixture, 0.0);
    const std::vector<Vec3> first_life = fixture.mWorld.GetObject(fixture.mCarObject)->GetDeformer().GetPositions();
    REQUIRE(fixture.mWorld.RemoveBody(fixture.mCar));
    RespawnCar(fixture, 2000); // another mesh in the same slots
    HitWall(fixture, 1.0);
    const std::vector<Vec3> second_life = fixture.mWorld.GetObject(fixture.mCarObject)->GetDeformer().GetPositions();
    REQUIRE(recorder->Close());

    const Replay replay = DecodeReplay(ReadFileBytes(path).Get()).Get();
    REQUIRE(replay.mObjects.size() == 2);
    REQUIRE(replay.mCollisions.size() == 2);
    CHECK(replay.mObjects[0].mObject.mValue == replay.mObjects[1].mObject.mValue);
    CHECK(replay.mObjects[0].mObject.mGeneration + 1 == replay.mObjects[1].mObject.mGeneration);
    // The wall and the car, in id order: the car (slot 2) is body B, the first life then the second.
    CHECK(replay.mCollisions[0].mBodyB.mValue == fixture.mCar.mValue);
    CHECK(replay.mCollisions[0].mBodyB.mGeneration + 1 == replay.mCollisions[1].mBodyB.mGeneration);
    Result<std::vector<ReplayedObject>> objects = ReplayDamage(replay);
    REQUIRE(objects);
    REQUIRE(objects.Get().size() == 2);
    // Each life is dented by its own collision only: the first car would otherwise take the second hit too.
    CHECK(objects.Get()[0].mDeformable.GetDeformer().GetPositions() == first_life);
    CHECK(objects.Get()[1].mDeformable.GetDeformer().GetPositions() == second_life);
}
