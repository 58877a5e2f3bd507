// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// Props in a damage recording: a run with a prop that cracks, replayed without an engine, ends bit for bit.
#include "BrittlePanel.h"
#include "CountingJobs.h"
#include "RecordedPropWorld.h"
#include "ScratchDirectory.h"
#include "ThreadJobSystem.h"
#include "WallPanelMesh.h"
#include "WorldFixture.h"

#include <crumple/base/FileBytes.h>
#include <crumple/fem/TetGrid.h>
#include <crumple/plugin/DamageRecorder.h>
#include <crumple/props/PropRecording.h>
#include <crumple/props/PropWorld.h>

#if defined(CRUMPLE_TEST_PROPS_WITH_GPU)
#include <crumple/gpu/ComputeDevice.h>
#include <crumple/gpu/GpuTetSolver.h>
#endif

#include "GpuFallback.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <optional>

using namespace crumple;
using namespace crumple::fem;
using namespace crumple::plugin;
using namespace crumple::props;

namespace
{

// The panel of these tests: stiff (10 GPa) at the shared brittle strength, 10 x 10 cells.
props::FemProp BrittlePanel()
{
    return test::BrittlePanel({1, 10, 10}, 1.0e10, 1.0);
}

// The car's two hits on the wall a few steps apart, the props stepping six steps of 1/120 s after each;
// returns how many props fractured over the steps.
int HitTwice(common::WorldFixture& ioFixture, PropWorld& ioProps)
{
    int fractured = 0;
    for (int hit = 0; hit < 2; ++hit)
    {
        REQUIRE(ioFixture.mWorld.SetBodyState(ioFixture.mCar, ioFixture.CarState(15.0 + 5.0 * hit)));
        REQUIRE(ioFixture.mWorld.SubmitContacts(std::vector<ContactEvent>{
            ioFixture.FrontContact(0.3 - 0.5 * hit, 0.2, 0.1 * hit), ioFixture.FrontContact(-0.4, -0.1, 0.1 * hit)}));
        ioFixture.mWorld.Flush();
        for (int step = 0; step < 6; ++step)
        {
            Result<PropStepReport> stepped = ioProps.Step(1.0 / 120.0);
            REQUIRE(stepped.IsValid());
            fractured += stepped.Get().mFractured;
        }
    }
    return fractured;
}

} // namespace

TEST_CASE("Props in a recording: a cracking prop replays bit for bit without an engine", "[props][replay]")
{
    const std::filesystem::path path = common::ScratchDirectory() / "props.crumple";
    common::WorldFixture fixture;
    std::unique_ptr<DamageRecorder> recorder = std::move(DamageRecorder::Create(path, fixture.mWorld).Get());
    std::unique_ptr<PropWorld> props = PropWorld::Create(fixture.mWorld).Get();
    REQUIRE(props->AttachRecorder(recorder.get()).IsValid());
    const PropId wall = props->AddProp(fixture.mWall, BrittlePanel()).Get();

    const int fractured = HitTwice(fixture, *props);
    REQUIRE(props->AttachRecorder(nullptr).IsValid());
    REQUIRE(recorder->Close().IsValid());
    const TetSolver& live = *props->GetProp(wall)->GetCpuSolver();
    REQUIRE(fractured > 0); // the run really cracked the prop
    REQUIRE(live.GetBrokenLinkCount() > 0);

    const Replay replay = DecodeReplay(ReadFileBytes(path).Get()).Get();
    CHECK(replay.mCollisions.size() == 2u);
    CHECK(replay.mExtensions.size() == 13u); // one prop, 12 steps
    const std::vector<ReplayedProp> replayed = ReplayProps(replay).Get();
    REQUIRE(replayed.size() == 1u);
    REQUIRE(replayed[0].mProp.GetCpuSolver() != nullptr);
    const TetSolver& again = *replayed[0].mProp.GetCpuSolver();
    CHECK(replayed[0].mBody == fixture.mWall);
    CHECK(again.GetBrokenLinks() == live.GetBrokenLinks());
    CHECK(again.GetElementNodes() == live.GetElementNodes());
    CHECK(again.GetPositions() == live.GetPositions());
    CHECK(again.GetVelocities() == live.GetVelocities());
    const std::vector<TetFragment> live_pieces = live.ComputeFragments();
    const std::vector<TetFragment> replayed_pieces = again.ComputeFragments();
    REQUIRE(replayed_pieces.size() == live_pieces.size());
    for (std::size_t piece = 0; piece < live_pieces.size(); ++piece)
    {
        CHECK(replayed_pieces[piece].mGroups == live_pieces[piece].mGroups);
        CHECK(replayed_pieces[piece].mMass == live_pieces[piece].mMass);
        CHECK(replayed_pieces[piece].mCenterOfMass == live_pieces[piece].mCenterOfMass);
    }
}

TEST_CASE(
    "Props in a recording: replayed with the element passes on a 2-thread job system, bit for bit as on one",
    "[props][replay]")
{
    // A panel of 4,500 tetrahedra: more than two pieces' worth of elements (2,048 each), so its passes split.
    test::RecordedPropWorld recorded("props_large.crumple");
    const std::filesystem::path& path = recorded.mPath;
    common::WorldFixture& fixture = recorded.mFixture;
    PropWorld* const props = recorded.mProps.get();
    const PropId wall = props->AddProp(fixture.mWall, test::BrittlePanel({1, 30, 30}, 1.0e10, 1.0)).Get();
    REQUIRE(props->GetProp(wall)->GetElementNodes().size() > 4096u);
    REQUIRE(HitTwice(fixture, *props) > 0); // it cracked
    recorded.Finish();
    const Replay replay = DecodeReplay(ReadFileBytes(path).Get()).Get();

    // The host's parallel fors counted, run on two threads.
    common::CountingJobs counted(2);
    const std::vector<ReplayedProp> serial = ReplayProps(replay).Get();
    const std::vector<ReplayedProp> parallel = ReplayProps(replay, nullptr, &counted.Get()).Get();
    CHECK(counted.GetCalls() > 0);
    REQUIRE(serial.size() == 1u);
    REQUIRE(parallel.size() == 1u);
    const TetSolver& live = *props->GetProp(wall)->GetCpuSolver();
    REQUIRE(live.GetBrokenLinkCount() > 0);
    CHECK(serial[0].mProp.GetCpuSolver()->GetPositions() == live.GetPositions());
    CHECK(parallel[0].mProp.GetCpuSolver()->GetPositions() == live.GetPositions());
    CHECK(parallel[0].mProp.GetCpuSolver()->GetVelocities() == live.GetVelocities());
    CHECK(parallel[0].mProp.GetCpuSolver()->GetBrokenLinks() == live.GetBrokenLinks());
}

TEST_CASE("Props in a recording: a prop that cannot be replayed exactly is refused, and bad records too",
          "[props][replay]")
{
    common::WorldFixture fixture;
    const std::filesystem::path path = common::ScratchDirectory() / "props_refused.crumple";
    std::unique_ptr<DamageRecorder> recorder = std::move(DamageRecorder::Create(path, fixture.mWorld).Get());
    std::unique_ptr<PropWorld> props = PropWorld::Create(fixture.mWorld).Get();

    // A prop that has stepped carries warm starts a rebuilt one would not: attaching is refused, nothing written.
    // (Struck first: one at rest without gravity would fall asleep at its first step, doing nothing.)
    const PropId panel = props->AddProp(fixture.mWall, BrittlePanel()).Get();
    REQUIRE(props->GetProp(panel)->ApplyImpulse(props->GetProp(panel)->GetNodeCount() - 1, Vec3(0.1, 0.0, 0.0)).IsValid());
    REQUIRE(props->Step(1.0 / 60.0).IsValid());
    REQUIRE(props->GetProp(panel)->GetCpuSolver() != nullptr);
    REQUIRE(props->GetProp(panel)->GetCpuSolver()->GetElementWorkCount() > 0u);
    CHECK(props->AttachRecorder(recorder.get()).HasError());
    REQUIRE(recorder->Close().IsValid());
    CHECK(DecodeReplay(ReadFileBytes(path).Get()).Get().mExtensions.empty());

    // A truncated or foreign prop record is refused with the record's index.
    Replay replay;
    RecordedExtension bad;
    bad.mTag = static_cast<std::uint32_t>(EPropRecord::Added);
    bad.mPayload = std::vector<std::byte>(10, std::byte{0x7f});
    replay.mExtensions.push_back(bad);
    Result<std::vector<ReplayedProp>> refused = ReplayProps(replay);
    REQUIRE(refused.HasError());
    CHECK(refused.GetError().mMessage.find("prop record 0") != std::string::npos);
    bad.mTag = static_cast<std::uint32_t>(EPropRecord::Step);
    bad.mPayload = std::vector<std::byte>(3, std::byte{0});
    replay.mExtensions = {bad};
    CHECK(ReplayProps(replay).HasError());
    // Another layer's record is left alone.
    bad.mTag = 0x12345678u;
    replay.mExtensions = {bad};
    CHECK(ReplayProps(replay).IsValid());
}

namespace
{

// What a run of PropRecordingTest's two hits, with the world updated every step, leaves: the prop's
// positions and the recording's bytes.
struct SteppedRun
{
    std::vector<Vec3> mPositions;
    std::vector<std::byte> mRecording;
    int mBrokenLinks = 0;
};

SteppedRun RunWithUpdates(const std::filesystem::path& inPath, bool inDeferDents)
{
    const common::ThreadJobSystem jobs(2);
    DamageWorldSettings settings;
    settings.mJobs = inDeferDents ? &jobs.Get() : nullptr;
    settings.mDeferDents = inDeferDents;
    common::WorldFixture fixture(4000, {8, 6, 6}, settings);
    std::unique_ptr<DamageRecorder> recorder = std::move(DamageRecorder::Create(inPath, fixture.mWorld).Get());
    std::unique_ptr<PropWorld> props = PropWorld::Create(fixture.mWorld).Get();
    REQUIRE(props->AttachRecorder(recorder.get()).IsValid());
    const PropId wall = props->AddProp(fixture.mWall, BrittlePanel()).Get();
    // A game's frame: contacts at the first and the 13th step, the world's Update, then the props' step.
    const double dt = 1.0 / 120.0;
    for (int step = 0; step < 24; ++step)
    {
        const double time = step * dt;
        if (step == 0 || step == 12)
        {
            const int hit = step / 12;
            REQUIRE(fixture.mWorld.SetBodyState(fixture.mCar, fixture.CarState(15.0 + 5.0 * hit)));
            REQUIRE(fixture.mWorld.SubmitContacts(std::vector<ContactEvent>{
                fixture.FrontContact(0.3 - 0.5 * hit, 0.2, time), fixture.FrontContact(-0.4, -0.1, time)}));
        }
        fixture.mWorld.Update(time);
        REQUIRE(props->Step(dt).IsValid());
    }
    fixture.mWorld.Flush();
    REQUIRE(props->AttachRecorder(nullptr).IsValid());
    REQUIRE(recorder->Close().IsValid());
    const TetSolver& solver = *props->GetProp(wall)->GetCpuSolver();
    return {solver.GetPositions(), ReadFileBytes(inPath).Get(), solver.GetBrokenLinkCount()};
}

} // namespace

TEST_CASE("Props in a recording: deferred dents hand the props the same hits at the same Update, and record the same bytes",
          "[props][replay]")
{
    // A prop takes a collision when the world dispatches it, not when the car's dent lands an Update later;
    // the recorder writes it then too. So a game that defers dents gets the same props and the same file.
    const SteppedRun inline_run = RunWithUpdates(common::ScratchDirectory() / "props_inline.crumple", false);
    const SteppedRun deferred = RunWithUpdates(common::ScratchDirectory() / "props_deferred.crumple", true);
    REQUIRE(inline_run.mBrokenLinks > 0); // the hits reached the prop and cracked it
    CHECK(deferred.mBrokenLinks == inline_run.mBrokenLinks);
    CHECK(deferred.mPositions == inline_run.mPositions);
    CHECK(deferred.mRecording == inline_run.mRecording);
    // And the recording replays to the live prop.
    const std::vector<ReplayedProp> replayed = ReplayProps(DecodeReplay(deferred.mRecording).Get()).Get();
    REQUIRE(replayed.size() == 1u);
    CHECK(replayed[0].mProp.GetCpuSolver()->GetPositions() == deferred.mPositions);
}

#if defined(CRUMPLE_TEST_PROPS_WITH_GPU)
namespace
{

// A brittle panel of inCells cubes on the GPU (E = 100 MPa, nu = 0.2, inStrengthScale times the brittle
// material's tensile strength), anchored along its base, hit twice by the car while recorded to inFile.
// Members in the order they must outlive each other: the device, the world, the props.
struct RecordedGpuPanel
{
    std::unique_ptr<gpu::ComputeDeviceProvider> mDevices = std::make_unique<gpu::ComputeDeviceProvider>();
    std::unique_ptr<common::WorldFixture> mFixture = std::make_unique<common::WorldFixture>();
    std::unique_ptr<PropWorld> mProps;
    PropId mWall;
    Replay mReplay;

    const FemProp& Live() const { return *mProps->GetProp(mWall); }
};

// Empty (and a warning) when no compute device is there.
std::optional<RecordedGpuPanel> RecordGpuPanel(const std::array<int, 3>& inCells, double inStrengthScale,
                                               const fem::TetSolverSettings& inSettings, const char* inFile)
{
    RecordedGpuPanel run;
    fem::FemMaterialSettings material = common::BrittleMaterial(fem::EFractureMode::CrackPlane);
    material.mYoungsModulus = 1.0e8;
    material.mPoissonRatio = 0.2;
    material.mTensileStrength *= inStrengthScale;
    FemPropSettings on_gpu;
    on_gpu.mBackend = EFemBackend::Gpu;
    FemProp panel =
        FemProp::Create(run.mDevices.get(), test::WallPanelMesh(inCells), material, inSettings, on_gpu).Get();
    if (panel.GetBackend() != EFemBackend::Gpu)
    {
        test::RequireNoComputeDevice(run.mDevices.get(), panel.GetFallbackReason());
        WARN("skipped: no compute device: " << panel.GetFallbackReason());
        return std::nullopt;
    }
    std::vector<int> base;
    for (int node = 0; node < panel.GetNodeCount(); ++node)
        if (panel.GetGpuSolver()->GetMesh().GetRestPositions()[static_cast<std::size_t>(node)].z() < -0.99)
            base.push_back(node);
    for (int node : base)
        REQUIRE(panel.SetNodeFixed(node, true).IsValid());

    const std::filesystem::path path = common::ScratchDirectory() / inFile;
    std::unique_ptr<DamageRecorder> recorder =
        std::move(DamageRecorder::Create(path, run.mFixture->mWorld).Get());
    run.mProps = PropWorld::Create(run.mFixture->mWorld).Get();
    REQUIRE(run.mProps->AttachRecorder(recorder.get()).IsValid());
    run.mWall = run.mProps->AddProp(run.mFixture->mWall, std::move(panel)).Get();
    HitTwice(*run.mFixture, *run.mProps);
    REQUIRE(run.mProps->AttachRecorder(nullptr).IsValid());
    REQUIRE(recorder->Close().IsValid());
    run.mReplay = DecodeReplay(ReadFileBytes(path).Get()).Get();
    return run;
}

} // namespace

TEST_CASE("Props in a recording: a GPU prop replays bit for bit on a device, and on the CPU without one",
          "[props][replay][gpu]")
{
    // The brittle panel on the GPU: symplectic Euler (the GPU's integrator), soft enough for a few sub-steps
    // per step, weak enough that the car's hits crack it.
    fem::TetSolverSettings settings;
    settings.mIntegrator = fem::EIntegrator::SymplecticEuler;
    settings.mGravity = Vec3::Zero();
    const std::optional<RecordedGpuPanel> run =
        RecordGpuPanel({1, 6, 6}, 0.05, settings, "props_gpu.crumple");
    if (!run)
        return;
    const FemProp& live = run->Live();
    std::vector<Vec3> live_positions;
    live.ReadPositions(live_positions);
    REQUIRE(live.GetBrokenLinkCount() > 0); // the run really cracked the prop

    const Replay& replay = run->mReplay;
    // On a device: the same floats, the same cracks, the same pieces.
    {
        // A device of its own, as a replay tool makes (nothing shared with the live run's context).
        gpu::ComputeDeviceProvider replay_devices;
        const std::vector<ReplayedProp> replayed = ReplayProps(replay, &replay_devices).Get();
        REQUIRE(replayed.size() == 1u);
        CHECK(replayed[0].mRecordedBackend == EFemBackend::Gpu);
        REQUIRE(replayed[0].mProp.GetBackend() == EFemBackend::Gpu);
        std::vector<Vec3> positions;
        replayed[0].mProp.ReadPositions(positions);
        CHECK(positions == live_positions);
        CHECK(replayed[0].mProp.GetElementNodes() == live.GetElementNodes());
        CHECK(replayed[0].mProp.GetGpuSolver()->GetBrokenLinks() == live.GetGpuSolver()->GetBrokenLinks());
        CHECK(replayed[0].mProp.ComputeFragments().size() == live.ComputeFragments().size());
    }
    // Without one: on the CPU, saying why; the same hits crack it (double precision: close, not bitwise).
    {
        const std::vector<ReplayedProp> replayed = ReplayProps(replay, nullptr).Get();
        REQUIRE(replayed.size() == 1u);
        CHECK(replayed[0].mRecordedBackend == EFemBackend::Gpu);
        CHECK(replayed[0].mProp.GetBackend() == EFemBackend::Cpu);
        CHECK_FALSE(replayed[0].mProp.GetFallbackReason().empty());
        CHECK(replayed[0].mProp.GetBrokenLinkCount() > 0);
    }
}

TEST_CASE("Props in a recording: an implicit GPU prop with its coarse space turning replays bit for bit on a "
          "device",
          "[props][replay][gpu]")
{
    // The brittle panel finer (2 x 12 x 12 cubes, 468 free nodes) and ten times as strong, stepped implicitly
    // (the default) with a held prop's refresh (6): its solves add the coarse correction, built again after
    // each crack and turned before each step (measured: 30 links broken, 4 builds, 11 turns, 120 coarse
    // unknowns at the end); the replay's rebuilds and turns read the same floats, so it ends on the same
    // state.
    fem::TetSolverSettings settings;
    settings.mGravity = Vec3::Zero();
    settings.mFactorRefreshIterations = 6;
    const std::optional<RecordedGpuPanel> run =
        RecordGpuPanel({2, 12, 12}, 10.0, settings, "props_gpu_implicit.crumple");
    if (!run)
        return;
    const FemProp& live = run->Live();
    std::vector<Vec3> live_positions;
    live.ReadPositions(live_positions);
    INFO("live: " << live.GetBrokenLinkCount() << " links broken, "
                  << live.GetGpuSolver()->GetCoarseUnknowns() << " coarse unknowns, "
                  << live.GetGpuSolver()->GetCoarseSpaceBuilds() << " builds, "
                  << live.GetGpuSolver()->GetCoarseSpaceTurns() << " turns");
    REQUIRE(live.GetGpuSolver()->GetCoarseUnknowns() > 0);
    REQUIRE(live.GetGpuSolver()->GetCoarseSpaceTurns() > 0);

    gpu::ComputeDeviceProvider replay_devices;
    const std::vector<ReplayedProp> replayed = ReplayProps(run->mReplay, &replay_devices).Get();
    REQUIRE(replayed.size() == 1u);
    REQUIRE(replayed[0].mProp.GetBackend() == EFemBackend::Gpu);
    std::vector<Vec3> positions;
    replayed[0].mProp.ReadPositions(positions);
    CHECK(positions == live_positions);
    CHECK(replayed[0].mProp.GetElementNodes() == live.GetElementNodes());
    CHECK(replayed[0].mProp.GetGpuSolver()->GetCoarseSpaceTurns() ==
          live.GetGpuSolver()->GetCoarseSpaceTurns());
}

TEST_CASE("Props in a recording: a GPU prop's at-rest test reads its state, so live and replay agree, a stepped "
          "solver moved to the GPU is refused",
          "[props][replay][gpu]")
{
    gpu::ComputeDeviceProvider devices;
    FemPropSettings on_gpu;
    on_gpu.mBackend = EFemBackend::Gpu;
    fem::TetGridSettings grid;
    grid.mSize = Vec3(0.2, 0.2, 1.0);
    grid.mCellCount = {1, 1, 4};
    fem::FemMaterialSettings material;
    material.mYoungsModulus = 1.0e7;
    fem::TetSolverSettings settings;
    settings.mIntegrator = fem::EIntegrator::SymplecticEuler;
    settings.mGravity = Vec3::Zero();
    const fem::TetMesh mesh = fem::TetGrid(grid).Get();
    FemProp post = FemProp::Create(&devices, mesh, material, settings, on_gpu).Get();
    if (post.GetBackend() != EFemBackend::Gpu)
    {
        test::RequireNoComputeDevice(&devices, post.GetFallbackReason());
        WARN("skipped: no compute device: " << post.GetFallbackReason());
        return;
    }

    // A force set and cleared leaves the state exactly as made: still, as a prop rebuilt from its recorded
    // state is (the flag this replaced only ever went from still to not, and the replay sleeps at once).
    // Both sleep at the first step.
    const int tip = post.GetNodeCount() - 1;
    REQUIRE(post.SetExternalForce(tip, Vec3(5.0, 0.0, 0.0)).IsValid());
    REQUIRE(post.SetExternalForce(tip, Vec3::Zero()).IsValid());
    REQUIRE(post.GetGpuSolver()->IsStillAndUnstrained());
    const PropSetup setup = MakePropSetup(BodyId{}, post).Get();
    FemProp rebuilt = FemProp::FromSolver(&devices, RebuildProp(setup).Get(), on_gpu);
    REQUIRE(rebuilt.GetBackend() == EFemBackend::Gpu);
    const fem::TetStepResult live_step = post.Step(1.0 / 60.0).Get();
    const fem::TetStepResult rebuilt_step = rebuilt.Step(1.0 / 60.0).Get();
    CHECK(HasEvent(live_step.mEvents, fem::ETetStepEvent::FellAsleep));
    CHECK(live_step.mEvents == rebuilt_step.mEvents);
    CHECK(post.GetGpuSolver()->GetElementWorkCount() == 0u);

    // A force left on: not still, so both integrate, to the same floats.
    REQUIRE(post.SetExternalForce(tip, Vec3(5.0, 0.0, 0.0)).IsValid());
    CHECK_FALSE(post.GetGpuSolver()->IsStillAndUnstrained());
    const PropSetup forced = MakePropSetup(BodyId{}, post).Get();
    FemProp forced_rebuilt = FemProp::FromSolver(&devices, RebuildProp(forced).Get(), on_gpu);
    for (int step = 0; step < 3; ++step)
    {
        REQUIRE(post.Step(1.0 / 60.0).IsValid());
        REQUIRE(forced_rebuilt.Step(1.0 / 60.0).IsValid());
    }
    std::vector<Vec3> live_positions, rebuilt_positions;
    post.ReadPositions(live_positions);
    forced_rebuilt.ReadPositions(rebuilt_positions);
    CHECK(post.GetGpuSolver()->GetElementWorkCount() > 0u);
    CHECK(live_positions == rebuilt_positions);
    CHECK(live_positions != post.GetGpuSolver()->GetMadeRestPositions());

    // A CPU solver that has stepped keeps its step count on the GPU, so a recording refuses it.
    fem::TetSolver cpu = fem::TetSolver::Create(mesh, material, settings).Get();
    REQUIRE(cpu.ApplyImpulse(tip, Vec3(0.1, 0.0, 0.0)).IsValid());
    REQUIRE(cpu.Step(1.0 / 60.0).IsValid());
    const std::uint64_t work = cpu.GetElementWorkCount();
    FemProp moved = FemProp::FromSolver(&devices, std::move(cpu), on_gpu);
    REQUIRE(moved.GetBackend() == EFemBackend::Gpu);
    CHECK(moved.GetGpuSolver()->GetElementWorkCount() == work);
    CHECK(MakePropSetup(BodyId{}, moved).HasError());
}
#endif

TEST_CASE("Props in a recording: a setup of mismatched sizes, a second recorder, a second prop for a body and records "
          "that go back are refused",
          "[props][replay]")
{
    common::WorldFixture fixture;
    FemProp panel = BrittlePanel();
    const PropSetup setup = MakePropSetup(fixture.mWall, panel).Get();
    for (int field = 0; field < 4; ++field)
    {
        PropSetup bad = setup;
        switch (field)
        {
        case 0: bad.mVelocities.clear(); break;
        case 1: bad.mAnchored.pop_back(); break;
        case 2: bad.mExternalForces.push_back(Vec3::Zero()); break;
        case 3: bad.mGroups.resize(1); break;
        }
        INFO("field " << field);
        CHECK(ValidatePropSetupSizes(bad).GetError().mCode == EError::InvalidArgument);
        CHECK(EncodePropSetup(bad).HasError());
        CHECK(RebuildProp(bad).HasError());
    }
    REQUIRE(ValidatePropSetupSizes(setup).IsValid());

    // A second recorder (or the same one again) would write every prop twice.
    const std::filesystem::path path = common::ScratchDirectory() / "props_twice.crumple";
    std::unique_ptr<DamageRecorder> recorder = std::move(DamageRecorder::Create(path, fixture.mWorld).Get());
    std::unique_ptr<PropWorld> props = PropWorld::Create(fixture.mWorld).Get();
    REQUIRE(props->AddProp(fixture.mWall, std::move(panel)).IsValid());
    REQUIRE(props->AttachRecorder(recorder.get()).IsValid());
    CHECK(props->AttachRecorder(recorder.get()).GetError().mCode == EError::InvalidArgument);
    REQUIRE(props->AttachRecorder(nullptr).IsValid());
    REQUIRE(recorder->Close().IsValid());
    // A closed recorder is refused too, and writes nothing.
    CHECK(props->AttachRecorder(recorder.get()).HasError());
    const Replay recorded = DecodeReplay(ReadFileBytes(path).Get()).Get();
    REQUIRE(recorded.mExtensions.size() == 1);
    REQUIRE(ReplayProps(recorded).Get().size() == 1);

    Replay twice = recorded;
    twice.mExtensions.push_back(recorded.mExtensions.front());
    const Result<std::vector<ReplayedProp>> second = ReplayProps(twice);
    REQUIRE(second.HasError());
    CHECK(second.GetError().mMessage.find("prop record 1") != std::string::npos);

    // A record placed after fewer collisions than the one before it.
    Replay back = recorded;
    back.mCollisions.resize(2);
    back.mExtensions.front().mAfterCollisions = 2;
    RecordedExtension step;
    step.mTag = static_cast<std::uint32_t>(EPropRecord::Step);
    step.mPayload = std::vector<std::byte>(8, std::byte{0});
    step.mAfterCollisions = 1;
    back.mExtensions.push_back(step);
    CHECK(ReplayProps(back).GetError().mCode == EError::CorruptData);
}

TEST_CASE("Props in a recording: the factor refresh setting is recorded, a record written before it replays without refreshes",
          "[props][replay]")
{
    common::WorldFixture fixture;
    FemProp panel = BrittlePanel();
    PropSetup setup = MakePropSetup(fixture.mWall, panel).Get();
    // With no crack stress bound the record ends at the refresh setting (the bound has a test of its own).
    setup.mSettings.mCrackStressTolerance = std::numeric_limits<double>::infinity();
    for (int refresh : {0, 1, 7})
    {
        setup.mSettings.mFactorRefreshIterations = refresh;
        const std::vector<std::byte> bytes = EncodePropSetup(setup).Get();
        CHECK(DecodePropSetup(bytes).Get().mSettings.mFactorRefreshIterations == refresh);
        // Older records end before the setting (and its tag): the solver then never refreshed, and replays so.
        const std::vector<std::byte> older(bytes.begin(), bytes.end() - 8);
        CHECK(DecodePropSetup(older).Get().mSettings.mFactorRefreshIterations == 0);
        // Anything else at the end is a corrupt record: a byte more or less, another tag, a count beyond int.
        std::vector<std::byte> longer = bytes;
        longer.push_back(std::byte{0});
        CHECK(DecodePropSetup(longer).GetError().mCode == EError::CorruptData);
        const std::vector<std::byte> shorter(bytes.begin(), bytes.end() - 4);
        CHECK(DecodePropSetup(shorter).GetError().mCode == EError::CorruptData);
        std::vector<std::byte> other_tag = bytes;
        other_tag[other_tag.size() - 8] ^= std::byte{1};
        CHECK(DecodePropSetup(other_tag).GetError().mCode == EError::CorruptData);
        std::vector<std::byte> huge = bytes;
        huge[huge.size() - 1] = std::byte{0xFF};
        CHECK(DecodePropSetup(huge).GetError().mCode == EError::CorruptData);
    }
}

TEST_CASE("Props in a recording: a contact spread is recorded and replays bit for bit, without one the record is "
          "as before",
          "[props][replay]")
{
    const std::filesystem::path path = common::ScratchDirectory() / "props-spread.crumple";
    common::WorldFixture fixture;
    std::unique_ptr<DamageRecorder> recorder = std::move(DamageRecorder::Create(path, fixture.mWorld).Get());
    std::unique_ptr<PropWorld> props = PropWorld::Create(fixture.mWorld).Get();
    REQUIRE(props->AttachRecorder(recorder.get()).IsValid());
    FemProp panel = BrittlePanel();
    REQUIRE(panel.SetContactSpread(0.35).IsValid());
    const PropId wall = props->AddProp(fixture.mWall, std::move(panel)).Get();
    REQUIRE(HitTwice(fixture, *props) > 0); // it cracked
    REQUIRE(props->AttachRecorder(nullptr).IsValid());
    REQUIRE(recorder->Close().IsValid());
    const TetSolver& live = *props->GetProp(wall)->GetCpuSolver();
    // The spread changed the run: the same hits without it end elsewhere.
    {
        common::WorldFixture plain_fixture;
        std::unique_ptr<PropWorld> plain = PropWorld::Create(plain_fixture.mWorld).Get();
        const PropId plain_wall = plain->AddProp(plain_fixture.mWall, BrittlePanel()).Get();
        HitTwice(plain_fixture, *plain);
        CHECK(plain->GetProp(plain_wall)->GetCpuSolver()->GetPositions() != live.GetPositions());
    }

    const std::vector<ReplayedProp> replayed = ReplayProps(DecodeReplay(ReadFileBytes(path).Get()).Get()).Get();
    REQUIRE(replayed.size() == 1u);
    CHECK(replayed[0].mProp.GetContactSpread() == 0.35);
    const TetSolver& again = *replayed[0].mProp.GetCpuSolver();
    CHECK(again.GetBrokenLinks() == live.GetBrokenLinks());
    CHECK(again.GetPositions() == live.GetPositions());
    CHECK(again.GetVelocities() == live.GetVelocities());

    // The record: 0 writes nothing more (the bytes of a prop before the spread existed); a radius adds a
    // tagged double, and a bad one is refused both ways.
    PropSetup setup = MakePropSetup(fixture.mWall, BrittlePanel()).Get();
    setup.mSettings.mCrackStressTolerance =
        std::numeric_limits<double>::infinity(); // the spread ends the record
    CHECK(setup.mContactSpread == 0.0);
    const std::vector<std::byte> plain = EncodePropSetup(setup).Get();
    setup.mContactSpread = 0.35;
    const std::vector<std::byte> spread = EncodePropSetup(setup).Get();
    CHECK(spread.size() == plain.size() + 12);
    CHECK(std::equal(plain.begin(), plain.end(), spread.begin()));
    CHECK(DecodePropSetup(plain).Get().mContactSpread == 0.0);
    CHECK(DecodePropSetup(spread).Get().mContactSpread == 0.35);
    std::vector<std::byte> negative = spread;
    negative[negative.size() - 1] |= std::byte{0x80}; // the double's sign bit
    CHECK(DecodePropSetup(negative).GetError().mCode == EError::CorruptData);
    std::vector<std::byte> other_tag = spread;
    other_tag[other_tag.size() - 12] ^= std::byte{1};
    CHECK(DecodePropSetup(other_tag).GetError().mCode == EError::CorruptData);
    setup.mContactSpread = -1.0;
    CHECK(EncodePropSetup(setup).HasError());
}

TEST_CASE("Props in a recording: the crack stress bound is recorded, a record written before it replays "
          "without one",
          "[props][replay]")
{
    common::WorldFixture fixture;
    PropSetup setup = MakePropSetup(fixture.mWall, BrittlePanel()).Get();
    CHECK(setup.mSettings.mCrackStressTolerance == TetSolverSettings{}.mCrackStressTolerance);
    const double infinity = std::numeric_limits<double>::infinity();
    const auto decoded = [](const std::vector<std::byte>& inBytes)
    { return DecodePropSetup(inBytes).Get().mSettings.mCrackStressTolerance; };

    // No bound writes nothing (the bytes of a prop before the bound existed), and such a record replays with
    // none.
    setup.mSettings.mCrackStressTolerance = infinity;
    const std::vector<std::byte> none = EncodePropSetup(setup).Get();
    CHECK(decoded(none) == infinity);
    setup.mSettings.mCrackStressTolerance = 0.5;
    const std::vector<std::byte> bound = EncodePropSetup(setup).Get();
    CHECK(bound.size() == none.size() + 12);
    CHECK(std::equal(none.begin(), none.end(), bound.begin()));
    CHECK(decoded(bound) == 0.5);
    // After a contact spread, in the order they are written.
    setup.mContactSpread = 0.35;
    const std::vector<std::byte> both = EncodePropSetup(setup).Get();
    CHECK(decoded(both) == 0.5);
    CHECK(DecodePropSetup(both).Get().mContactSpread == 0.35);

    // Refused: a value that is not > 0, an unknown tag, the two tagged settings swapped, one given twice.
    std::vector<std::byte> negative = bound;
    negative[negative.size() - 1] |= std::byte{0x80}; // the double's sign bit
    CHECK(DecodePropSetup(negative).GetError().mCode == EError::CorruptData);
    std::vector<std::byte> other_tag = bound;
    other_tag[other_tag.size() - 12] ^= std::byte{1};
    CHECK(DecodePropSetup(other_tag).GetError().mCode == EError::CorruptData);
    std::vector<std::byte> swapped(both.begin(), both.end() - 24);
    swapped.insert(swapped.end(), both.end() - 12, both.end());
    swapped.insert(swapped.end(), both.end() - 24, both.end() - 12);
    CHECK(DecodePropSetup(swapped).GetError().mCode == EError::CorruptData);
    std::vector<std::byte> twice = bound;
    twice.insert(twice.end(), bound.end() - 12, bound.end());
    CHECK(DecodePropSetup(twice).GetError().mCode == EError::CorruptData);
    // A solver and the record's writer refuse the same values the reader does.
    for (double value : {0.0, -0.5, std::nan("")})
    {
        setup.mSettings.mCrackStressTolerance = value;
        CHECK(EncodePropSetup(setup).HasError());
        TetSolverSettings settings;
        settings.mCrackStressTolerance = value;
        CHECK(TetSolver::Create(TetGrid({}).Get(), FemMaterialSettings{}, settings).HasError());
    }
}

TEST_CASE("Props in a recording: the factor refresh by cost is recorded, a record written before it replays "
          "without it",
          "[props][replay]")
{
    common::WorldFixture fixture;
    PropSetup setup = MakePropSetup(fixture.mWall, BrittlePanel()).Get();
    setup.mSettings.mFactorRefreshIterations = 6;
    const auto by_cost = [](const std::vector<std::byte>& inBytes)
    { return DecodePropSetup(inBytes).Get().mSettings.mFactorRefreshByCost; };

    // Off writes nothing (the bytes of a prop before the policy existed), and such a record replays without
    // it.
    setup.mSettings.mFactorRefreshByCost = false;
    const std::vector<std::byte> off = EncodePropSetup(setup).Get();
    CHECK_FALSE(by_cost(off));
    setup.mSettings.mFactorRefreshByCost = true;
    const std::vector<std::byte> on = EncodePropSetup(setup).Get();
    CHECK(on.size() == off.size() + 12);
    CHECK(std::equal(off.begin(), off.end(), on.begin()));
    CHECK(by_cost(on));
    CHECK(DecodePropSetup(on).Get().mSettings.mCrackStressTolerance == setup.mSettings.mCrackStressTolerance);
    // Before a ground, in the order they are written.
    setup.mSettings.mGround.mEnabled = true;
    setup.mSettings.mGround.mOffset = -1.0;
    const std::vector<std::byte> grounded = EncodePropSetup(setup).Get();
    CHECK(by_cost(grounded));
    CHECK(DecodePropSetup(grounded).Get().mSettings.mGround.mEnabled);

    // Refused: a value other than 1, the tag given twice, the crack stress bound after it (out of order).
    std::vector<std::byte> not_one = on;
    not_one[not_one.size() - 1] = std::byte{0x40}; // 1.0 (0x3FF0...) becomes 0x40F0...: 65536.0
    CHECK(DecodePropSetup(not_one).GetError().mCode == EError::CorruptData);
    std::vector<std::byte> twice = on;
    twice.insert(twice.end(), on.end() - 12, on.end());
    CHECK(DecodePropSetup(twice).GetError().mCode == EError::CorruptData);
    std::vector<std::byte> swapped(on.begin(), on.end() - 24);
    swapped.insert(swapped.end(), on.end() - 12, on.end());
    swapped.insert(swapped.end(), on.end() - 24, on.end() - 12);
    CHECK(DecodePropSetup(swapped).GetError().mCode == EError::CorruptData);
}

TEST_CASE(
    "Props in a recording: a prop on a ground replays bit for bit, without a ground the record is as before",
    "[props][replay]")
{
    const std::filesystem::path path = common::ScratchDirectory() / "props-ground.crumple";
    common::WorldFixture fixture;
    std::unique_ptr<DamageRecorder> recorder = std::move(DamageRecorder::Create(path, fixture.mWorld).Get());
    std::unique_ptr<PropWorld> props = PropWorld::Create(fixture.mWorld).Get();
    REQUIRE(props->AttachRecorder(recorder.get()).IsValid());
    const PropId wall = props->AddProp(fixture.mWall, test::WeakPanelOnGround()).Get();
    REQUIRE(HitTwice(fixture, *props) > 0); // it cracked
    // The knocked-out pieces fall for half a second onto the ground at z = -1.
    for (int step = 0; step < 60; ++step)
        REQUIRE(props->Step(1.0 / 120.0).IsValid());
    REQUIRE(props->AttachRecorder(nullptr).IsValid());
    REQUIRE(recorder->Close().IsValid());
    const TetSolver& live = *props->GetProp(wall)->GetCpuSolver();
    // The ground held something: free nodes that came down onto it, none through it.
    int on_ground = 0;
    for (std::size_t node = 0; node < live.GetPositions().size(); ++node)
        if (live.GetInverseMasses()[node] > 0.0)
        {
            CHECK(live.GetPositions()[node].z() >= -1.0 - 1.0e-9);
            on_ground +=
                live.GetPositions()[node].z() < -1.0 + 1.0e-9 && live.GetNodeRestPositions()[node].z() > -0.99
                    ? 1
                    : 0;
        }
    WARN(on_ground << " free nodes came down onto the ground");
    CHECK(on_ground > 0);

    const std::vector<ReplayedProp> replayed =
        ReplayProps(DecodeReplay(ReadFileBytes(path).Get()).Get()).Get();
    REQUIRE(replayed.size() == 1u);
    const TetSolver& again = *replayed[0].mProp.GetCpuSolver();
    CHECK(again.GetSettings().mGround.mEnabled);
    CHECK(again.GetSettings().mGround.mOffset == -1.0);
    CHECK(again.GetBrokenLinks() == live.GetBrokenLinks());
    CHECK(again.GetPositions() == live.GetPositions());
    CHECK(again.GetVelocities() == live.GetVelocities());

    // The record: no ground writes nothing more (the bytes of a prop before grounds existed); a ground adds
    // its tag, normal, offset and friction last. Cut, followed by another tagged setting, or out of range:
    // refused.
    PropSetup setup = MakePropSetup(fixture.mWall, test::WeakPanel()).Get();
    const std::vector<std::byte> plain = EncodePropSetup(setup).Get();
    CHECK(!DecodePropSetup(plain).Get().mSettings.mGround.mEnabled);
    setup.mSettings.mGround = GroundPlane{true, Vec3(0.0, 0.6, 0.8), -1.5, 0.45};
    const std::vector<std::byte> grounded = EncodePropSetup(setup).Get();
    CHECK(grounded.size() == plain.size() + 44);
    CHECK(std::equal(plain.begin(), plain.end(), grounded.begin()));
    const GroundPlane read = DecodePropSetup(grounded).Get().mSettings.mGround;
    CHECK(read.mEnabled);
    CHECK(read.mNormal == Vec3(0.0, 0.6, 0.8));
    CHECK(read.mOffset == -1.5);
    CHECK(read.mFriction == 0.45);
    const std::vector<std::byte> cut(grounded.begin(), grounded.end() - 8);
    CHECK(DecodePropSetup(cut).GetError().mCode == EError::CorruptData);
    std::vector<std::byte> then_spread = grounded;
    then_spread.insert(then_spread.end(), grounded.end() - 56, grounded.end() - 44); // the crack bound again
    CHECK(DecodePropSetup(then_spread).GetError().mCode == EError::CorruptData);
    PropSetup tilted = setup;
    tilted.mSettings.mGround.mNormal = Vec3(0.0, 0.0, 2.0);
    CHECK(RebuildProp(DecodePropSetup(EncodePropSetup(tilted).Get()).Get()).HasError());
}

#if defined(CRUMPLE_TEST_PROPS_WITH_GPU)
TEST_CASE("Props: a GPU prop asked for with a ground runs on the CPU and says why", "[props][gpu]")
{
    gpu::ComputeDeviceProvider devices;
    FemPropSettings on_gpu;
    on_gpu.mBackend = EFemBackend::Gpu;
    fem::TetSolverSettings settings;
    const FemProp without =
        FemProp::Create(&devices, TetGrid({}).Get(), FemMaterialSettings{}, settings, on_gpu).Get();
    if (without.GetBackend() != EFemBackend::Gpu)
    {
        test::RequireNoComputeDevice(&devices, without.GetFallbackReason());
        WARN("skipped: no compute device: " << without.GetFallbackReason());
        return;
    }
    settings.mGround.mEnabled = true;
    std::string logged;
    on_gpu.mLog = [&](std::string_view inLine) { logged = inLine; };
    const FemProp grounded =
        FemProp::Create(&devices, TetGrid({}).Get(), FemMaterialSettings{}, settings, on_gpu).Get();
    CHECK(grounded.GetBackend() == EFemBackend::Cpu);
    CHECK(grounded.GetCpuSolver()->GetSettings().mGround.mEnabled);
    CHECK_THAT(grounded.GetFallbackReason(), Catch::Contains("ground"));
    CHECK_THAT(logged, Catch::Contains("ground"));
}
#endif
