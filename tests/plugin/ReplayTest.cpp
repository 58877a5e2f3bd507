// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "BoxMesh.h"
#include "ScratchDirectory.h"
#include "WallCrashScene.h"
#include "WorldFixture.h"

#include <crumple/base/ByteWriter.h>
#include <crumple/base/Crc32.h>
#include <crumple/base/FileBytes.h>
#include <crumple/plugin/DamageRecorder.h>
#include <crumple/plugin/DamageState.h>
#include <crumple/plugin/ReplayDamage.h>

#include <catch2/catch.hpp>

#include <filesystem>
#include <functional>

using namespace crumple;
using namespace crumple::plugin;
using namespace crumple::common;

namespace
{

std::filesystem::path ScratchFile(const std::string& inName)
{
    return ScratchDirectory() / inName;
}

// A 30-degree wall crash recorded to a file; returns the live car mesh.
std::vector<Vec3> RecordCrash(const std::filesystem::path& inPath, bool inDentBeforeRecording)
{
    WallCrashSettings settings;
    settings.mYawDegrees = 30.0;
    settings.mTriangles = 4000;
    WallCrashScene scene = WallCrashScene::Create(settings).Get();
    if (inDentBeforeRecording)
    {
        // Damage the car's rear before recording starts (a saved damage state loaded into the world, the way
        // a game restores a damaged car): the recording must carry it.
        DeformableObject car = *scene.GetWorld().GetObject(scene.GetCarObject());
        REQUIRE(car.GetDeformer().ApplyDent(std::vector<ffd::PointDisplacement>{{Vec3(-2.1, 0.0, 0.0), Vec3(0.05, 0.0, 0.0)}}));
        DamageState state = DecodeDamageState(scene.GetWorld().SaveDamage()).Get();
        for (ObjectDamage& object : state.mObjects)
            if (object.mObject == scene.GetCarObject())
            {
                object.mZones.clear();
                for (const ffd::FfdLattice& zone : car.GetDeformer().GetZones())
                    object.mZones.push_back(zone.GetControlDisplacements());
            }
        REQUIRE(scene.GetWorld().LoadDamage(EncodeDamageState(state)));
    }
    std::unique_ptr<DamageRecorder> recorder = std::move(DamageRecorder::Create(inPath, scene.GetWorld()).Get());
    // A second deformable object created mid-run, on the wall, is recorded before its first collision.
    DeformableObjectSettings wall_panel;
    wall_panel.mMesh.mPositions = {Vec3(0.0, -3.0, -1.0), Vec3(0.0, 3.0, -1.0), Vec3(0.0, 3.0, 2.0), Vec3(0.0, -3.0, 2.0)};
    wall_panel.mMesh.mTriangles = {{0u, 2u, 1u}, {0u, 3u, 2u}};
    REQUIRE(scene.GetWorld().CreateDeformableObject(scene.GetWall(), wall_panel));
    // A third object, on the car, created after its first collision: replay must not give it that one.
    while (recorder->GetCollisionCount() == 0 && scene.GetTime() < 1.0)
        scene.Step();
    REQUIRE(recorder->GetCollisionCount() >= 1);
    DeformableObjectSettings bumper;
    bumper.mMesh = MakeBoxMesh(Vec3(2.0, 0.8, 0.6), {8, 4, 4});
    bumper.mDeformer.mOneSidedDents = false; // a non-default deformer setting the replay must carry
    bumper.mDeformer.mRigidParts = {{0, 1, 2}, {5}}; // and rigid parts (version 8)
    REQUIRE(scene.GetWorld().CreateDeformableObject(scene.GetCar(), bumper));
    // A second hit, on the same front, so the late object is dented too.
    BodyState again = scene.GetCarState();
    again.mLinearVelocity = Vec3(8.0, 0.0, 0.0);
    REQUIRE(scene.GetWorld().SetBodyState(scene.GetCar(), again));
    ContactEvent hit;
    hit.mBodyA = scene.GetCar();
    hit.mBodyB = scene.GetWall();
    hit.mPointOnA = hit.mPointOnB = again.mTransform.ToWorld(Vec3(2.1, 0.0, 0.0));
    hit.mNormal = -Vec3::UnitX();
    hit.mTime = scene.GetTime();
    REQUIRE(scene.GetWorld().SubmitContacts(std::span(&hit, 1)));
    scene.GetWorld().Flush();
    REQUIRE(recorder->Close());
    std::vector<Vec3> positions;
    for (ObjectId id : scene.GetWorld().GetObjectIds())
    {
        const std::vector<Vec3>& p = scene.GetWorld().GetObject(id)->GetDeformer().GetPositions();
        positions.insert(positions.end(), p.begin(), p.end());
    }
    return positions;
}

} // namespace

TEST_CASE("A recorded run replayed without an engine gives bitwise identical meshes", "[plugin][replay]")
{
    for (bool pre_damaged : {false, true})
    {
        const std::filesystem::path path = ScratchFile(pre_damaged ? "pre.crumple" : "fresh.crumple");
        const std::vector<Vec3> live = RecordCrash(path, pre_damaged);
        CHECK_FALSE(std::filesystem::exists(path.string() + ".partial"));
        const std::vector<std::byte> bytes = ReadFileBytes(path).Get();
        Result<Replay> replay = DecodeReplay(bytes);
        REQUIRE(replay);
        CHECK(replay.Get().mObjects.size() == 3);
        for (const RecordedObject& object : replay.Get().mObjects)
        {
            // Version 3 carries the fold guard's setting, version 4 the prior, read back in place (the fields
            // after them too).
            CHECK(object.mSettings.mDeformer.mMinControlSpacing == ffd::FfdDeformerSettings{}.mMinControlSpacing);
            CHECK(object.mSettings.mDeformer.mPrior == ffd::FfdDeformerSettings{}.mPrior);
            CHECK(object.mSettings.mDeformer.mInverseIterations == ffd::FfdDeformerSettings{}.mInverseIterations);
        }
        // Version 6 carries the one-sided dents flag (the bumper, recorded last, has it off).
        CHECK(replay.Get().mObjects[0].mSettings.mDeformer.mOneSidedDents);
        CHECK_FALSE(replay.Get().mObjects[2].mSettings.mDeformer.mOneSidedDents);
        // Version 8 carries the rigid parts.
        CHECK(replay.Get().mObjects[0].mSettings.mDeformer.mRigidParts.empty());
        CHECK(replay.Get().mObjects[2].mSettings.mDeformer.mRigidParts ==
              std::vector<std::vector<std::uint32_t>>{{0, 1, 2}, {5}});
        Result<std::vector<ReplayedObject>> objects = ReplayDamage(replay.Get());
        REQUIRE(objects);
        REQUIRE(objects.Get().size() == 3);
        std::vector<Vec3> replayed;
        for (const ReplayedObject& object : objects.Get())
        {
            const std::vector<Vec3>& p = object.mDeformable.GetDeformer().GetPositions();
            replayed.insert(replayed.end(), p.begin(), p.end());
        }
        CHECK(replayed == live); // all three objects, the late one included
    }
}

TEST_CASE("A truncated, corrupt or foreign replay file is refused with a clear message", "[plugin][replay]")
{
    const std::filesystem::path path = ScratchFile("refuse.crumple");
    RecordCrash(path, false);
    const std::vector<std::byte> bytes = ReadFileBytes(path).Get();

    for (std::size_t length = 0; length < bytes.size(); length += 1 + bytes.size() / 50)
    {
        Result<Replay> truncated = DecodeReplay(std::span(bytes).first(length));
        REQUIRE(truncated.HasError());
        CHECK(truncated.GetError().mCode == EError::CorruptData);
    }
    std::vector<std::byte> corrupt = bytes;
    corrupt[corrupt.size() / 2] ^= std::byte{0x40};
    Result<Replay> corrupted = DecodeReplay(corrupt);
    REQUIRE(corrupted.HasError());
    CHECK(corrupted.GetError().mMessage.find("record") != std::string::npos);

    std::vector<std::byte> newer = bytes;
    newer[8] = std::byte{static_cast<unsigned char>(cReplayVersion + 1)};
    CHECK(DecodeReplay(newer).GetError().mCode == EError::VersionMismatch);
    std::vector<std::byte> foreign = bytes;
    foreign[0] = std::byte{'Z'};
    CHECK(DecodeReplay(foreign).GetError().mCode == EError::CorruptData);
}

TEST_CASE("The replay fuzz regressions are in a format this library reads, so they reach the decoder", "[plugin][replay]")
{
    // A version bump that refuses an old file at its header would make the regression pass without testing
    // anything (the three files below sat at version 5 behind versions 6 and 7). They are at version 7, the
    // oldest DecodeReplay reads (version 8 added rigid parts): they also show that an old recording replays.
    // Convert them when the oldest version read moves past theirs. A file the decoder now refuses by its
    // contents (replay_huge_impulse: an impulse past what bodies produce) must be refused at that record, past
    // the header.
    int files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(CRUMPLE_SOURCE_DIR) / "fuzz/regressions/replay"))
    {
        const Result<Replay> replay = DecodeReplay(ReadFileBytes(entry.path()).Get());
        INFO(entry.path().filename().string() << ": " << (replay ? std::string("read") : replay.GetError().mMessage));
        if (entry.path().filename() == "replay_huge_impulse")
        {
            REQUIRE(replay.HasError());
            CHECK(replay.GetError().mCode == EError::CorruptData);
            CHECK(replay.GetError().mMessage.find("collision record") != std::string::npos);
        }
        else
        {
            REQUIRE(replay);
            CHECK_FALSE(replay.Get().mObjects.empty());
            CHECK_FALSE(replay.Get().mCollisions.empty());
            // Recorded before the occupant cell: they replay without one.
            for (const RecordedObject& object : replay.Get().mObjects)
                CHECK(object.mSettings.mMaterial.mCrushZoneFraction == 0.5);
        }
        ++files;
    }
    CHECK(files >= 3);
}

TEST_CASE("An interrupted recording never looks complete", "[plugin][replay]")
{
    const std::filesystem::path path = ScratchFile("interrupted.crumple");
    std::filesystem::remove(path);
    WorldFixture fixture;
    {
        std::unique_ptr<DamageRecorder> recorder = std::move(DamageRecorder::Create(path, fixture.mWorld).Get());
        CHECK(std::filesystem::exists(path.string() + ".partial"));
        CHECK_FALSE(std::filesystem::exists(path));
        // Without Close() the partial file alone stays incomplete: it has no end record.
        const std::vector<std::byte> partial = ReadFileBytes(path.string() + ".partial").Get();
        CHECK(DecodeReplay(partial).HasError());
    }
    CHECK(std::filesystem::exists(path)); // the destructor closes it properly
    CHECK(DecodeReplay(ReadFileBytes(path).Get()));
    CHECK(DamageRecorder::Create("/nonexistent-dir/x.crumple", fixture.mWorld).GetError().mCode == EError::IoError);
}

TEST_CASE("Extension records written together are the bytes of the same records written one by one", "[plugin][replay]")
{
    const std::vector<std::vector<std::byte>> payloads = {
        {std::byte{1}, std::byte{2}}, {}, {std::byte{0xFF}, std::byte{0}, std::byte{7}, std::byte{9}}};
    const std::filesystem::path one_by_one = ScratchFile("extensions_one_by_one.crumple");
    const std::filesystem::path together = ScratchFile("extensions_together.crumple");
    {
        WorldFixture fixture;
        std::unique_ptr<DamageRecorder> recorder = std::move(DamageRecorder::Create(one_by_one, fixture.mWorld).Get());
        for (const std::vector<std::byte>& payload : payloads)
            REQUIRE(recorder->WriteExtension(42u, payload));
        REQUIRE(recorder->Close());
    }
    {
        WorldFixture fixture;
        std::unique_ptr<DamageRecorder> recorder = std::move(DamageRecorder::Create(together, fixture.mWorld).Get());
        REQUIRE(recorder->WriteExtensions(42u, payloads));
        REQUIRE(recorder->WriteExtensions(43u, {})); // nothing to write: nothing written
        REQUIRE(recorder->Close());
        // Closed: refused, as WriteExtension is
        CHECK(recorder->WriteExtensions(42u, payloads).GetError().mCode == EError::InvalidArgument);
    }
    const std::vector<std::byte> expected = ReadFileBytes(one_by_one).Get();
    CHECK(ReadFileBytes(together).Get() == expected);
    const Replay replay = DecodeReplay(expected).Get();
    REQUIRE(replay.mExtensions.size() == payloads.size());
    for (std::size_t i = 0; i < payloads.size(); ++i)
    {
        CHECK(replay.mExtensions[i].mTag == 42u);
        CHECK(replay.mExtensions[i].mPayload == payloads[i]);
    }
}

TEST_CASE("A recorded collision beyond what bodies can produce is refused, and a hand-made one dents finitely", "[plugin][replay]")
{
    // A file of one collision (no object) and its end record.
    const auto file_of = [](const Collision& inCollision) {
        std::vector<std::byte> bytes = EncodeReplayHeader();
        const std::vector<std::byte> record = EncodeReplayRecord(EReplayRecord::Collision, EncodeCollision(inCollision));
        bytes.insert(bytes.end(), record.begin(), record.end());
        ByteWriter end;
        end.WriteU32(0);
        end.WriteU64(1);
        const std::vector<std::byte> closing = EncodeReplayRecord(EReplayRecord::End, end.GetBytes());
        bytes.insert(bytes.end(), closing.begin(), closing.end());
        return bytes;
    };
    Collision collision;
    CollisionContact contact;
    contact.mLocalPointOnA = contact.mLocalPointOnB = Vec3(2.0, 0.0, 0.0);
    contact.mLocalNormalOnA = Vec3::UnitX();
    contact.mLocalNormalOnB = -Vec3::UnitX();
    contact.mNormal = Vec3::UnitX();
    contact.mImpulse = 1.0e3;
    contact.mFriction = 0.5;
    contact.mFrictionImpulse = contact.mLocalFrictionOnA = Vec3(0.0, 300.0, 0.0);
    contact.mLocalFrictionOnB = Vec3(0.0, -300.0, 0.0);
    collision.mContacts = {contact, contact};
    const Result<Replay> read = DecodeReplay(file_of(collision));
    REQUIRE(read.IsValid());
    // The friction of a contact comes back as written (version 9).
    CHECK(read.Get().mCollisions[0].mContacts[1].mFriction == 0.5);
    CHECK(read.Get().mCollisions[0].mContacts[1].mFrictionImpulse == contact.mFrictionImpulse);
    CHECK(read.Get().mCollisions[0].mContacts[1].mLocalFrictionOnB == contact.mLocalFrictionOnB);

    // Friction outside its cone |t| <= mu j, a negative or NaN coefficient, a non-finite impulse: refused.
    for (const auto& spoil : std::vector<std::function<void(CollisionContact&)>>{
             [](CollisionContact& c) { c.mFrictionImpulse = Vec3(0.0, 600.0, 0.0); },
             [](CollisionContact& c) { c.mFriction = -0.5; },
             [](CollisionContact& c) { c.mFriction = std::nan(""); },
             [](CollisionContact& c) { c.mLocalFrictionOnA.z() = std::numeric_limits<double>::infinity(); }})
    {
        Collision spoiled = collision;
        spoil(spoiled.mContacts[0]);
        CHECK(DecodeReplay(file_of(spoiled)).GetError().mCode == EError::CorruptData);
    }
    Collision sticky = collision;
    sticky.mContacts[0].mFriction = std::numeric_limits<double>::infinity(); // a surface that never slides
    CHECK(DecodeReplay(file_of(sticky)).IsValid());

    Collision huge = collision;
    huge.mContacts[1].mImpulse = 1.0e308; // finite, far past the 1e28 N s bodies can produce
    CHECK(DecodeReplay(file_of(huge)).GetError().mCode == EError::CorruptData);
    Collision timeless = collision;
    timeless.mContacts[0].mTime = std::numeric_limits<double>::infinity();
    CHECK(DecodeReplay(file_of(timeless)).GetError().mCode == EError::CorruptData);
    Collision pointless = collision;
    pointless.mContacts[0].mPointOnB.y() = std::nan("");
    CHECK(DecodeReplay(file_of(pointless)).GetError().mCode == EError::CorruptData);

    // Handed straight to an object (impulse-factor dents), impulses whose weighted sum overflows still make a
    // finite dent of the material's maximum depth along their common normal.
    DeformableObjectSettings settings;
    settings.mMesh = MakeBoxMesh(Vec3(2.0, 0.8, 0.6), {8, 4, 4});
    settings.mMaterial.mModel = ECrushModel::ImpulseFactor;
    DeformableObject object = DeformableObject::Create(settings).Get();
    huge.mContacts[0].mImpulse = 1.0e308;
    const std::vector<ffd::PointDisplacement> dent = object.DentFor(huge, ECollisionSide::A);
    REQUIRE(dent.size() == 2);
    for (const ffd::PointDisplacement& point : dent)
        CHECK(point.mDisplacement == settings.mMaterial.mMaxInstantDeformation * contact.mLocalNormalOnA);
    for (const Vec3& position : object.GetDeformer().GetPositions())
        CHECK(IsFinite(position));
    // ApplyCollision itself refuses impulses past what a replay may hold (cMaxCollisionImpulse), denting
    // nothing.
    const std::vector<Vec3> before = object.GetDeformer().GetPositions();
    CHECK(object.ApplyCollision(huge, ECollisionSide::A).GetError().mCode == EError::OutOfRange);
    CHECK(object.GetDeformer().GetPositions() == before);
}
