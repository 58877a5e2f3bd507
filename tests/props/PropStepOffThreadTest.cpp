// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// Props stepped off the game's thread (PropWorldSettings::mStepOffThread): the same props whatever the job
// system, the same as on the game's thread when nothing happens between a step and its landing, and a
// recording that replays bit for bit.
#include "BrittlePanel.h"
#include "ScratchDirectory.h"
#include "ThreadJobSystem.h"
#include "WorldFixture.h"

#include <crumple/base/FileBytes.h>
#include <crumple/plugin/DamageRecorder.h>
#include <crumple/props/PropRecording.h>
#include <crumple/props/PropWorld.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <optional>
#include <utility>

using namespace crumple;
using namespace crumple::fem;
using namespace crumple::plugin;
using namespace crumple::props;

namespace
{

// One contact of the car at speed inSpeed (m/s) on the panel's centre at time inTime (s), dispatched at once.
void HitCentre(common::WorldFixture& ioFixture, double inSpeed, double inTime)
{
    REQUIRE(ioFixture.mWorld.SetBodyState(ioFixture.mCar, ioFixture.CarState(inSpeed)));
    REQUIRE(ioFixture.mWorld.SubmitContacts(std::vector<ContactEvent>{ioFixture.FrontContact(0.0, 0.0, inTime)}));
    ioFixture.mWorld.Flush();
}

// How the game drives the props after each engine step.
enum class ELoop
{
    Step,         ///< Step(), then loose pieces: the step on the game's thread, or started and landed at once
    LandThenStart ///< LandStep(), loose pieces, StartStep(): the step runs while the engine steps
};

// What a run left.
struct Outcome
{
    std::vector<Vec3> mPositions, mVelocities;
    std::vector<TetIndices> mElements;
    int mBrokenLinks = 0;
    int mLoosePieces = 0;
    int mFractured = 0; ///< Steps' reports: props fractured
    std::vector<std::vector<int>> mLooseNodes;    ///< Each loose piece's nodes, in hand-over order
    std::vector<double> mLooseMasses;             ///< ... and its rigid body's mass (0 when dropped)
    std::vector<std::vector<std::vector<Vec3>>> mShapes; ///< Every changed shape taken, in order
    PropHandOverStats mHandOver;
    std::vector<std::byte> mRecording;
};

// The shape the loop takes after the loose pieces: 0.25 m cubes, following the panel to 10 micrometres (it barely moves between hits).
constexpr double cShapeCell = 0.25, cShapeTolerance = 1.0e-5;

// Hard hits across the wall panel, the engine's Update dispatching each while the props are (or would be)
// stepping; after each of 40 engine steps of 1/120 s the game drives the props as inLoop says and takes the
// loose pieces. inThreads: 0 for no job system, else a ThreadJobSystem of that many threads. inLastHit: one
// more hit after the last step (off the thread it waits for a step that never comes).
Outcome Run(int inThreads, bool inOffThread, ELoop inLoop, bool inRecord, bool inLastHit = false)
{
    std::optional<common::ThreadJobSystem> jobs;
    DamageWorldSettings settings;
    if (inThreads > 0)
    {
        jobs.emplace(inThreads);
        settings.mJobs = &jobs->Get();
    }
    common::WorldFixture fixture(4000, {8, 6, 6}, settings);
    const std::filesystem::path path = common::ScratchDirectory() / "props_off_thread.crumple";
    std::unique_ptr<DamageRecorder> recorder;
    if (inRecord)
        recorder = std::move(DamageRecorder::Create(path, fixture.mWorld).Get());
    std::unique_ptr<PropWorld> props = PropWorld::Create(fixture.mWorld, {.mStepOffThread = inOffThread}).Get();
    if (inRecord)
        REQUIRE(props->AttachRecorder(recorder.get()));
    const PropId wall = props->AddProp(fixture.mWall, test::WeakPanel()).Get();
    Outcome outcome;
    // The hand-over after each landed step: loose pieces, then the changed shape.
    const auto hand_over = [&] {
        Result<std::vector<LooseFragment>> loose = props->TakeLooseFragments();
        REQUIRE(loose);
        outcome.mLoosePieces += static_cast<int>(loose.Get().size());
        for (const LooseFragment& piece : loose.Get())
        {
            outcome.mLooseNodes.push_back(piece.mNodes);
            outcome.mLooseMasses.push_back(piece.mDropped ? 0.0 : piece.mRigidBody.mBody.mMass);
        }
        Result<std::optional<std::vector<std::vector<Vec3>>>> shape = props->TakeChangedShape(wall, cShapeCell, cShapeTolerance);
        REQUIRE(shape);
        if (shape.Get())
            outcome.mShapes.push_back(*shape.Get());
    };
    // The shape at rest, before the first step (the game hands the engine its first shape at level load),
    // and the loose pieces then (none).
    REQUIRE(props->TakeLooseFragments().Get().empty());
    Result<std::optional<std::vector<std::vector<Vec3>>>> first_shape = props->TakeChangedShape(wall, cShapeCell, cShapeTolerance);
    REQUIRE(first_shape);
    REQUIRE(first_shape.Get());
    outcome.mShapes.push_back(*first_shape.Get());
    for (int step = 0; step <= 40; ++step)
    {
        if ((step % 8 == 0 && step < 32) || (step == 40 && inLastHit))
        {
            const int hit = step / 8;
            REQUIRE(fixture.mWorld.SetBodyState(fixture.mCar, fixture.CarState(40.0)));
            const double y = -0.6 + 0.4 * hit, z = 0.6 - 0.3 * hit;
            REQUIRE(fixture.mWorld.SubmitContacts(std::vector<ContactEvent>{fixture.FrontContact(y, z, 0.1 * step),
                                                                           fixture.FrontContact(y + 0.1, z - 0.1, 0.1 * step)}));
            fixture.mWorld.Flush();
        }
        // intent: the 40th step lands after the loop (LandThenStart): either loop hands over after each step
        if (step == 40)
            break;
        Result<PropStepReport> report = inLoop == ELoop::Step ? props->Step(1.0 / 120.0) : props->LandStep();
        REQUIRE(report);
        outcome.mFractured += report.Get().mFractured;
        if (inLoop == ELoop::Step || step > 0)
            hand_over();
        if (inLoop == ELoop::LandThenStart)
            REQUIRE(props->StartStep(1.0 / 120.0));
    }
    if (inLoop == ELoop::LandThenStart)
    {
        Result<PropStepReport> report = props->LandStep();
        REQUIRE(report);
        outcome.mFractured += report.Get().mFractured;
        hand_over();
    }
    const TetSolver& solver = *props->GetProp(wall)->GetCpuSolver(); // waits for a step in flight
    outcome.mPositions = solver.GetPositions();
    outcome.mVelocities = solver.GetVelocities();
    outcome.mElements = solver.GetElementNodes();
    outcome.mBrokenLinks = solver.GetBrokenLinkCount();
    outcome.mHandOver = props->GetHandOverStats();
    if (inRecord)
    {
        REQUIRE(props->AttachRecorder(nullptr));
        REQUIRE(recorder->Close());
        outcome.mRecording = ReadFileBytes(path).Get();
    }
    return outcome;
}

void CheckSame(const Outcome& inA, const Outcome& inB)
{
    INFO("shapes " << inA.mShapes.size() << " and " << inB.mShapes.size());
    CHECK(inA.mBrokenLinks == inB.mBrokenLinks);
    CHECK(inA.mLoosePieces == inB.mLoosePieces);
    CHECK(inA.mFractured == inB.mFractured);
    CHECK(inA.mElements == inB.mElements);
    CHECK(inA.mPositions == inB.mPositions);
    CHECK(inA.mVelocities == inB.mVelocities);
    CHECK(inA.mLooseNodes == inB.mLooseNodes);
    CHECK(inA.mLooseMasses == inB.mLooseMasses);
    CHECK(inA.mShapes == inB.mShapes);
}

// A host job system whose started tasks run only when waited for (a real host may run them that late): a call
// that reads a prop without waiting for the step in flight sees it unstepped. Counts the tasks started.
struct LazyTasks
{
    JobSystem mJobs;
    void (*mTask)(void*) = nullptr;
    void* mContext = nullptr;
    int mStarted = 0;

    LazyTasks(const LazyTasks&) = delete;
    LazyTasks& operator=(const LazyTasks&) = delete;
    LazyTasks()
    {
        mJobs.mHost = this;
        mJobs.mParallelFor = [](void*, int inCount, void (*inTask)(void*, int), void* inContext) {
            for (int index = 0; index < inCount; ++index)
                inTask(inContext, index);
        };
        mJobs.mStartTask = [](void* inHost, void (*inTask)(void*), void* inContext) -> std::uint64_t {
            auto* self = static_cast<LazyTasks*>(inHost);
            REQUIRE(self->mTask == nullptr); // one in flight at a time
            self->mTask = inTask;
            self->mContext = inContext;
            return static_cast<std::uint64_t>(++self->mStarted);
        };
        mJobs.mWaitTask = [](void* inHost, std::uint64_t) {
            auto* self = static_cast<LazyTasks*>(inHost);
            if (self->mTask != nullptr)
                std::exchange(self->mTask, nullptr)(self->mContext);
        };
    }
    DamageWorldSettings Settings() const
    {
        DamageWorldSettings settings;
        settings.mJobs = &mJobs;
        return settings;
    }
};

// A weak wall panel whose props step off the game's thread, on a 2-thread job system.
struct OffThreadWall
{
    common::ThreadJobSystem mJobs{2};
    common::WorldFixture mFixture{4000, {8, 6, 6}, WithJobs(mJobs)};
    std::unique_ptr<PropWorld> mProps = PropWorld::Create(mFixture.mWorld, {.mStepOffThread = true}).Get();
    PropId mWall = mProps->AddProp(mFixture.mWall, test::WeakPanel()).Get();

    static DamageWorldSettings WithJobs(const common::ThreadJobSystem& inJobs)
    {
        DamageWorldSettings settings;
        settings.mJobs = &inJobs.Get();
        return settings;
    }
};

} // namespace

TEST_CASE("Props off the game's thread end bitwise the same for any job system and thread count", "[props][threads]")
{
    const Outcome inline_run = Run(0, true, ELoop::LandThenStart, true);
    // The run is worth comparing: the hits cracked the panel and knocked pieces out, taken between steps.
    REQUIRE(inline_run.mBrokenLinks > 0);
    REQUIRE(inline_run.mLoosePieces > 0);
    for (int threads : {1, 2, 4})
    {
        INFO("threads " << threads);
        const Outcome threaded = Run(threads, true, ELoop::LandThenStart, true);
        CheckSame(threaded, inline_run);
        CHECK(threaded.mRecording == inline_run.mRecording);
    }
}

TEST_CASE("Props off the game's thread, landed before the next hit, are the props stepped on the game's thread",
          "[props][threads]")
{
    // The collisions that waited reach the props just where they would have when dispatched: with hits that
    // do not depend on the props (no engine here), bitwise the same run, whether each step lands at once or
    // at the next engine step with the loose pieces taken in between. (In an engine the held body's velocity
    // and the pieces then reach the engine a step later, and the run differs: the racing samples.)
    // The hand-over between landing and start (loose pieces, changed shapes) is the one the game's thread
    // works out, though off the thread the task worked most of it out (PropHandOverStats).
    const Outcome on_thread = Run(2, false, ELoop::Step, false);
    REQUIRE(on_thread.mLoosePieces > 0);
    REQUIRE(on_thread.mShapes.size() > 2u);
    CHECK(on_thread.mHandOver.mFragmentsForecast == 0u);
    CHECK(on_thread.mHandOver.mShapesForecast == 0u);
    {
        INFO("stepped and landed at once");
        CheckSame(Run(2, true, ELoop::Step, false), on_thread);
    }
    const Outcome off_thread = Run(2, true, ELoop::LandThenStart, false);
    {
        INFO("landed at the next engine step");
        CheckSame(off_thread, on_thread);
    }
    CHECK(off_thread.mHandOver.mFragmentsForecast > 0u);
    CHECK(off_thread.mHandOver.mShapesForecast > 0u);
    // Worked out in a call only where the task could not: the calls at rest, before the first step (the task
    // learns the shape's cell size and tolerance from them); then the task worked out every hand-over, the
    // shapes after pieces left too.
    CHECK(off_thread.mHandOver.mShapesComputed == 1u);
    CHECK(off_thread.mHandOver.mFragmentsComputed == 1u);
    // Inline (no job system) nothing is worked out ahead: the calls do it when asked.
    const Outcome inline_off_thread = Run(0, true, ELoop::LandThenStart, false);
    {
        INFO("inline");
        CheckSame(inline_off_thread, on_thread);
    }
    CHECK(inline_off_thread.mHandOver.mFragmentsForecast == 0u);
    CHECK(inline_off_thread.mHandOver.mShapesForecast == 0u);
}

TEST_CASE("Props off the game's thread replay bit for bit, loose pieces taken between landing and start", "[props][replay][threads]")
{
    // A last hit waits for a step that never comes: it must not reach the replayed prop either.
    const Outcome live = Run(2, true, ELoop::LandThenStart, true, true);
    REQUIRE(live.mLoosePieces > 0);
    const Replay replay = DecodeReplay(live.mRecording).Get();
    REQUIRE(!replay.mExtensions.empty());
    CHECK(replay.mExtensions[0].mTag == static_cast<std::uint32_t>(EPropRecord::Queued));
    const std::vector<ReplayedProp> replayed = ReplayProps(replay).Get();
    REQUIRE(replayed.size() == 1u);
    const TetSolver& again = *replayed[0].mProp.GetCpuSolver();
    CHECK(again.GetBrokenLinkCount() == live.mBrokenLinks);
    CHECK(again.GetElementNodes() == live.mElements);
    CHECK(again.GetPositions() == live.mPositions);
    CHECK(again.GetVelocities() == live.mVelocities);

    // The same records read as stepped on the game's thread (no Queued record) give the last hit to the prop:
    // the record is what makes the replay right.
    Replay unqueued = replay;
    unqueued.mExtensions.erase(unqueued.mExtensions.begin());
    const std::vector<ReplayedProp> wrong = ReplayProps(unqueued).Get();
    REQUIRE(wrong.size() == 1u);
    CHECK(wrong[0].mProp.GetCpuSolver()->GetVelocities() != live.mVelocities);

    // A Queued record after a prop's, or with a payload, is refused.
    Replay late = replay;
    std::swap(late.mExtensions[0], late.mExtensions[1]);
    CHECK(ReplayProps(late).HasError());
    Replay padded = replay;
    padded.mExtensions[0].mPayload.push_back(std::byte{0});
    CHECK(ReplayProps(padded).HasError());
}

TEST_CASE("Props off the game's thread: a second start, a late recorder and a collision older than its prop", "[props][threads]")
{
    LazyTasks host;
    common::WorldFixture fixture(4000, {8, 6, 6}, host.Settings());
    std::unique_ptr<PropWorld> props = PropWorld::Create(fixture.mWorld, {.mStepOffThread = true}).Get();
    CHECK(props->GetSettings().mStepOffThread);

    // Nothing in flight: an empty report.
    Result<PropStepReport> nothing = props->LandStep();
    REQUIRE(nothing);
    CHECK(nothing.Get().mStepped == 0);
    CHECK(nothing.Get().mSleeping == 0);

    // A hit before any prop joined waits in no queue and never reaches one (as on the game's thread).
    HitCentre(fixture, 20.0, 0.0);
    CHECK(props->GetQueuedCollisionCount() == 0u);
    const PropId wall = props->AddProp(fixture.mWall, test::WeakPanel()).Get();
    REQUIRE(props->StartStep(1.0 / 120.0));
    REQUIRE(props->LandStep());
    CHECK(props->GetCollisionCount() == 0u);
    const std::vector<Vec3> at_rest = props->GetProp(wall)->GetCpuSolver()->GetVelocities();
    CHECK(std::all_of(at_rest.begin(), at_rest.end(), [](const Vec3& v) { return v == Vec3::Zero(); }));

    // A hit now waits for the next start; a recorder cannot start with it waiting.
    HitCentre(fixture, 20.0, 1.0);
    CHECK(props->GetQueuedCollisionCount() == 1u);
    CHECK(props->GetCollisionCount() == 0u);
    const std::filesystem::path path = common::ScratchDirectory() / "props_late_recorder.crumple";
    std::unique_ptr<DamageRecorder> recorder = std::move(DamageRecorder::Create(path, fixture.mWorld).Get());
    CHECK(props->AttachRecorder(recorder.get()).HasError());
    REQUIRE(recorder->Close());

    // The step starts with it, as a task of the host; a second start before landing is refused and changes
    // nothing.
    const int started = host.mStarted;
    REQUIRE(props->StartStep(1.0 / 120.0));
    CHECK(host.mStarted == started + 1);
    CHECK(props->HasStepInFlight());
    CHECK(props->GetQueuedCollisionCount() == 0u);
    CHECK(props->StartStep(1.0 / 120.0).HasError());
    CHECK(props->Step(1.0 / 120.0).HasError());
    CHECK(props->StartStep(-1.0).HasError());
    CHECK(host.mStarted == started + 1);
    CHECK(props->GetQueuedCollisionCount() == 0u);
    CHECK(props->GetCollisionCount() == 0u);             // counted on the task, published by LandStep
    CHECK(props->GetContactVelocity(wall) == Vec3::Zero()); // the last landed step's until LandStep
    Result<PropStepReport> landed = props->LandStep();
    REQUIRE(landed);
    CHECK(landed.Get().mStepped == 1);
    CHECK_FALSE(props->HasStepInFlight());
    CHECK(props->GetCollisionCount() == 1u);
    CHECK(props->GetRefusedCount() == 0u);
    // Landed: the struck material's velocity is this step's, and it moves away from the car (+x).
    CHECK(props->GetContactVelocity(wall).x() > 0.0);
}

TEST_CASE("Props off the game's thread: every read of a prop waits for the step in flight, and a prop added after a "
          "collision was dispatched does not take it, live or replayed",
          "[props][threads][replay]")
{
    // The host runs a task only when it is waited for: a read that did not wait would see the prop unstepped.
    LazyTasks host;
    common::WorldFixture fixture(4000, {8, 6, 6}, host.Settings());
    const std::filesystem::path path = common::ScratchDirectory() / "props_added_late.crumple";
    std::unique_ptr<DamageRecorder> recorder = std::move(DamageRecorder::Create(path, fixture.mWorld).Get());
    std::unique_ptr<PropWorld> props = PropWorld::Create(fixture.mWorld, {.mStepOffThread = true}).Get();
    REQUIRE(props->AttachRecorder(recorder.get()));
    const PropId wall = props->AddProp(fixture.mWall, test::WeakPanel()).Get();
    HitCentre(fixture, 40.0, 0.0);
    REQUIRE(props->GetQueuedCollisionCount() == 1u);
    // The car's body takes a prop after its hit was dispatched: the hit reaches the wall only.
    const PropId car = props->AddProp(fixture.mCar, test::WeakPanel()).Get();
    REQUIRE(props->StartStep(1.0 / 120.0));
    const std::vector<Vec3> wall_rest = props->GetProp(wall)->GetCpuSolver()->GetMesh().GetRestPositions();
    const std::vector<Vec3> read_in_flight = props->GetProp(wall)->GetCpuSolver()->GetPositions(); // waits
    REQUIRE(props->LandStep());
    CHECK(props->GetCollisionCount() == 1u);
    const std::vector<Vec3> wall_positions = props->GetProp(wall)->GetCpuSolver()->GetPositions();
    CHECK(read_in_flight == wall_positions);
    CHECK(wall_positions != wall_rest); // the step moved it: the read above saw the task's work
    const std::vector<Vec3> car_velocities = props->GetProp(car)->GetCpuSolver()->GetVelocities();
    CHECK(std::all_of(car_velocities.begin(), car_velocities.end(), [](const Vec3& v) { return v == Vec3::Zero(); }));
    const std::vector<Vec3> car_positions = props->GetProp(car)->GetCpuSolver()->GetPositions();
    REQUIRE(props->AttachRecorder(nullptr));
    REQUIRE(recorder->Close());

    const std::vector<ReplayedProp> replayed = ReplayProps(DecodeReplay(ReadFileBytes(path).Get()).Get()).Get();
    REQUIRE(replayed.size() == 2u);
    CHECK(replayed[0].mProp.GetCpuSolver()->GetPositions() == wall_positions);
    CHECK(replayed[1].mProp.GetCpuSolver()->GetPositions() == car_positions);
    CHECK(replayed[1].mProp.GetCpuSolver()->GetVelocities() == car_velocities);
}

TEST_CASE("Props off the game's thread: a prop the game changed after the step landed is handed over as it is now",
          "[props][threads]")
{
    // The task works out the hand-over for the prop as it stepped. The game may then change the prop through
    // GetProp: pin a node, move one. The calls must not take the task's answers then (they would hand over a
    // piece that is now held, or a shape where the prop no longer is), but work them out from the prop.
    OffThreadWall scene;
    common::WorldFixture& fixture = scene.mFixture;
    PropWorld* props = scene.mProps.get();
    const PropId wall = scene.mWall;
    REQUIRE(props->TakeChangedShape(wall, cShapeCell, cShapeTolerance));
    HitCentre(fixture, 60.0, 0.0);
    bool moved = false, pinned = false;
    for (int step = 0; step < 80 && !(moved && pinned); ++step)
    {
        REQUIRE(props->StartStep(1.0 / 120.0));
        REQUIRE(props->LandStep());
        FemProp& prop = *props->GetProp(wall);
        const std::vector<fem::TetFragment> fragments = prop.ComputeFragments();
        const auto loose = std::find_if(fragments.begin() + 1, fragments.end(), [](const fem::TetFragment& inF) { return !inF.mAnchored; });
        const PropHandOverStats before = props->GetHandOverStats();
        if (loose != fragments.end() && !pinned)
        {
            // A piece is loose: pin one of its nodes. It stays in the prop.
            pinned = true;
            const int node = loose->mNodes[0];
            REQUIRE(prop.SetNodeFixed(node, true));
            Result<std::vector<LooseFragment>> taken = props->TakeLooseFragments();
            REQUIRE(taken);
            for (const LooseFragment& piece : taken.Get())
                CHECK(std::find(piece.mNodes.begin(), piece.mNodes.end(), node) == piece.mNodes.end());
            CHECK(props->GetHandOverStats().mFragmentsForecast == before.mFragmentsForecast);
            CHECK(props->GetHandOverStats().mFragmentsComputed == before.mFragmentsComputed + 1);
        }
        else
            REQUIRE(props->TakeLooseFragments());
        const PropHandOverStats taken_loose = props->GetHandOverStats();
        if (loose == fragments.end() && taken_loose.mShapesForecast > 0 && !moved && step % 2 == 1)
        {
            // No piece leaves, and the task built this step's shape: move a node 5 cm first.
            moved = true;
            std::vector<Vec3> positions = prop.GetCpuSolver()->GetPositions();
            positions[positions.size() / 2] += Vec3(0.0, 0.0, 0.05);
            REQUIRE(prop.GetCpuSolver()->SetPositions(positions));
            Result<std::optional<std::vector<std::vector<Vec3>>>> shape = props->TakeChangedShape(wall, cShapeCell, cShapeTolerance);
            REQUIRE(shape);
            REQUIRE(shape.Get());
            CHECK(*shape.Get() == props->GetCollisionPieces(wall, cShapeCell).Get());
            CHECK(props->GetHandOverStats().mShapesForecast == taken_loose.mShapesForecast);
            CHECK(props->GetHandOverStats().mShapesComputed == taken_loose.mShapesComputed + 1);
            continue;
        }
        REQUIRE(props->TakeChangedShape(wall, cShapeCell, cShapeTolerance));
    }
    CHECK(pinned);
    CHECK(moved);
}

TEST_CASE("Props off the game's thread: the task works out a hand-over only for a prop that moved", "[props][threads]")
{
    // A sleeping prop costs nothing, its hand-over included: its state, and so its last forecast, is unchanged.
    OffThreadWall scene;
    common::WorldFixture& fixture = scene.mFixture;
    PropWorld* props = scene.mProps.get();
    const PropId wall = scene.mWall;
    REQUIRE(props->TakeLooseFragments());
    REQUIRE(props->TakeChangedShape(wall, cShapeCell, cShapeTolerance));
    int awake = 0, asleep = 0;
    const auto step = [&] {
        REQUIRE(props->StartStep(1.0 / 120.0));
        Result<PropStepReport> report = props->LandStep();
        REQUIRE(report);
        awake += report.Get().mStepped;
        asleep += report.Get().mSleeping;
        REQUIRE(props->TakeLooseFragments());
        REQUIRE(props->TakeChangedShape(wall, cShapeCell, cShapeTolerance));
    };
    for (int i = 0; i < 10; ++i)
        step();
    CHECK(awake == 0);
    CHECK(asleep == 10);
    CHECK(props->GetHandOverStats().mForecastsMade == 0u);
    HitCentre(fixture, 20.0, 0.0);
    for (int i = 0; i < 10; ++i)
        step();
    REQUIRE(awake > 0);
    CHECK(props->GetHandOverStats().mForecastsMade == static_cast<std::uint64_t>(awake));
}
