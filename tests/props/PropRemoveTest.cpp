// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// PropWorld::RemoveProp: a race restarted or a prop streamed out. The removed prop steps no more and takes no
// hit, its id answers as an unknown prop's, a fresh prop may take its body, and a recording replays the
// removal where it happened.
#include "BrittlePanel.h"
#include "GpuFallback.h"
#include "RecordedPropWorld.h"
#include "ScratchDirectory.h"
#include "WallPanelMesh.h"
#include "WorldFixture.h"

#include <crumple/base/ByteWriter.h>
#include <crumple/base/FileBytes.h>
#include <crumple/plugin/DamageRecorder.h>
#include <crumple/props/HeldPropBodies.h>
#include <crumple/props/PropRecording.h>
#include <crumple/props/PropWorld.h>

#if defined(CRUMPLE_TEST_PROPS_WITH_GPU)
#include <crumple/gpu/ComputeDevice.h>
#endif

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstring>

using namespace crumple;
using namespace crumple::fem;
using namespace crumple::plugin;
using namespace crumple::props;

namespace
{

// One hit of the car on the wall at 20 m/s (two contacts at inTime), dispatched at once.
void HitWall(common::WorldFixture& ioFixture, double inTime)
{
    REQUIRE(ioFixture.mWorld.SetBodyState(ioFixture.mCar, ioFixture.CarState(20.0)));
    REQUIRE(ioFixture.mWorld.SubmitContacts(std::vector<ContactEvent>{
        ioFixture.FrontContact(0.3, 0.2, inTime), ioFixture.FrontContact(-0.4, -0.1, inTime)}));
    ioFixture.mWorld.Flush();
}

// inSteps steps of 1/120 s; how many props integrated (awake) over them.
int StepProps(PropWorld& ioProps, int inSteps)
{
    int stepped = 0;
    for (int step = 0; step < inSteps; ++step)
    {
        Result<PropStepReport> report = ioProps.Step(1.0 / 120.0);
        REQUIRE(report.IsValid());
        stepped += report.Get().mStepped;
    }
    return stepped;
}

} // namespace

TEST_CASE(
    "PropWorld::RemoveProp: the prop steps no more and takes no hit, its id answers as an unknown prop's, "
    "and a fresh prop takes its body",
    "[props]")
{
    common::WorldFixture fixture;
    std::unique_ptr<PropWorld> props = PropWorld::Create(fixture.mWorld).Get();
    const PropId wall = props->AddProp(fixture.mWall, test::WeakPanel()).Get();
    HitWall(fixture, 0.0);
    REQUIRE(props->GetCollisionCount() == 1u);
    REQUIRE(StepProps(*props, 3) == 3); // struck: awake

    REQUIRE(props->RemoveProp(wall).IsValid());
    CHECK(props->GetProp(wall) == nullptr);
    CHECK_FALSE(props->GetBody(wall).IsValid());
    CHECK_FALSE(props->FindProp(fixture.mWall).IsValid());
    CHECK(props->GetPropCount() == 1); // ids are not reused
    CHECK(props->GetContactVelocity(wall) == Vec3::Zero());
    CHECK(props->GetTakenElements(wall).empty());
    CHECK(props->GetCollisionPieces(wall, 0.25).GetError().mCode == EError::OutOfRange);
    CHECK(props->TakeChangedShape(wall, 0.25, 0.01).GetError().mCode == EError::OutOfRange);
    CHECK(props->TakeLooseFragments().Get().empty());
    CHECK(props->Prepare(1.0 / 120.0).IsValid());

    // The struck prop would have stepped on: removed, nothing steps, sleeps or takes the next hit.
    const PropStepReport after = props->Step(1.0 / 120.0).Get();
    CHECK(after.mStepped == 0);
    CHECK(after.mSleeping == 0);
    HitWall(fixture, 0.1);
    CHECK(props->GetCollisionCount() == 1u);

    // Removing it again, or an id never handed out, is refused.
    CHECK(props->RemoveProp(wall).GetError().mCode == EError::InvalidArgument);
    CHECK(props->RemoveProp(PropId{7}).GetError().mCode == EError::OutOfRange);

    // A fresh prop takes the body under a new id and the next hit.
    const PropId fresh = props->AddProp(fixture.mWall, test::WeakPanel()).Get();
    CHECK(fresh.mValue == 1u);
    CHECK(props->FindProp(fixture.mWall) == fresh);
    HitWall(fixture, 0.2);
    CHECK(props->GetCollisionCount() == 2u);
    CHECK(StepProps(*props, 1) == 1);
}

TEST_CASE("PropWorld::RemoveProp is refused while a step is in flight, changing nothing", "[props]")
{
    common::WorldFixture fixture;
    std::unique_ptr<PropWorld> props = PropWorld::Create(fixture.mWorld).Get();
    const PropId wall = props->AddProp(fixture.mWall, test::WeakPanel()).Get();
    HitWall(fixture, 0.0);
    REQUIRE(props->StartStep(1.0 / 120.0).IsValid());
    const Status refused = props->RemoveProp(wall);
    CHECK(refused.GetError().mCode == EError::InvalidArgument);
    CHECK(refused.GetError().mMessage.find("LandStep") != std::string::npos);
    REQUIRE(props->LandStep().IsValid());
    CHECK(props->GetProp(wall) != nullptr);
    CHECK(props->RemoveProp(wall).IsValid());
}

TEST_CASE("PropWorld::RemoveProp off the game's thread: a hit queued for the removed prop reaches no prop",
          "[props]")
{
    common::WorldFixture fixture;
    std::unique_ptr<PropWorld> props = PropWorld::Create(fixture.mWorld, {.mStepOffThread = true}).Get();
    const PropId wall = props->AddProp(fixture.mWall, test::WeakPanel()).Get();
    HitWall(fixture, 0.0);
    REQUIRE(props->GetQueuedCollisionCount() == 1u); // waits for the next step
    REQUIRE(props->RemoveProp(wall).IsValid());
    // A fresh prop on the same body joined after the hit was dispatched: it is not its hit either.
    const PropId fresh = props->AddProp(fixture.mWall, test::WeakPanel()).Get();
    const PropStepReport report = props->Step(1.0 / 120.0).Get();
    CHECK(props->GetCollisionCount() == 0u);
    CHECK(report.mStepped == 0);
    CHECK(props->GetContactVelocity(fresh) == Vec3::Zero());
    HitWall(fixture, 0.1);
    CHECK(StepProps(*props, 1) == 1);
    CHECK(props->GetCollisionCount() == 1u);
}

TEST_CASE(
    "PropWorld::RemoveProp in a recording: the replay stops the prop where it was removed and replays the "
    "fresh one bit for bit, and refuses bad removal records",
    "[props][replay]")
{
    test::RecordedPropWorld recorded("props_removed.crumple");
    const std::filesystem::path& path = recorded.mPath;
    common::WorldFixture& fixture = recorded.mFixture;
    PropWorld* const props = recorded.mProps.get();

    // The first panel cracks, is removed mid-swing (it would have stepped on), and misses the next hit; a
    // fresh panel on the same body takes it.
    const PropId first = props->AddProp(fixture.mWall, test::WeakPanel()).Get();
    HitWall(fixture, 0.0);
    REQUIRE(StepProps(*props, 4) == 4);
    const std::vector<Vec3> removed_positions = props->GetProp(first)->GetCpuSolver()->GetPositions();
    const int removed_broken = props->GetProp(first)->GetBrokenLinkCount();
    REQUIRE(removed_broken > 0);
    REQUIRE(props->RemoveProp(first).IsValid());
    HitWall(fixture, 0.1);
    StepProps(*props, 2);
    const PropId second = props->AddProp(fixture.mWall, test::WeakPanel()).Get();
    HitWall(fixture, 0.2);
    REQUIRE(StepProps(*props, 4) == 4);
    recorded.Finish();

    // A recorder attached after a removal would number the props otherwise than the live world.
    std::unique_ptr<DamageRecorder> late = std::move(
        DamageRecorder::Create(common::ScratchDirectory() / "props_late.crumple", fixture.mWorld).Get());
    CHECK(props->AttachRecorder(late.get()).GetError().mMessage.find("RemoveProp") != std::string::npos);

    const Replay replay = DecodeReplay(ReadFileBytes(path).Get()).Get();
    const std::vector<ReplayedProp> replayed = ReplayProps(replay).Get();
    REQUIRE(replayed.size() == 2u);
    CHECK(replayed[0].mRemoved);
    CHECK(replayed[0].mProp.GetCpuSolver()->GetPositions() == removed_positions);
    CHECK(replayed[0].mProp.GetBrokenLinkCount() == removed_broken);
    CHECK_FALSE(replayed[1].mRemoved);
    const TetSolver& live = *props->GetProp(second)->GetCpuSolver();
    CHECK(replayed[1].mProp.GetCpuSolver()->GetPositions() == live.GetPositions());
    CHECK(replayed[1].mProp.GetCpuSolver()->GetBrokenLinks() == live.GetBrokenLinks());

    // The removal record: of a prop not yet added, of a removed one, or of the wrong length.
    std::size_t removal = replay.mExtensions.size();
    for (std::size_t index = 0; index < replay.mExtensions.size(); ++index)
        if (replay.mExtensions[index].mTag == static_cast<std::uint32_t>(EPropRecord::Removed))
            removal = index;
    REQUIRE(removal < replay.mExtensions.size());
    const auto refused = [&](const Replay& inReplay)
    {
        Result<std::vector<ReplayedProp>> result = ReplayProps(inReplay);
        REQUIRE(result.HasError());
        CHECK(result.GetError().mCode == EError::CorruptData);
        CHECK(result.GetError().mMessage.find("removal") != std::string::npos);
    };
    Replay unknown = replay;
    ByteWriter prop_one;
    prop_one.WriteU32(1); // prop 1 joins after the removal
    unknown.mExtensions[removal].mPayload = prop_one.GetBytes();
    refused(unknown);
    Replay twice = replay;
    twice.mExtensions.insert(twice.mExtensions.begin() + static_cast<std::ptrdiff_t>(removal) + 1,
                             replay.mExtensions[removal]);
    refused(twice);
    Replay short_record = replay;
    short_record.mExtensions[removal].mPayload.pop_back();
    refused(short_record);
}

TEST_CASE(
    "HeldPropBodies after RemoveProp: the held body the game keeps is put back at rest with its own mass "
    "once, and then nothing",
    "[props]")
{
    common::WorldFixture fixture;
    std::unique_ptr<PropWorld> props = PropWorld::Create(fixture.mWorld, {.mContactMass = true}).Get();
    const PropId wall = props->AddProp(fixture.mWall, test::WeakPanel()).Get();
    std::vector<BodyId> shapes, velocity_bodies, mass_bodies;
    std::vector<Vec3> velocities;
    std::vector<double> masses;
    HeldPropEngine engine{.mCreatePieceBody = [](const ConvexBodySettings&) -> Result<BodyId> {
                              return BodyId{1000, 0};
                          },
                          .mSetPropPieces =
                              [&](BodyId inBody, const std::vector<std::vector<Vec3>>&)
                          {
                              shapes.push_back(inBody);
                              return Status::Ok();
                          },
                          .mSetHeldVelocity =
                              [&](BodyId inBody, const Vec3& inVelocity)
                          {
                              velocity_bodies.push_back(inBody);
                              velocities.push_back(inVelocity);
                              return Status::Ok();
                          },
                          .mSetHeldMass =
                              [&](BodyId inBody, double inMass)
                          {
                              mass_bodies.push_back(inBody);
                              masses.push_back(inMass);
                              return Status::Ok();
                          },
                          .mIsHeld = nullptr};
    // intent: its piece bodies are not the world's (the engine here only counts): not made quiet
    HeldPropBodies held = HeldPropBodies::Create(*props, engine, {.mQuietPieces = false}).Get();
    HitWall(fixture, 0.0);
    HeldPropUpdate update;
    REQUIRE(held.Update(props->Step(1.0 / 120.0).Get(), update).IsValid());
    // The struck prop's body got its shape, the struck members' velocity and their mass.
    REQUIRE_FALSE(shapes.empty());
    REQUIRE_FALSE(velocities.empty());
    REQUIRE(velocities.back() != Vec3::Zero());
    REQUIRE_FALSE(masses.empty());
    REQUIRE(masses.back() > 0.0);

    shapes.clear();
    velocity_bodies.clear();
    velocities.clear();
    mass_bodies.clear();
    masses.clear();
    REQUIRE(props->RemoveProp(wall).IsValid());
    for (int step = 0; step < 3; ++step)
        REQUIRE(held.Update(props->Step(1.0 / 120.0).Get(), update).IsValid());
    CHECK(shapes.empty());
    REQUIRE(velocities.size() == 1u);
    CHECK(velocity_bodies[0] == fixture.mWall);
    CHECK(velocities[0] == Vec3::Zero());
    REQUIRE(masses.size() == 1u);
    CHECK(mass_bodies[0] == fixture.mWall);
    CHECK(masses[0] == 0.0); // its own mass again
}

TEST_CASE("PropWorld::RemoveProp is refused, changing nothing, while the recorder cannot write", "[props]")
{
    test::RecordedPropWorld recorded("props_closed.crumple");
    common::WorldFixture& fixture = recorded.mFixture;
    DamageRecorder* const recorder = recorded.mRecorder.get();
    PropWorld* const props = recorded.mProps.get();
    const PropId wall = props->AddProp(fixture.mWall, test::WeakPanel()).Get();
    REQUIRE(recorder->Close().IsValid());
    CHECK(props->RemoveProp(wall).HasError());
    CHECK(props->GetProp(wall) != nullptr);
    CHECK(props->FindProp(fixture.mWall) == wall);
    // Detached, the prop can go.
    REQUIRE(props->AttachRecorder(nullptr).IsValid());
    CHECK(props->RemoveProp(wall).IsValid());
}

TEST_CASE(
    "PropWorld::RemoveProp off the game's thread in a recording: the replay drops the hit queued for the "
    "removed prop as live did",
    "[props][replay]")
{
    test::RecordedPropWorld recorded("props_removed_queued.crumple", {.mStepOffThread = true});
    const std::filesystem::path& path = recorded.mPath;
    common::WorldFixture& fixture = recorded.mFixture;
    PropWorld* const props = recorded.mProps.get();
    const PropId first = props->AddProp(fixture.mWall, test::WeakPanel()).Get();
    HitWall(fixture, 0.0);
    REQUIRE(StepProps(*props, 3) == 3);
    const std::vector<Vec3> removed_positions = props->GetProp(first)->GetCpuSolver()->GetPositions();
    HitWall(fixture, 0.1); // queued for the next step: the prop goes before it
    REQUIRE(props->RemoveProp(first).IsValid());
    const PropId second = props->AddProp(fixture.mWall, test::WeakPanel()).Get();
    StepProps(*props, 1);
    HitWall(fixture, 0.2);
    REQUIRE(StepProps(*props, 3) == 3);
    recorded.Finish();
    CHECK(props->GetCollisionCount() == 2u); // the first hit and the third; the second reached no prop

    const std::vector<ReplayedProp> replayed =
        ReplayProps(DecodeReplay(ReadFileBytes(path).Get()).Get()).Get();
    REQUIRE(replayed.size() == 2u);
    CHECK(replayed[0].mRemoved);
    CHECK(replayed[0].mProp.GetCpuSolver()->GetPositions() == removed_positions);
    CHECK(replayed[1].mProp.GetCpuSolver()->GetPositions() ==
          props->GetProp(second)->GetCpuSolver()->GetPositions());
}

TEST_CASE("PropWorld::RemoveProp of a GPU prop frees it, and a fresh GPU prop then steps on the same device",
          "[props][gpu]")
{
#if defined(CRUMPLE_TEST_PROPS_WITH_GPU)
    gpu::ComputeDeviceProvider provider;
    gpu::ComputeDeviceProvider* devices = &provider;
#else
    gpu::ComputeDeviceProvider* devices = nullptr;
#endif
    TetSolverSettings explicit_steps;
    explicit_steps.mIntegrator = EIntegrator::SymplecticEuler;
    explicit_steps.mGravity = Vec3::Zero();
    const auto gpu_panel = [&]
    {
        Result<FemProp> made =
            FemProp::Create(devices, test::WallPanelMesh({1, 4, 4}), FemMaterialSettings{}, explicit_steps,
                            {.mBackend = EFemBackend::Gpu, .mLog = nullptr});
        REQUIRE(made.IsValid());
        return std::move(made).Get();
    };
#if defined(CRUMPLE_TEST_PROPS_WITH_GPU)
    // What holds the device (shared_ptr): the provider, and every buffer and program made on it. Counted the
    // same way each time (the provider's Result holds one more while it lives).
    const auto device_holders = [&]() -> long
    {
        Result<std::shared_ptr<gpu::ComputeDevice>> device = provider.Acquire();
        return device ? device.Get().use_count() : 0;
    };
#else
    const auto device_holders = [] { return 0L; };
#endif
    const long idle = device_holders();
    FemProp first = gpu_panel();
    if (first.GetBackend() != EFemBackend::Gpu)
    {
        test::RequireNoComputeDevice(devices, first.GetFallbackReason());
        WARN("skipped: no compute device: " << first.GetFallbackReason());
        return;
    }
    common::WorldFixture fixture;
    std::unique_ptr<PropWorld> props = PropWorld::Create(fixture.mWorld).Get();
    const PropId wall = props->AddProp(fixture.mWall, std::move(first)).Get();
    HitWall(fixture, 0.0);
    REQUIRE(StepProps(*props, 2) == 2);
    CHECK(device_holders() > idle); // the prop's buffers and programs
    REQUIRE(props->RemoveProp(wall).IsValid());
    CHECK(props->GetProp(wall) == nullptr);
    CHECK(device_holders() == idle); // all of them released with it
    CHECK(StepProps(*props, 1) == 0);

    const PropId fresh = props->AddProp(fixture.mWall, gpu_panel()).Get();
    REQUIRE(props->GetProp(fresh)->GetBackend() == EFemBackend::Gpu);
    HitWall(fixture, 0.1);
    CHECK(StepProps(*props, 2) == 2);
    std::vector<Vec3> velocities;
    props->GetProp(fresh)->ReadVelocities(velocities);
    double fastest = 0.0;
    for (const Vec3& velocity : velocities)
        fastest = std::max(fastest, velocity.norm());
    CHECK(fastest > 0.0); // the fresh prop took the hit on the device
}
