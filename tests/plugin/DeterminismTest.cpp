// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "DentsInFlight.h"
#include "SameBytes.h"
#include "ScratchDirectory.h"
#include "ThreadJobSystem.h"
#include "WallCrashScene.h"
#include "WorldFixture.h"

#include <crumple/base/FileBytes.h>
#include <crumple/plugin/DamageRecorder.h>
#include <crumple/plugin/ReplayDamage.h>

#include <catch2/catch.hpp>

#include <cstring>

using namespace crumple;
using namespace crumple::plugin;
using namespace crumple::common;

namespace
{

struct Snapshot
{
    std::vector<Vec3> mPositions;
    std::vector<Vec3> mNormals;
    std::vector<std::byte> mDamage;
};

Snapshot RunCrash(double inYawDegrees)
{
    WallCrashSettings settings;
    settings.mYawDegrees = inYawDegrees;
    settings.mTriangles = 6000;
    WallCrashScene scene = WallCrashScene::Create(settings).Get();
    scene.Run();
    const ffd::FfdDeformer& car = scene.GetWorld().GetObject(scene.GetCarObject())->GetDeformer();
    return {car.GetPositions(), car.GetNormals(), scene.GetWorld().SaveDamage()};
}

} // namespace

TEST_CASE("The same contact stream twice gives bitwise identical meshes", "[plugin][determinism]")
{
    for (double yaw : {0.0, 30.0})
    {
        INFO("yaw " << yaw << " degrees");
        const Snapshot first = RunCrash(yaw);
        const Snapshot second = RunCrash(yaw);
        CHECK(SameBytes(first.mPositions, second.mPositions));
        CHECK(SameBytes(first.mNormals, second.mNormals));
        CHECK(first.mDamage == second.mDamage);
        // And the crash did dent the car.
        CHECK(HashPositions(first.mPositions) != 0);
        WallCrashSettings settings;
        settings.mTriangles = 6000;
        const WallCrashScene untouched = WallCrashScene::Create(settings).Get();
        CHECK_FALSE(SameBytes(first.mPositions, untouched.GetWorld().GetObject(untouched.GetCarObject())->GetDeformer().GetPositions()));
    }
}

TEST_CASE("Replaying dispatched collisions on fresh objects reproduces the live meshes", "[plugin][determinism]")
{
    // Record every collision the live world dispatches, then apply them to a fresh object in order:
    // the headless-replay path (no contacts, no impulses, no engine).
    struct Recorder : DamageListener
    {
        void OnCollision(const Collision& inCollision, std::span<const ObjectDent>) override { mCollisions.push_back(inCollision); }
        std::vector<Collision> mCollisions;
    } recorder;
    WallCrashSettings settings;
    settings.mYawDegrees = 30.0;
    settings.mTriangles = 6000;
    WallCrashScene live = WallCrashScene::Create(settings).Get();
    live.GetWorld().AddListener(&recorder);
    live.Run();
    REQUIRE_FALSE(recorder.mCollisions.empty());

    WallCrashScene fresh = WallCrashScene::Create(settings).Get();
    // A copy of the fresh world's car, dented by hand outside any world.
    DeformableObject replayed = *fresh.GetWorld().GetObject(fresh.GetCarObject());
    for (const Collision& collision : recorder.mCollisions)
        // (Every collision the world dispatched passes ValidateCollision, which ApplyCollision runs first.)
        REQUIRE(replayed
                    .ApplyCollision(collision, collision.mBodyA == fresh.GetCar() ? ECollisionSide::A
                                                                                  : ECollisionSide::B)
                    .IsValid());
    CHECK(SameBytes(replayed.GetDeformer().GetPositions(),
                    live.GetWorld().GetObject(live.GetCarObject())->GetDeformer().GetPositions()));
}

namespace
{

struct CountingListener : DamageListener
{
    void OnBeforeCollision(const Collision& inCollision) override { mBefore.push_back(inCollision.mSequence); }
    void OnCollision(const Collision& inCollision, std::span<const ObjectDent> inDents) override
    {
        mAfter.push_back(inCollision.mSequence);
        for (const ObjectDent& dent : inDents)
            mVertices += dent.mReport.mVerticesMoved;
    }
    std::vector<std::uint64_t> mBefore, mAfter;
    std::uint64_t mVertices = 0;
};

} // namespace

TEST_CASE("Deferred dents land one Update later, bitwise as inline, on any thread count", "[plugin][determinism]")
{
    for (double yaw : {0.0, 30.0})
    {
        WallCrashSettings settings;
        settings.mYawDegrees = yaw;
        settings.mTriangles = 6000;
        WallCrashScene inline_scene = WallCrashScene::Create(settings).Get();
        CountingListener inline_listener;
        inline_scene.GetWorld().AddListener(&inline_listener);
        inline_scene.Run();
        const ffd::FfdDeformer& reference = inline_scene.GetWorld().GetObject(inline_scene.GetCarObject())->GetDeformer();

        for (int threads : {1, 2, 4})
        {
            INFO("yaw " << yaw << " degrees, " << threads << " thread(s)");
            const ThreadJobSystem jobs(threads);
            WallCrashSettings deferred_settings = settings;
            deferred_settings.mWorld.mJobs = &jobs.Get();
            deferred_settings.mWorld.mDeferDents = true;
            WallCrashScene scene = WallCrashScene::Create(deferred_settings).Get();
            CountingListener listener;
            scene.GetWorld().AddListener(&listener);
            const ffd::FfdDeformer& car = scene.GetWorld().GetObject(scene.GetCarObject())->GetDeformer();
            const std::vector<Vec3> rest = car.GetPositions();
            // Step until the first dispatch: its dents are started, not landed, and the game still sees
            // the mesh as it was.
            REQUIRE(StepUntilDentsInFlight(scene));
            CHECK(SameBytes(car.GetPositions(), rest));
            CHECK(listener.mAfter.size() < listener.mBefore.size());
            scene.Run();
            CHECK_FALSE(scene.GetWorld().HasDentsInFlight());
            CHECK(SameBytes(car.GetPositions(), reference.GetPositions()));
            CHECK(SameBytes(car.GetNormals(), reference.GetNormals()));
            CHECK(scene.GetWorld().SaveDamage() == inline_scene.GetWorld().SaveDamage());
            CHECK(listener.mBefore == inline_listener.mBefore);
            CHECK(listener.mAfter == inline_listener.mAfter);
            CHECK(listener.mVertices == inline_listener.mVertices);
        }
    }
}

TEST_CASE("Deferred dents need a job system that can start tasks", "[plugin]")
{
    DamageWorldSettings settings;
    settings.mDeferDents = true;
    CHECK(DamageWorld::Create(settings).HasError());
    JobSystem parallel_only;
    parallel_only.mParallelFor = [](void*, int inCount, void (*inTask)(void*, int), void* inContext) {
        for (int i = 0; i < inCount; ++i)
            inTask(inContext, i);
    };
    settings.mJobs = &parallel_only;
    CHECK(DamageWorld::Create(settings).HasError());
}

TEST_CASE("A recorder started or closed while deferred dents are in flight replays the run exactly", "[plugin][determinism]")
{
    const ThreadJobSystem jobs(2);
    WallCrashSettings settings;
    settings.mYawDegrees = 30.0;
    settings.mTriangles = 4000;
    settings.mWorld.mJobs = &jobs.Get();
    settings.mWorld.mDeferDents = true;
    WallCrashScene scene = WallCrashScene::Create(settings).Get();
    for (int step = 0; step < 200 && !scene.GetWorld().HasDentsInFlight(); ++step)
        scene.Step();
    REQUIRE(scene.GetWorld().HasDentsInFlight());
    // Started now: the dents in flight land first and belong to the damage the recording starts from.
    const std::filesystem::path path = ScratchDirectory() / "deferred.crumple";
    Result<std::unique_ptr<DamageRecorder>> recorder = DamageRecorder::Create(path, scene.GetWorld());
    REQUIRE(recorder);
    for (int step = 0; step < 200 && !scene.GetWorld().HasDentsInFlight(); ++step)
        scene.Step();
    // Closed now: the dents in flight land first and are recorded.
    REQUIRE(recorder.Get()->Close());
    const std::vector<Vec3> live = scene.GetWorld().GetObject(scene.GetCarObject())->GetDeformer().GetPositions();
    Result<Replay> replay = DecodeReplay(ReadFileBytes(path).Get());
    REQUIRE(replay);
    Result<std::vector<ReplayedObject>> replayed = ReplayDamage(replay.Get());
    REQUIRE(replayed);
    CHECK(SameBytes(replayed.Get()[0].mDeformable.GetDeformer().GetPositions(), live));
}

TEST_CASE("The wall crash's meshes hash to their committed golden values", "[plugin][determinism]")
{
    // Golden hashes of the scripted wall crash's final car mesh (positions, then normals), head-on and at
    // 30 degrees. Results are bitwise reproducible for a given build of the same sources; a commit that
    // changes them on purpose (a new dent rule, a different solve) updates these values and says why.
    struct Golden
    {
        double mYaw;
        std::uint64_t mPositions;
        std::uint64_t mNormals;
    };
    for (const Golden& golden : {Golden{0.0, 0xbd62a9ed55ca599full, 0x302b357c572b91c9ull},
                                 Golden{30.0, 0xbc46875eaeccb64dull, 0x1f792a826e80b21cull}})
    {
        const Snapshot run = RunCrash(golden.mYaw);
        INFO("yaw " << golden.mYaw << ": positions " << std::hex << HashPositions(run.mPositions) << ", normals "
                    << HashPositions(run.mNormals));
        CHECK(HashPositions(run.mPositions) == golden.mPositions);
        CHECK(HashPositions(run.mNormals) == golden.mNormals);
    }
}

TEST_CASE("Deferred dents: a collision's OnCollision goes to the listeners that had its OnBeforeCollision",
          "[plugin]")
{
    // The dispatch calls OnBeforeCollision at one Update, the landing OnCollision at the next: a listener
    // added in between heard no OnBeforeCollision of that collision (a recorder captures its objects there),
    // so it must not hear its OnCollision either; it hears the collisions dispatched after it was added.
    struct CountingListener : DamageListener
    {
        void OnBeforeCollision(const Collision&) override { ++mBefore; }
        void OnCollision(const Collision&, std::span<const ObjectDent>) override { ++mAfter; }
        int mBefore = 0, mAfter = 0;
    };
    const ThreadJobSystem jobs(2);
    DamageWorldSettings settings;
    settings.mJobs = &jobs.Get();
    settings.mDeferDents = true;
    WorldFixture fixture(4000, {8, 6, 6}, settings);
    CountingListener early, late;
    fixture.mWorld.AddListener(&early);
    const double dt = 1.0 / 120.0;
    REQUIRE(fixture.mWorld.SetBodyState(fixture.mCar, fixture.CarState(10.0)));
    REQUIRE(
        fixture.mWorld.SubmitContacts(std::vector<ContactEvent>{fixture.FrontContact(0.0, 0.0, 0.0)}, dt));
    (void)fixture.mWorld.Update(1.0); // the first collision's window closed: dispatched, its dent in flight
    REQUIRE(fixture.mWorld.HasDentsInFlight());
    CHECK(early.mBefore == 1);
    fixture.mWorld.AddListener(&late);
    REQUIRE(fixture.mWorld.SetBodyState(fixture.mCar, fixture.CarState(10.0)));
    REQUIRE(
        fixture.mWorld.SubmitContacts(std::vector<ContactEvent>{fixture.FrontContact(0.0, 0.0, 2.0)}, dt));
    (void)fixture.mWorld.Flush(); // lands the first, dispatches and lands the second
    CHECK(early.mBefore == 2);
    CHECK(early.mAfter == 2);
    CHECK(late.mBefore == 1);
    CHECK(late.mAfter == 1); // the second collision's only
    fixture.mWorld.RemoveListener(&late);
    fixture.mWorld.RemoveListener(&early);
}
