// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "WallCrashScene.h"
#include "WorldFixture.h"

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

bool SameBytes(const std::vector<Vec3>& inA, const std::vector<Vec3>& inB)
{
    return inA.size() == inB.size() && std::memcmp(inA.data(), inB.data(), inA.size() * sizeof(Vec3)) == 0;
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
    DeformableObject& replayed = *fresh.GetWorld().GetObject(fresh.GetCarObject());
    for (const Collision& collision : recorder.mCollisions)
        replayed.ApplyCollision(collision, collision.mBodyA == fresh.GetCar() ? ECollisionSide::A : ECollisionSide::B);
    CHECK(SameBytes(replayed.GetDeformer().GetPositions(),
                    live.GetWorld().GetObject(live.GetCarObject())->GetDeformer().GetPositions()));
}
