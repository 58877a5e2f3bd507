// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/props/PropBody.h>
#include <crumple/props/PropWorld.h>

#include <crumple/base/ByteWriter.h>
#include <crumple/base/TimeStep.h>
#include <crumple/props/PropRecording.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

namespace crumple::props
{

Result<std::unique_ptr<PropWorld>> PropWorld::Create(plugin::DamageWorld& ioWorld, const PropWorldSettings& inSettings)
{
    std::unique_ptr<PropWorld> world(new PropWorld(ioWorld, inSettings));
    ioWorld.AddListener(world.get());
    return world;
}

PropWorld::~PropWorld()
{
    WaitForStep();
    mWorld->RemoveListener(this);
}

bool PropWorld::StepsOnTasks() const
{
    const JobSystem* jobs = mWorld->GetSettings().mJobs;
    return mSettings.mStepOffThread && jobs != nullptr && jobs->mStartTask != nullptr && jobs->mWaitTask != nullptr;
}

void PropWorld::WaitForStep() const
{
    if (!HasStepInFlight() || mInFlight->mWaited)
        return;
    if (mInFlight->mOnJobs)
        mWorld->GetSettings().mJobs->mWaitTask(mWorld->GetSettings().mJobs->mHost, mInFlight->mTicket);
    mInFlight->mWaited = true;
}

namespace
{

// intent: a FemProp that was moved from has no solver left: as a prop it would take its body's collisions
// and refuse every one, and a recording of it would not replay
Status CheckNotEmpty(const FemProp& inProp, const char* inWhat)
{
    if (inProp.GetNodeCount() > 0)
        return Status::Ok();
    return MakeError(EError::InvalidArgument,
                     std::string(inWhat) + ": the prop is empty (no nodes: a FemProp that was moved from)");
}

} // namespace

Result<PropId> PropWorld::AddProp(plugin::BodyId inBody, FemProp&& ioProp)
{
    WaitForStep(); // intent: the list of props may grow (move) only while no task steps them
    if (Status filled = CheckNotEmpty(ioProp, "PropWorld::AddProp"); filled.HasError())
        return filled.GetError();
    if (mWorld->GetBodyState(inBody) == nullptr)
        return MakeError(EError::OutOfRange, "PropWorld::AddProp: body " + std::to_string(inBody.mValue) +
                                                 " is not in the world");
    if (FindProp(inBody).IsValid())
        return MakeError(EError::InvalidArgument,
                         "PropWorld::AddProp: body " + std::to_string(inBody.mValue) + " already has a prop");
    if (mRecorder != nullptr)
    {
        Result<std::vector<std::byte>> setup = RecordedSetup(inBody, ioProp);
        if (setup.HasError())
            return setup.GetError();
        if (Status status = mRecorder->WriteExtension(static_cast<std::uint32_t>(EPropRecord::Added), setup.Get());
            status.HasError())
            return status.GetError();
    }
    // intent: a body the engine moves (a held or a free prop) cannot wait for the world's time window: the
    // prop's FEM must hear of each hit before the next step, so its collisions are dispatched every step
    if (mWorld->GetBodyState(inBody)->mMotionType != plugin::EMotionType::Static)
        (void)mWorld->SetDispatchEachStep(inBody, true); // the body exists: checked above
    mProps.push_back(Prop{.mBody = inBody, .mProp = std::move(ioProp)});
    // intent: a prop stepped on a task splits nothing over the job system (a task must not call back into it)
    if (fem::TetSolver* cpu = mProps.back().mProp.GetCpuSolver(); cpu != nullptr)
        cpu->SetJobSystem(StepsOnTasks() ? nullptr : mWorld->GetSettings().mJobs);
    return PropId{static_cast<std::uint32_t>(mProps.size() - 1)};
}

Status PropWorld::RemoveProp(PropId inProp)
{
    // intent: the task of a step in flight reads every prop; the caller lands it first (as StartStep asks)
    if (HasStepInFlight())
        return MakeError(EError::InvalidArgument,
                         "PropWorld::RemoveProp: a step is in flight; LandStep first");
    if (inProp.mValue >= mProps.size())
        return MakeError(EError::OutOfRange,
                         "PropWorld::RemoveProp: no prop " + std::to_string(inProp.mValue));
    if (mProps[inProp.mValue].IsRemoved())
        return MakeError(EError::InvalidArgument, "PropWorld::RemoveProp: prop " +
                                                      std::to_string(inProp.mValue) + " was removed already");
    if (mRecorder != nullptr)
    {
        ByteWriter record;
        record.WriteU32(inProp.mValue);
        if (Status status = mRecorder->WriteExtension(static_cast<std::uint32_t>(EPropRecord::Removed),
                                                      record.GetBytes());
            status.HasError())
            return status;
    }
    const plugin::BodyId body = mProps[inProp.mValue].mBody;
    // intent: everything of the prop goes (its FEM with its device buffers, hits, shape, forecast); the slot
    // stays so that no later prop takes its id
    Prop& prop = mProps[inProp.mValue];
    {
        const FemProp released = std::move(prop.mProp); // its solver and device buffers go with this
    }
    prop = Prop{.mBody = plugin::BodyId(), .mProp = std::move(prop.mProp)}; // moved from: empty
    // intent: a body the game keeps goes back to the world's time window (off, as AddProp found it unless the
    // game had set it itself)
    if (mWorld->GetBodyState(body) != nullptr)
        (void)mWorld->SetDispatchEachStep(body, false); // the body exists: checked
    return Status::Ok();
}

Status PropWorld::CheckCanAdd(const FemProp& inProp) const
{
    if (Status filled = CheckNotEmpty(inProp, "PropWorld::CheckCanAdd"); filled.HasError())
        return filled;
    if (mRecorder == nullptr)
        return Status::Ok();
    if (Status recorder = mRecorder->GetStatus(); recorder.HasError())
        return recorder;
    if (!mRecorder->IsOpen())
        return MakeError(EError::InvalidArgument, "PropWorld: the recorder is closed");
    Result<std::vector<std::byte>> setup = RecordedSetup(plugin::BodyId{}, inProp);
    return setup.HasError() ? Status(setup.GetError()) : Status::Ok();
}

Result<std::vector<std::byte>> PropWorld::RecordedSetup(plugin::BodyId inBody, const FemProp& inProp) const
{
    Result<PropSetup> setup = MakePropSetup(inBody, inProp);
    if (setup.HasError())
        return setup.GetError();
    return EncodePropSetup(setup.Get());
}

Status PropWorld::AttachRecorder(plugin::DamageRecorder* ioRecorder)
{
    if (ioRecorder == nullptr)
    {
        mRecorder = nullptr;
        return Status::Ok();
    }
    // intent: a second attach would write every prop's setup again (a replay would make two of each)
    if (mRecorder != nullptr)
        return MakeError(EError::InvalidArgument, "PropWorld::AttachRecorder: a recorder is attached; detach it (nullptr) first");
    if (Status recorder = ioRecorder->GetStatus(); recorder.HasError())
        return recorder;
    if (!ioRecorder->IsOpen())
        return MakeError(EError::InvalidArgument, "PropWorld::AttachRecorder: the recorder is closed");
    // intent: a replay numbers the props in the order the recording adds them; a removed one would shift the
    // ids of those after it
    if (std::any_of(mProps.begin(), mProps.end(), [](const Prop& inProp) { return inProp.IsRemoved(); }))
        return MakeError(
            EError::InvalidArgument,
            "PropWorld::AttachRecorder: a prop was removed; attach the recorder before the first RemoveProp");
    // intent: collisions dispatched before the recording reach the props at the next step; a replay would
    // not have them
    if (!mQueued.empty())
        return MakeError(EError::InvalidArgument, "PropWorld::AttachRecorder: " + std::to_string(mQueued.size()) +
                                                      " collisions wait for the next step; attach the recorder before the first hit");
    WaitForStep();
    // Every prop so far must be recordable before any is written.
    std::vector<std::vector<std::byte>> setups;
    for (const Prop& prop : mProps)
    {
        Result<std::vector<std::byte>> setup = RecordedSetup(prop.mBody, prop.mProp);
        if (setup.HasError())
            return setup.GetError();
        setups.push_back(std::move(setup).Get());
    }
    // intent: a replay must know before the first collision that collisions reach the props at the steps
    if (mSettings.mStepOffThread)
        if (Status status = ioRecorder->WriteExtension(static_cast<std::uint32_t>(EPropRecord::Queued), {}); status.HasError())
            return status;
    for (const std::vector<std::byte>& setup : setups)
        if (Status status = ioRecorder->WriteExtension(static_cast<std::uint32_t>(EPropRecord::Added), setup);
            status.HasError())
            return status;
    mRecorder = ioRecorder;
    return Status::Ok();
}

FemProp* PropWorld::GetProp(PropId inProp)
{
    WaitForStep();
    return inProp.mValue < mProps.size() && !mProps[inProp.mValue].IsRemoved() ? &mProps[inProp.mValue].mProp
                                                                               : nullptr;
}

const FemProp* PropWorld::GetProp(PropId inProp) const
{
    WaitForStep();
    return inProp.mValue < mProps.size() && !mProps[inProp.mValue].IsRemoved() ? &mProps[inProp.mValue].mProp
                                                                               : nullptr;
}

PropId PropWorld::FindProp(plugin::BodyId inBody) const
{
    for (std::size_t index = 0; index < mProps.size(); ++index)
        if (!mProps[index].IsRemoved() && mProps[index].mBody == inBody)
            return PropId{static_cast<std::uint32_t>(index)};
    return PropId{};
}

Result<PropStepReport> PropWorld::Step(double inDeltaTime)
{
    if (Status started = StartStep(inDeltaTime); !started)
        return started.GetError();
    return LandStep();
}

Status PropWorld::StartStep(double inDeltaTime)
{
    if (Status valid = CheckTimeStep(inDeltaTime, "PropWorld::Step"); !valid)
        return valid;
    if (HasStepInFlight())
        return MakeError(EError::InvalidArgument, "PropWorld::Step: a step is in flight; LandStep first");
    // intent: a step some prop refuses is refused before any prop steps or the recording takes it
    for (std::size_t index = 0; index < mProps.size(); ++index)
        if (Status valid =
                mProps[index].IsRemoved() ? Status::Ok() : mProps[index].mProp.CheckStep(inDeltaTime);
            valid.HasError())
        {
            Error error = valid.GetError();
            error.mMessage = "PropWorld::Step: prop " + std::to_string(index) + ": " + error.mMessage;
            return error;
        }
    if (mRecorder != nullptr)
    {
        ByteWriter step;
        step.WriteDouble(inDeltaTime);
        if (Status status = mRecorder->WriteExtension(static_cast<std::uint32_t>(EPropRecord::Step), step.GetBytes());
            status.HasError())
            return status;
    }
    if (mInFlight == nullptr)
        mInFlight = std::make_unique<InFlight>();
    InFlight& flight = *mInFlight;
    flight.mOwner = this;
    flight.mDeltaTime = inDeltaTime;
    flight.mReport = PropStepReport();
    flight.mStatus = Status::Ok();
    flight.mTally = CollisionTally();
    flight.mForecastsMade = 0;
    // The collisions that waited reach the props just before the step, in dispatch order (as they would have
    // when dispatched: nothing changes a prop between its steps but a hand-over of loose pieces): on the
    // task for the props it steps.
    flight.mCollisions.clear();
    flight.mCollisions.swap(mQueued);
    const JobSystem* jobs = mWorld->GetSettings().mJobs;
    flight.mOnJobs = StepsOnTasks();
    flight.mOnTask.assign(mProps.size(), 0);
    flight.mBodyRotations.assign(mProps.size(), std::nullopt);
    for (std::size_t index = 0; index < mProps.size(); ++index)
    {
        // intent: the body's frame as the step starts, read here: the engine moves bodies while the task runs
        if (const plugin::BodyState* state = mWorld->GetBodyState(mProps[index].mBody); state != nullptr)
            flight.mBodyRotations[index] = state->mTransform.mRotation;
        // intent: GPU props on the game's thread, where their context is current; the rest on the task (all
        // of them, in PropId order, when the task runs inline)
        const bool cpu = !mProps[index].IsRemoved() && mProps[index].mProp.GetCpuSolver() != nullptr;
        flight.mOnTask[index] = !flight.mOnJobs || cpu ? 1 : 0;
    }
    flight.mWaited = false;
    flight.mActive = true;
    RunPart(flight, false);
    if (flight.mOnJobs)
        flight.mTicket = jobs->mStartTask(jobs->mHost, &PropWorld::RunStep, &flight);
    else
        RunStep(&flight);
    return Status::Ok();
}

void PropWorld::RunStep(void* inFlight)
{
    auto* flight = static_cast<InFlight*>(inFlight);
    flight->mOwner->RunPart(*flight, true);
}

void PropWorld::RunPart(InFlight& ioFlight, bool inOnTask)
{
    const auto mine = [&ioFlight, inOnTask](std::size_t inProp) { return (ioFlight.mOnTask[inProp] != 0) == inOnTask; };
    for (const QueuedCollision& collision : ioFlight.mCollisions)
        ApplyToProps(collision.mCollision, collision.mPropCount, mine, collision.mStrikerSpeeds,
                     ioFlight.mTally);
    for (std::size_t index = 0; index < ioFlight.mOnTask.size() && ioFlight.mStatus.IsValid(); ++index)
        if (mine(index) && !mProps[index].IsRemoved())
        {
            const bool integrated = StepProp(ioFlight, index);
            // intent: only where the step runs as a task of its own (inline, the calls would do the same work
            // at once, and only when asked), and only for a prop that moved: a sleeping prop costs nothing,
            // and its last forecast still holds
            if (inOnTask && ioFlight.mOnJobs && integrated)
            {
                ForecastHandOver(mProps[index]);
                ++ioFlight.mForecastsMade;
            }
        }
}

bool PropWorld::StepProp(InFlight& ioFlight, std::size_t inIndex)
{
    Prop& prop = mProps[inIndex];
    Result<fem::TetStepResult> step = prop.mProp.Step(ioFlight.mDeltaTime);
    if (step.HasError())
    {
        Error error = step.GetError();
        error.mMessage = "PropWorld::Step: prop " + std::to_string(inIndex) + ": " + error.mMessage;
        ioFlight.mStatus = error;
        return false;
    }
    const fem::ETetStepEvent events = step.Get().mEvents;
    const bool sleeping = fem::HasEvent(events, fem::ETetStepEvent::Sleeping);
    ++(sleeping ? ioFlight.mReport.mSleeping : ioFlight.mReport.mStepped);
    ioFlight.mReport.mFractured += fem::HasEvent(events, fem::ETetStepEvent::Fractured) ? 1 : 0;
    ioFlight.mReport.mDiverged += fem::HasEvent(events, fem::ETetStepEvent::Diverged) ? 1 : 0;
    ioFlight.mReport.mSplit += fem::HasEvent(events, fem::ETetStepEvent::Split) &&
                                       !fem::HasEvent(events, fem::ETetStepEvent::Diverged)
                                   ? 1
                                   : 0;
    ioFlight.mReport.mNotConverged += fem::HasEvent(events, fem::ETetStepEvent::SolverNotConverged) ? 1 : 0;
    // intent: the taken nodes once for both, and only for a struck prop that handed pieces over
    const std::vector<std::uint8_t> taken =
        prop.mHits.empty() && prop.mStruck.empty() ? std::vector<std::uint8_t>() : TakenNodes(prop);
    prop.mSteppedVelocity = UpdateContactVelocity(prop, sleeping, ioFlight.mBodyRotations[inIndex], taken);
    prop.mSteppedMass = mSettings.mContactMass ? UpdateContactMass(prop, ioFlight.mDeltaTime, taken) : 0.0;
    return !sleeping;
}

Result<PropStepReport> PropWorld::LandStep()
{
    if (!HasStepInFlight())
        return PropStepReport();
    WaitForStep();
    InFlight& flight = *mInFlight;
    flight.mActive = false;
    for (std::size_t index = 0; index < flight.mOnTask.size(); ++index)
    {
        mProps[index].mContactVelocity = mProps[index].mSteppedVelocity;
        mProps[index].mContactMass = mProps[index].mSteppedMass;
    }
    mTally.mCollisions += flight.mTally.mCollisions;
    if (mTally.mRefused == 0 && flight.mTally.mRefused > 0)
        mTally.mFirstRefusal = flight.mTally.mFirstRefusal;
    mTally.mRefused += flight.mTally.mRefused;
    mHandOverStats.mForecastsMade += flight.mForecastsMade;
    flight.mCollisions.clear();
    if (flight.mStatus.HasError())
        return flight.mStatus.GetError();
    return flight.mReport;
}

Status PropWorld::Prepare(double inDeltaTime)
{
    if (Status valid = CheckTimeStep(inDeltaTime, "PropWorld::Prepare"); !valid)
        return valid;
    WaitForStep();
    for (Prop& prop : mProps)
        if (Status prepared = prop.IsRemoved() ? Status::Ok() : prop.mProp.Prepare(inDeltaTime); !prepared)
            return prepared; // cannot happen for a valid step: kept for a future backend's refusal
    return Status::Ok();
}

Result<std::vector<LooseFragment>> PropWorld::TakeLooseFragments(double inMinMass)
{
    if (!std::isfinite(inMinMass) || !(inMinMass >= 0.0))
        return MakeError(std::isfinite(inMinMass) ? EError::InvalidArgument : EError::NonFinite,
                         "PropWorld::TakeLooseFragments: the minimum mass must be finite and >= 0 kg");
    WaitForStep();
    // intent: every piece and its rigid body first
    std::vector<LooseFragment> loose;
    std::vector<Vec3> positions, velocities;
    for (std::size_t index = 0; index < mProps.size(); ++index)
    {
        Prop& prop = mProps[index];
        const plugin::BodyState* body = mWorld->GetBodyState(prop.mBody);
        if (body == nullptr)
            continue; // its body left the world: nothing of it is in the game's world to hand over
        prop.mTakenElements.resize(prop.mProp.GetElementNodes().size(), 0);
        // intent: a piece comes loose only when links break or anchors change; the pieces of an unchanged
        // prop (most steps of a swinging fence) are not worked out again
        if (IsSettled(prop))
            continue;
        // intent: positions read once, and only when needed: to check a forecast, or for pieces that leave (a
        // GPU prop's are read back from the device)
        const bool read_first = prop.mForecast.mHasFragments;
        if (read_first)
            prop.mProp.ReadPositions(positions);
        std::vector<fem::TetFragment> fragments;
        if (read_first && ForecastHolds(prop, positions, true))
        {
            fragments = std::move(prop.mForecast.mFragments);
            ++mHandOverStats.mFragmentsForecast;
        }
        else
        {
            fragments = prop.mProp.ComputeFragments();
            ++mHandOverStats.mFragmentsComputed;
        }
        prop.mForecast.mHasFragments = false;
        const std::vector<std::size_t> leaving = LeavingFragments(prop, fragments);
        if (leaving.empty())
            continue;
        if (!read_first)
            prop.mProp.ReadPositions(positions);
        prop.mProp.ReadVelocities(velocities);
        for (std::size_t f : leaving)
        {
            LooseFragment piece;
            piece.mProp = PropId{static_cast<std::uint32_t>(index)};
            piece.mElements = fragments[f].mElements;
            piece.mNodes = fragments[f].mNodes;
            piece.mDropped = fragments[f].mMass < inMinMass;
            if (!piece.mDropped)
            {
                // A piece no rigid body can stand for (crushed flat, its nodes coplanar) leaves without one.
                Result<FragmentRigidBody> rigid = FragmentBody(fragments[f], positions, velocities, prop.mProp.GetMasses(), *body);
                if (rigid.IsValid())
                    piece.mRigidBody = std::move(rigid).Get();
                else
                    piece.mDropped = true;
            }
            loose.push_back(std::move(piece));
        }
    }
    // intent: record (one write for all the pieces), then fix the pieces' nodes in their props. A recorder's
    // write error does not stop the hand-over (the game's world already holds what it returns): the recorder
    // keeps it (GetStatus, Close).
    if (mRecorder != nullptr && !loose.empty())
    {
        std::vector<std::vector<std::byte>> records;
        records.reserve(loose.size());
        for (const LooseFragment& piece : loose)
        {
            ByteWriter record;
            record.Reserve(sizeof(std::uint32_t) * (2 + piece.mNodes.size()));
            record.WriteU32(piece.mProp.mValue);
            record.WriteU32(static_cast<std::uint32_t>(piece.mNodes.size()));
            for (int node : piece.mNodes)
                record.WriteU32(static_cast<std::uint32_t>(node));
            records.push_back(record.TakeBytes());
        }
        (void)mRecorder->WriteExtensions(static_cast<std::uint32_t>(EPropRecord::Loose), records);
    }
    // intent: one SetNodesLeft per prop for all its pieces, in their order (the same nodes fixed in the same
    // order as one call per piece): each call walks every element of the prop, and 56 pieces leaving the
    // racing fence at once took 1.1 ms of the game's thread one call each
    std::vector<std::vector<int>> left_nodes(loose.empty() ? 0 : mProps.size());
    for (const LooseFragment& piece : loose)
    {
        Prop& prop = mProps[piece.mProp.mValue];
        ++prop.mPiecesTaken;
        std::vector<int>& nodes = left_nodes[piece.mProp.mValue];
        nodes.insert(nodes.end(), piece.mNodes.begin(), piece.mNodes.end());
        for (int element : piece.mElements)
            prop.mTakenElements[static_cast<std::size_t>(element)] = 1;
    }
    for (std::size_t index = 0; index < left_nodes.size(); ++index)
        if (!left_nodes[index].empty())
            (void)mProps[index].mProp.SetNodesLeft(
                left_nodes[index]); // its own fragments' nodes: cannot be refused
    // Every prop looked at has handed over all it had loose: settled until links break or anchors change.
    for (Prop& prop : mProps)
        if (mWorld->GetBodyState(prop.mBody) != nullptr)
            Settle(prop);
    return loose;
}

bool PropWorld::IsSettled(const Prop& inProp)
{
    if (inProp.mSettledBrokenLinks != inProp.mProp.GetBrokenLinkCount())
        return false;
    const std::vector<double>& inverse_masses = inProp.mProp.GetInverseMasses();
    if (inverse_masses.size() != inProp.mSettledFixed.size())
        return false;
    for (std::size_t node = 0; node < inverse_masses.size(); ++node)
        if ((inverse_masses[node] == 0.0) != (inProp.mSettledFixed[node] != 0))
            return false;
    return true;
}

void PropWorld::Settle(Prop& ioProp)
{
    ioProp.mSettledBrokenLinks = ioProp.mProp.GetBrokenLinkCount();
    const std::vector<double>& inverse_masses = ioProp.mProp.GetInverseMasses();
    ioProp.mSettledFixed.resize(inverse_masses.size());
    for (std::size_t node = 0; node < inverse_masses.size(); ++node)
        ioProp.mSettledFixed[node] = inverse_masses[node] == 0.0 ? 1 : 0;
}

Result<std::vector<std::vector<Vec3>>> PropWorld::PiecesOf(const Prop& inProp, std::span<const Vec3> inPositions, double inCellSize)
{
    return PiecesOf(inProp, inProp.mTakenElements, inPositions, inCellSize);
}

std::vector<std::uint8_t> PropWorld::TakenNodes(const Prop& inProp)
{
    if (std::find(inProp.mTakenElements.begin(), inProp.mTakenElements.end(), std::uint8_t{1}) ==
        inProp.mTakenElements.end())
        return {};
    const std::vector<fem::TetIndices>& elements = inProp.mProp.GetElementNodes();
    std::vector<std::uint8_t> taken(static_cast<std::size_t>(inProp.mProp.GetNodeCount()), 0);
    for (std::size_t element = 0; element < inProp.mTakenElements.size() && element < elements.size();
         ++element)
        if (inProp.mTakenElements[element] != 0)
            for (int node : elements[element])
                taken[static_cast<std::size_t>(node)] = 1;
    return taken;
}

Result<std::vector<std::vector<Vec3>>> PropWorld::PiecesOf(const Prop& inProp, std::span<const std::uint8_t> inTaken,
                                                           std::span<const Vec3> inPositions, double inCellSize)
{
    const std::vector<fem::TetIndices>& elements = inProp.mProp.GetElementNodes();
    std::vector<std::uint8_t> left_out(inTaken.begin(), inTaken.end());
    left_out.resize(elements.size(), 0);
    return PropCollisionPieces(inPositions, elements, left_out, inCellSize);
}

Status PropWorld::ValidateShapeQuery(PropId inProp, double inCellSize, const char* inWhat) const
{
    if (inProp.mValue >= mProps.size())
        return MakeError(EError::OutOfRange, std::string("PropWorld::") + inWhat + ": no prop " + std::to_string(inProp.mValue));
    if (mProps[inProp.mValue].IsRemoved())
        return MakeError(EError::OutOfRange, std::string("PropWorld::") + inWhat + ": prop " +
                                                 std::to_string(inProp.mValue) + " was removed");
    if (!std::isfinite(inCellSize) || !(inCellSize > 0.0))
        return MakeError(std::isfinite(inCellSize) ? EError::InvalidArgument : EError::NonFinite,
                         std::string("PropWorld::") + inWhat + ": the cell size must be finite and > 0 m");
    return Status::Ok();
}

Result<std::vector<std::vector<Vec3>>> PropWorld::GetCollisionPieces(PropId inProp, double inCellSize) const
{
    if (Status valid = ValidateShapeQuery(inProp, inCellSize, "GetCollisionPieces"); !valid)
        return valid.GetError();
    WaitForStep();
    const Prop& prop = mProps[inProp.mValue];
    std::vector<Vec3> positions;
    prop.mProp.ReadPositions(positions);
    return PiecesOf(prop, positions, inCellSize);
}

Result<std::optional<std::vector<std::vector<Vec3>>>> PropWorld::TakeChangedShape(PropId inProp, double inCellSize,
                                                                                 double inTolerance)
{
    if (Status valid = ValidateShapeQuery(inProp, inCellSize, "TakeChangedShape"); !valid)
        return valid.GetError();
    if (!std::isfinite(inTolerance) || !(inTolerance >= 0.0))
        return MakeError(std::isfinite(inTolerance) ? EError::InvalidArgument : EError::NonFinite,
                         "PropWorld::TakeChangedShape: the tolerance must be finite and >= 0 m");
    WaitForStep();
    // intent: the positions read once; the pieces built only when the shape changed (called every step)
    Prop& prop = mProps[inProp.mValue];
    std::vector<Vec3> positions;
    prop.mProp.ReadPositions(positions);
    prop.mShapeCellSize = inCellSize;
    prop.mShapeTolerance = inTolerance;
    // intent: the forecast checked only for a shape that changed (this runs at every step)
    const bool changed = ShapeChanged(prop, positions, inTolerance);
    const bool forecast = changed && ShapeForecastHolds(prop, positions, inCellSize);
    prop.mForecast.mHasPieces = false;
    if (!changed)
        return std::optional<std::vector<std::vector<Vec3>>>();
    Result<std::vector<std::vector<Vec3>>> pieces = forecast ? Result<std::vector<std::vector<Vec3>>>(std::move(prop.mForecast.mPieces))
                                                             : PiecesOf(prop, positions, inCellSize);
    ++(forecast ? mHandOverStats.mShapesForecast : mHandOverStats.mShapesComputed);
    if (pieces.HasError())
        return MakeError(pieces.GetError().mCode, "PropWorld::TakeChangedShape: " + pieces.GetError().mMessage);
    prop.mShapeRevision = prop.mPiecesTaken;
    prop.mShapePositions = std::move(positions);
    return std::optional<std::vector<std::vector<Vec3>>>(std::move(pieces).Get());
}

Vec3 PropWorld::UpdateContactVelocity(Prop& ioProp, bool inSleeping,
                                      const std::optional<Mat3>& inBodyRotation,
                                      std::span<const std::uint8_t> inTakenNodes)
{
    // The latest hits stand until new ones arrive: collisions reach the prop when the world dispatches them,
    // not at every engine step, and between them the struck material goes on moving (or is held back).
    if (!ioProp.mHits.empty())
    {
        ioProp.mStruck.swap(ioProp.mHits);
        ioProp.mHits.clear();
        ioProp.mStruckStrikerSpeed = ioProp.mHitsStrikerSpeed;
        ioProp.mHitsStrikerSpeed = 0.0;
    }
    if (inSleeping)
        ioProp.mStruck.clear();
    if (ioProp.mStruck.empty())
        return Vec3::Zero();
    // intent: the struck nodes' mean velocity, each weighted by the size of the impulse it took (body frame),
    // leaving out nodes of pieces handed over (fixed, they no longer move with the prop)
    // intent: the CPU solver's velocities in place; the GPU's read back
    std::vector<Vec3> read_back;
    const fem::TetSolver* cpu = ioProp.mProp.GetCpuSolver();
    if (cpu == nullptr)
        ioProp.mProp.ReadVelocities(read_back);
    const std::vector<Vec3>& velocities = cpu != nullptr ? cpu->GetVelocities() : read_back;
    Vec3 sum = Vec3::Zero();
    Vec3 impulse = Vec3::Zero();
    double weight = 0.0;
    for (const NodalImpulse& hit : ioProp.mStruck)
    {
        const auto node = static_cast<std::size_t>(hit.mNode);
        if (node < inTakenNodes.size() && inTakenNodes[node] != 0)
            continue;
        const double share = hit.mImpulse.norm();
        sum += share * velocities[node];
        impulse += hit.mImpulse;
        weight += share;
    }
    if (!(weight > 0.0) || !(impulse.norm() > 0.0) || !inBodyRotation)
        return Vec3::Zero();
    // intent: only along the direction the material was struck. The held body stands for the whole prop: moved
    // sideways or up with a timber flung so, it would carry the car with it.
    const Vec3 direction = impulse.normalized();
    // intent: no faster than what struck it, either way. The engine met the struck members with the whole
    // prop's mass, and the FEM hands those impulses to the few nodes they landed on: where those outran
    // their striker, the held body would carry the whole prop's mass at their speed into the next contact
    // (a car pressing a fence that held at 43 km/h met it at up to 59 m/s, 70 dents in 0.3 s).
    const double cap = ioProp.mStruckStrikerSpeed;
    const double speed = std::clamp(direction.dot(sum / weight), -cap, cap);
    return *inBodyRotation * (speed * direction);
}

double PropWorld::UpdateContactMass(Prop& ioProp, double inDeltaTime,
                                    std::span<const std::uint8_t> inTakenNodes)
{
    fem::TetSolver* cpu = ioProp.mProp.GetCpuSolver();
    if (cpu == nullptr || ioProp.mStruck.empty())
        return 0.0;
    // intent: the nodes, shares and direction UpdateContactVelocity weighs (body frame: the solver's), less
    // the anchored ones: a touch at a footing alone (a piece lying against it) would weigh the whole held
    // body as the ground, and the next contact with it, the car's, would meet a wall
    std::vector<int>& nodes = ioProp.mMassNodes;
    std::vector<double>& shares = ioProp.mMassShares;
    nodes.clear();
    shares.clear();
    Vec3 impulse = Vec3::Zero();
    const std::vector<double>& inverse_masses = cpu->GetInverseMasses();
    for (const NodalImpulse& hit : ioProp.mStruck)
    {
        const auto node = static_cast<std::size_t>(hit.mNode);
        if ((node < inTakenNodes.size() && inTakenNodes[node] != 0) || inverse_masses[node] == 0.0)
            continue;
        nodes.push_back(hit.mNode);
        shares.push_back(hit.mImpulse.norm());
        impulse += hit.mImpulse;
    }
    if (nodes.empty() || !(impulse.norm() > 0.0))
        return 0.0;
    // intent: refused cannot happen for struck nodes of the prop and a step it took; unconverged (block
    // Jacobi on a large prop) is no figure to weigh an engine body with: the held body keeps its own mass
    const Result<fem::TetContactMass> mass = cpu->ContactEffectiveMass(nodes, shares, impulse, inDeltaTime);
    if (!mass || !mass.Get().mConverged)
        return 0.0;
    return std::min(mass.Get().mMass, plugin::cMaxBodyMass);
}

void PropWorld::OnCollision(const plugin::Collision&, std::span<const plugin::ObjectDent>)
{
}

PropWorld::StrikerSpeeds PropWorld::MeasureStrikerSpeeds(const plugin::Collision& inCollision) const
{
    // The normal impulses on A (+j n; -j n on B) and their impulse-weighted point, in the world.
    Vec3 on_a = Vec3::Zero(), point = Vec3::Zero();
    double weight = 0.0;
    for (const plugin::CollisionContact& contact : inCollision.mContacts)
    {
        on_a += contact.mImpulse * contact.mNormal;
        point += contact.mImpulse * 0.5 * (contact.mPointOnA + contact.mPointOnB);
        weight += contact.mImpulse;
    }
    StrikerSpeeds speeds{0.0, 0.0};
    if (!(weight > 0.0) || !(on_a.norm() > 0.0))
        return speeds;
    point /= weight;
    // intent: the world's state now (after the collision's own steps): how fast the striker pushes the
    // struck members on
    const auto pushing = [&](plugin::BodyId inStriker, const Vec3& inPush)
    {
        const plugin::BodyState* striker = mWorld->GetBodyState(inStriker);
        if (striker == nullptr)
            return 0.0;
        const double speed = striker->PointVelocity(point).dot(inPush.normalized());
        return std::isfinite(speed) ? std::max(speed, 0.0) : 0.0;
    };
    speeds[0] = pushing(inCollision.mBodyB, on_a);
    speeds[1] = pushing(inCollision.mBodyA, -on_a);
    return speeds;
}

void PropWorld::OnBeforeCollision(const plugin::Collision& inCollision)
{
    // intent: off the game's thread, a collision of a prop's body waits for the next StartStep (a task may be
    // stepping the prop now); others are no prop's business
    if (!FindProp(inCollision.mBodyA).IsValid() && !FindProp(inCollision.mBodyB).IsValid())
        return;
    if (mSettings.mStepOffThread)
    {
        mQueued.push_back({inCollision, mProps.size(), MeasureStrikerSpeeds(inCollision)});
        return;
    }
    ApplyToProps(
        inCollision, mProps.size(), [](std::size_t) { return true; }, MeasureStrikerSpeeds(inCollision),
        mTally);
}

template <class Which>
void PropWorld::ApplyToProps(const plugin::Collision& inCollision, std::size_t inPropCount,
                             const Which& inWhich, const StrikerSpeeds& inStrikerSpeeds,
                             CollisionTally& ioTally)
{
    // Both bodies may carry a prop (a car hitting a fence carries none; two crates hitting each other two).
    for (const plugin::BodyId body : {inCollision.mBodyA, inCollision.mBodyB})
    {
        const PropId prop = FindProp(body);
        if (!prop.IsValid() || prop.mValue >= inPropCount || !inWhich(prop.mValue))
            continue;
        ++ioTally.mCollisions;
        Prop& hit = mProps[prop.mValue];
        if (Status status = hit.mProp.ApplyCollision(inCollision, body, &hit.mHits); status.HasError())
        {
            if (ioTally.mRefused++ == 0)
                ioTally.mFirstRefusal = status;
            continue;
        }
        hit.mHitsStrikerSpeed =
            std::max(hit.mHitsStrikerSpeed, inStrikerSpeeds[body == inCollision.mBodyA ? 0 : 1]);
    }
}

} // namespace crumple::props
