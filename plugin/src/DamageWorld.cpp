// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/base/Assert.h>
#include <crumple/plugin/BaraffImpulse.h>
#include <crumple/plugin/CampbellCrush.h>
#include <crumple/plugin/DamageWorld.h>
#include <crumple/plugin/FrictionalImpulses.h>

#include "BodyPairIndex.h"
#include "ContactBatches.h"
#include "PairSolve.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>
#include <utility>

namespace crumple::plugin
{

namespace
{

// inOf's collision shape box (BodyState::mShapeMin, mShapeMax) in inIn's body frame; unknown when inOf did not
// state its shape.
ShapeBox ShapeBoxIn(const BodyState& inOf, const BodyState& inIn)
{
    ShapeBox box;
    if (!inOf.mHasShapeBounds)
        return box;
    box.mCenter = inIn.mTransform.ToBody(inOf.mTransform.ToWorld(0.5 * (inOf.mShapeMin + inOf.mShapeMax)));
    box.mHalfAxes = inIn.mTransform.mRotation.transpose() * inOf.mTransform.mRotation *
                    (0.5 * (inOf.mShapeMax - inOf.mShapeMin)).asDiagonal();
    box.mKnown = true;
    return box;
}

// The dent of a collision this world grouped: its contacts were validated on submission and its impulses and
// energies come from bodies within BodyState's ranges, so DeformableObject::ApplyCollision cannot refuse it.
ffd::DentReport DispatchedDent(const Result<ffd::DentReport>& inDent)
{
    CRUMPLE_ASSERT(inDent.IsValid(), "a collision the world grouped was refused");
    return inDent ? inDent.Get() : ffd::DentReport{};
}

} // namespace

Result<std::unique_ptr<DamageWorld>> DamageWorld::Create(const DamageWorldSettings& inSettings)
{
    if (!(inSettings.mRestitution >= 0.0 && inSettings.mRestitution <= 1.0))
        return MakeError(EError::InvalidArgument, "DamageWorldSettings.mRestitution must be in [0, 1]");
    if (!(std::isfinite(inSettings.mRestingSpeed) && inSettings.mRestingSpeed >= 0.0))
        return MakeError(EError::InvalidArgument, "DamageWorldSettings.mRestingSpeed must be finite and >= 0 m/s");
    if (inSettings.mJobs != nullptr && (inSettings.mJobs->mParallelFor == nullptr || inSettings.mJobs->mWorkerCount < 1))
        return MakeError(EError::InvalidArgument,
                         "DamageWorldSettings.mJobs needs an mParallelFor and an mWorkerCount >= 1 (or pass null)");
    if (inSettings.mSpeculativeContacts != ESpeculativeContacts::StopAtSurface &&
        inSettings.mSpeculativeContacts != ESpeculativeContacts::ResolveWhole)
        return MakeError(EError::InvalidArgument,
                         "DamageWorldSettings.mSpeculativeContacts is not an ESpeculativeContacts value");
    if (inSettings.mMaxContactsPerPair < 9)
        return MakeError(EError::InvalidArgument, "DamageWorldSettings.mMaxContactsPerPair must be >= 9");
    if (inSettings.mFrictionSolve.mMaxSweeps < 1 || inSettings.mFrictionSolve.mSubspaceInterval < 0 ||
        inSettings.mFrictionSolve.mSubspaceMaxContacts < 0)
        return MakeError(EError::InvalidArgument, "DamageWorldSettings.mFrictionSolve needs mMaxSweeps >= 1, "
                                                  "mSubspaceInterval >= 0 and mSubspaceMaxContacts >= 0");
    if (inSettings.mDeferDents && (inSettings.mJobs == nullptr || inSettings.mJobs->mStartTask == nullptr ||
                                   inSettings.mJobs->mWaitTask == nullptr))
        return MakeError(EError::InvalidArgument,
                         "DamageWorldSettings.mDeferDents needs mJobs with mStartTask and mWaitTask");
    if (inSettings.mDeferImpulses && !inSettings.mDeferDents)
        return MakeError(EError::InvalidArgument, "DamageWorldSettings.mDeferImpulses needs mDeferDents");
    Result<CollisionGrouper> grouper = CollisionGrouper::Create(inSettings.mGrouping);
    if (!grouper)
        return grouper.GetError();
    return std::unique_ptr<DamageWorld>(new DamageWorld(inSettings, std::move(grouper).Get()));
}

DamageWorld::~DamageWorld()
{
    WaitForDents();
}

void DamageWorld::WaitForDents() const
{
    if (HasDentsInFlight())
        mSettings.mJobs->mWaitTask(mSettings.mJobs->mHost, mInFlight->mTicket);
}

void DamageWorld::RunDeferredDents(void* inInFlight)
{
    auto* flight = static_cast<InFlight*>(inInFlight);
    // intent: the impulses of the steps submitted since the last Update, in order (the grouper and the impact
    // memories are the task's until it lands); the dents are of collisions closed before them
    // intent: no job system here: a task never calls back into it (JobSystem)
    flight->mSubmissionsDropped += flight->mWorld->SolveSubmissions(flight->mSubmissions, nullptr);
    for (std::size_t i = 0; i < flight->mCollisions.size(); ++i)
        for (const DentTarget& target : flight->mTargets[i])
            flight->mDents[i].push_back({target.mObject, DispatchedDent(target.mDeformable->ApplyCollision(
                                                             flight->mCollisions[i], target.mSide))});
}

void DamageWorld::Land()
{
    if (!HasDentsInFlight())
        return;
    WaitForDents();
    InFlight& flight = *mInFlight;
    flight.mActive = false;
    mLanded.mSubmissionsDropped += flight.mSubmissionsDropped;
    flight.mSubmissionsDropped = 0;
    flight.mSubmissions.clear();
    // Take the batch out first: a listener that updates the world from its callback (DamageListener says it
    // must not) would start the next batch in this slot.
    const std::vector<Collision> collisions = std::move(flight.mCollisions);
    const std::vector<std::vector<DentTarget>> targets = std::move(flight.mTargets);
    const std::vector<std::vector<ObjectDent>> dents = std::move(flight.mDents);
    const std::vector<DamageListener*> listeners = std::move(flight.mListeners);
    flight.mCollisions.clear();
    flight.mTargets.clear();
    flight.mDents.clear();
    flight.mListeners.clear();
    // Publish every dented object once, then tell the listeners, collision by collision.
    std::vector<DeformableObject*> published;
    for (const std::vector<DentTarget>& collision_targets : targets)
        for (const DentTarget& target : collision_targets)
            if (std::find(published.begin(), published.end(), target.mDeformable) == published.end())
            {
                target.mDeformable->GetDeformer().Publish();
                published.push_back(target.mDeformable);
            }
    bool moved = false;
    for (std::size_t i = 0; i < collisions.size(); ++i)
        for (const ObjectDent& dent : dents[i])
        {
            mLanded.mVerticesMoved += dent.mReport.mVerticesMoved;
            if (dent.mReport.mVerticesMoved > 0)
            {
                ++mLanded.mObjectsDented;
                moved = true;
            }
        }
    if (moved)
        ++mShapeRevision;
    for (std::size_t i = 0; i < collisions.size(); ++i)
        for (DamageListener* listener : listeners)
            if (IsListening(listener))
                listener->OnCollision(collisions[i], dents[i]);
}

UpdateReport DamageWorld::TakeLandedReport()
{
    const UpdateReport report = mLanded;
    mLanded = {};
    return report;
}

UpdateReport DamageWorld::LandDents()
{
    Land();
    return TakeLandedReport();
}

Result<BodyId> DamageWorld::CreateBody(const BodyState& inState)
{
    if (Status valid = ValidateBodyState(inState); !valid)
        return valid.GetError();
    if (!mFreeBodies.empty())
    {
        const std::uint32_t index = mFreeBodies.back();
        mFreeBodies.pop_back();
        BodySlot& slot = mBodies[index];
        slot.mState = CanonicalBodyState(inState);
        slot.mAlive = true;
        slot.mDispatchEachStep = false;
        slot.mQuiet = false;
        return BodyId{index, slot.mGeneration};
    }
    if (mBodies.size() >= BodyId::cInvalid)
        return MakeError(EError::OutOfRange, "too many bodies");
    mBodies.push_back({CanonicalBodyState(inState), true, 0, false, {}, false});
    return BodyId{static_cast<std::uint32_t>(mBodies.size() - 1), 0};
}

Status DamageWorld::SetBodyState(BodyId inBody, const BodyState& inState)
{
    if (!IsLive(inBody))
        return MakeError(EError::OutOfRange, "SetBodyState: body " + std::to_string(inBody.mValue) + " does not exist");
    if (Status valid = ValidateBodyState(inState); !valid)
        return valid;
    mBodies[inBody.mValue].mState = CanonicalBodyState(inState);
    return Status::Ok();
}

const BodyState* DamageWorld::GetBodyState(BodyId inBody) const
{
    return IsLive(inBody) ? &mBodies[inBody.mValue].mState : nullptr;
}

Status DamageWorld::RemoveBody(BodyId inBody)
{
    if (!IsLive(inBody))
        return MakeError(EError::OutOfRange, "RemoveBody: body " + std::to_string(inBody.mValue) + " does not exist");
    Land(); // its objects may be denting
    SolvePendingHere(); // its open collisions and memories, this step's included, go with it
    BodySlot& slot = mBodies[inBody.mValue];
    for (ObjectId object : slot.mObjects)
    {
        ObjectSlot& freed = mObjects[object.mValue];
        freed.mObject.clear();
        freed.mBody = BodyId{};
        ++freed.mGeneration; // the removed object's id is stale from now on
        mFreeObjects.push_back(object.mValue);
    }
    slot.mObjects.clear();
    if (slot.mQuiet)
        --mQuietBodies;
    slot.mQuiet = false;
    slot.mAlive = false;
    ++slot.mGeneration;
    mFreeBodies.push_back(inBody.mValue);
    mGrouper.Forget(inBody);
    ForgetMemoriesOf(inBody);
    return Status::Ok();
}

Status DamageWorld::ForgetImpacts(BodyId inBody)
{
    if (!IsLive(inBody))
        return MakeError(EError::OutOfRange, "ForgetImpacts: body " + std::to_string(inBody.mValue) + " does not exist");
    if (mSettings.mDeferImpulses)
    {
        // intent: in order with the submissions around it, on the task that solves them
        mPending.push_back(Submission{.mForget = inBody});
        return Status::Ok();
    }
    ForgetMemoriesOf(inBody);
    return Status::Ok();
}

Status DamageWorld::SetDispatchEachStep(BodyId inBody, bool inEachStep)
{
    if (!IsLive(inBody))
        return MakeError(EError::OutOfRange, "SetDispatchEachStep: body " + std::to_string(inBody.mValue) + " does not exist");
    mBodies[inBody.mValue].mDispatchEachStep = inEachStep;
    return Status::Ok();
}

Status DamageWorld::SetQuiet(BodyId inBody, bool inQuiet)
{
    if (!IsLive(inBody))
        return MakeError(EError::OutOfRange,
                         "SetQuiet: body " + std::to_string(inBody.mValue) + " does not exist");
    bool& quiet = mBodies[inBody.mValue].mQuiet;
    if (inQuiet != quiet)
        inQuiet ? ++mQuietBodies : --mQuietBodies;
    quiet = inQuiet;
    return Status::Ok();
}

Result<ObjectId> DamageWorld::CreateDeformableObject(BodyId inBody, const DeformableObjectSettings& inSettings)
{
    if (!IsLive(inBody))
        return MakeError(EError::OutOfRange,
                         "CreateDeformableObject: body " + std::to_string(inBody.mValue) + " does not exist");
    Result<DeformableObject> object = DeformableObject::Create(inSettings);
    if (!object)
        return object.GetError();
    Land(); // mObjects may grow: the task points into it
    // Deferred dents run on the task's thread and never call the parallel for from it.
    object.Get().GetDeformer().SetJobSystem(mSettings.mDeferDents ? nullptr : mSettings.mJobs);
    object.Get().GetDeformer().SetPublishing(mSettings.mDeferDents);
    ObjectId id;
    if (!mFreeObjects.empty())
    {
        id = ObjectId{mFreeObjects.back(), mObjects[mFreeObjects.back()].mGeneration};
        mFreeObjects.pop_back();
    }
    else if (mObjects.size() < ObjectId::cInvalid)
    {
        id = ObjectId{static_cast<std::uint32_t>(mObjects.size()), 0};
        mObjects.emplace_back();
    }
    else
        return MakeError(EError::OutOfRange, "too many deformable objects");
    ObjectSlot& slot = mObjects[id.mValue];
    slot.mBody = inBody;
    slot.mObject.push_back(std::move(object).Get());
    mBodies[inBody.mValue].mObjects.push_back(id);
    return id;
}

const DeformableObject* DamageWorld::GetObject(ObjectId inObject) const
{
    if (inObject.mValue >= mObjects.size() || mObjects[inObject.mValue].mObject.empty() ||
        mObjects[inObject.mValue].mGeneration != inObject.mGeneration)
        return nullptr;
    return &mObjects[inObject.mValue].mObject.front();
}

DeformableObject* DamageWorld::GetMutableObject(ObjectId inObject)
{
    if (inObject.mValue >= mObjects.size() || mObjects[inObject.mValue].mObject.empty() ||
        mObjects[inObject.mValue].mGeneration != inObject.mGeneration)
        return nullptr;
    return &mObjects[inObject.mValue].mObject.front();
}

std::vector<ffd::VertexRange> DamageWorld::TakeDirtyRanges(ObjectId inObject)
{
    DeformableObject* object = GetMutableObject(inObject);
    return object != nullptr ? object->GetDeformer().TakeDirtyRanges() : std::vector<ffd::VertexRange>{};
}

BodyId DamageWorld::GetObjectBody(ObjectId inObject) const
{
    return GetObject(inObject) != nullptr ? mObjects[inObject.mValue].mBody : BodyId{};
}

std::vector<ObjectId> DamageWorld::GetObjectIds() const
{
    std::vector<ObjectId> ids;
    for (std::uint32_t i = 0; i < mObjects.size(); ++i)
        if (!mObjects[i].mObject.empty())
            ids.push_back(ObjectId{i, mObjects[i].mGeneration});
    return ids;
}

Status DamageWorld::ValidateContact(const ContactEvent& inContact, std::size_t inIndex) const
{
    // intent: the message's prefix made only for a refusal (this runs for every contact of every step)
    const auto where = [inIndex] { return "contact " + std::to_string(inIndex) + ": "; };
    if (!IsLive(inContact.mBodyA) || !IsLive(inContact.mBodyB))
        return MakeError(EError::OutOfRange, where() + "names a body that does not exist");
    if (inContact.mBodyA == inContact.mBodyB)
        return MakeError(EError::InvalidArgument, where() + "a body cannot collide with itself");
    if (!IsFinite(inContact.mPointOnA) || !IsFinite(inContact.mPointOnB) || !IsFinite(inContact.mNormal) ||
        !IsFinite(inContact.mPenetrationDepth) || !IsFinite(inContact.mTime))
        return MakeError(EError::NonFinite, where() + "has a NaN or Inf field");
    if (!(inContact.mFriction >= 0.0)) // NaN too; +inf is a surface that never slides
        return MakeError(std::isnan(inContact.mFriction) ? EError::NonFinite : EError::InvalidArgument,
                         where() + "mFriction must be >= 0 (or +inf)");
    if (std::abs(inContact.mNormal.norm() - 1.0) > 1.0e-3)
        return MakeError(EError::InvalidArgument, where() + "mNormal must be a unit vector");
    // Within twice the bodies' range (BodyState.h), so lever arms and impulses stay far from overflow.
    if (!(inContact.mPointOnA.cwiseAbs().maxCoeff() <= 2.0 * cMaxBodyPosition) ||
        !(inContact.mPointOnB.cwiseAbs().maxCoeff() <= 2.0 * cMaxBodyPosition) ||
        !(std::abs(inContact.mPenetrationDepth) <= cMaxBodyPosition))
        return MakeError(EError::OutOfRange, where() + "a point or the depth is farther than 2e9 m from the world's origin");
    return Status::Ok();
}

Status DamageWorld::SubmitContacts(std::span<const ContactEvent> inContacts, double inTimeStep)
{
    if (!(std::isfinite(inTimeStep) && inTimeStep >= 0.0))
        return MakeError(std::isfinite(inTimeStep) ? EError::InvalidArgument : EError::NonFinite,
                         "SubmitContacts: the time step must be finite and >= 0 s");
    // Validate everything first: a refused batch changes nothing.
    for (std::size_t i = 0; i < inContacts.size(); ++i)
        if (Status valid = ValidateContact(inContacts[i], i); !valid)
            return valid;
    // intent: the contacts of pairs with a body that is not quiet, in their order, copied (into a buffer kept
    // between calls) only when some pair is quiet
    if (mQuietBodies > 0)
    {
        const auto quiet_pair = [&](const ContactEvent& inContact)
        { return mBodies[inContact.mBodyA.mValue].mQuiet && mBodies[inContact.mBodyB.mValue].mQuiet; };
        if (std::any_of(inContacts.begin(), inContacts.end(), quiet_pair))
        {
            mHeardScratch.clear();
            std::copy_if(inContacts.begin(), inContacts.end(), std::back_inserter(mHeardScratch),
                         [&](const ContactEvent& inContact) { return !quiet_pair(inContact); });
            inContacts = mHeardScratch;
        }
    }
    if (inContacts.empty())
        return Status::Ok(); // a step without contacts changes nothing (its pairs' memories expire later)
    if (!mSettings.mDeferImpulses)
        return SolveContacts(inContacts, inTimeStep, SnapshotBodies(inContacts), mSettings.mJobs);
    mPending.push_back(Submission{.mContacts = {inContacts.begin(), inContacts.end()},
                                  .mTimeStep = inTimeStep,
                                  .mBodies = SnapshotBodies(inContacts)});
    return Status::Ok();
}

std::vector<DamageWorld::SubmittedBody> DamageWorld::SnapshotBodies(std::span<const ContactEvent> inContacts)
{
    // intent: a flag per body slot finds the distinct bodies in one pass (a manifold of 10,000 contacts names
    // two); only those are sorted and copied. The flags are kept between calls, all clear (no allocation per
    // step once the world has its bodies).
    mNamedScratch.resize(mBodies.size(), 0);
    std::vector<BodyId> ids;
    for (const ContactEvent& contact : inContacts)
        for (BodyId body : {contact.mBodyA, contact.mBodyB})
            if (mNamedScratch[body.mValue] == 0)
            {
                mNamedScratch[body.mValue] = 1;
                ids.push_back(body);
            }
    for (BodyId id : ids)
        mNamedScratch[id.mValue] = 0;
    std::sort(ids.begin(), ids.end());
    std::vector<SubmittedBody> bodies;
    bodies.reserve(ids.size());
    for (BodyId id : ids)
        bodies.push_back({id, mBodies[id.mValue].mState, mBodies[id.mValue].mDispatchEachStep});
    return bodies;
}

void DamageWorld::ForgetMemoriesOf(BodyId inBody)
{
    std::erase_if(mImpactMemories, [&](const ImpactMemory& m) { return m.mA == inBody || m.mB == inBody; });
}

Status DamageWorld::SolveSubmission(const Submission& inSubmission, const JobSystem* inJobs)
{
    if (inSubmission.mForget.IsValid())
    {
        ForgetMemoriesOf(inSubmission.mForget);
        return Status::Ok();
    }
    return SolveContacts(inSubmission.mContacts, inSubmission.mTimeStep, inSubmission.mBodies, inJobs);
}

void DamageWorld::SolvePendingHere()
{
    // intent: what waited for the next task; each submission was validated when it came (a non-finite
    // impulse drops it whole, as on the task)
    std::vector<Submission> pending = std::move(mPending);
    mPending.clear();
    mLanded.mSubmissionsDropped += SolveSubmissions(pending, mSettings.mJobs);
}

int DamageWorld::SolveSubmissions(std::span<const Submission> inSubmissions, const JobSystem* inJobs)
{
    int dropped = 0;
    for (const Submission& submission : inSubmissions)
        if (SolveSubmission(submission, inJobs).HasError())
            ++dropped;
    return dropped;
}

const DamageWorld::SubmittedBody& DamageWorld::SubmittedBodyOf(std::span<const SubmittedBody> inBodies,
                                                               BodyId inBody)
{
    const auto found =
        std::lower_bound(inBodies.begin(), inBodies.end(), inBody,
                         [](const SubmittedBody& inEntry, BodyId inId) { return inEntry.mBody < inId; });
    CRUMPLE_ASSERT(found != inBodies.end() && found->mBody == inBody,
                   "a contact's body is not in its submission");
    return *found;
}

Status DamageWorld::SolveContacts(std::span<const ContactEvent> inContacts, double inTimeStep,
                                  std::span<const SubmittedBody> inBodies, const JobSystem* inJobs)
{
    // Canonical orientation (A = lower id), surface points, and batches of the same pair and time.
    std::vector<ContactBatch> batches = GroupContactBatches(inContacts, cSameStepTime);
    // intent: each pair's impact memory by an index (a pair has at most one): a burst of hundreds of pairs
    // would otherwise scan every memory for every batch. Built per call from every live memory, and again
    // after the expiry below shifts them: O(memories) per call, where the scan cost O(batches x memories)
    BodyPairIndex memory_of;
    const auto index_memories = [&](std::size_t inMore)
    {
        memory_of.Reset(mImpactMemories.size() + inMore);
        for (std::size_t i = 0; i < mImpactMemories.size(); ++i)
            memory_of.TryInsert(mImpactMemories[i].mA, mImpactMemories[i].mB, static_cast<std::uint32_t>(i));
    };
    index_memories(0);

    // Impulses per batch, from the bodies as they were when the contacts came (on the task, the game has
    // moved on since). A pair that already took an impulse at the previous step is solved from the velocities
    // that impulse left it with (ImpactMemory), not from the engine's: a soft engine needs several steps to
    // stop a car, and each of them would otherwise count the closing speed it has not removed yet once more.
    std::vector<PairSolve> solves;
    solves.reserve(batches.size());
    std::vector<std::size_t> closing_batches; // intent: the batches whose solve has work
    std::size_t closing = 0;
    for (std::size_t b = 0; b < batches.size(); ++b)
    {
        ContactBatch& batch = batches[b];
        const std::uint32_t found = memory_of.Find(batch.mA, batch.mB);
        const ImpactMemory* previous = found == BodyPairIndex::cNone ? nullptr : &mImpactMemories[found];
        // intent: the same step's contacts submitted in a later call (a game that submits per manifold) also
        // continue from what the earlier call's impulse left: they are the same impact, counted once
        const bool continues = mSettings.mCountImpactOnce && previous != nullptr && inTimeStep > 0.0 &&
                               batch.mTime >= previous->mTime - cSameStepTime &&
                               batch.mTime - previous->mTime <= cImpactMemorySteps * inTimeStep;
        const PairVelocities continued = continues
                                             ? PairVelocities{previous->mLinearA, previous->mAngularBodyA,
                                                              previous->mLinearB, previous->mAngularBodyB}
                                             : PairVelocities{};
        solves.push_back(PreparePairSolve(batch, SubmittedBodyOf(inBodies, batch.mA).mState,
                                          SubmittedBodyOf(inBodies, batch.mB).mState,
                                          continues ? &continued : nullptr, inTimeStep, mSettings));
        closing += solves.back().mClosing;
        if (solves.back().mClosing > 0)
            closing_batches.push_back(b);
        else
            SolvePair(solves.back(), mSettings);
    }
    // intent: a burst's closing pairs split over the host's workers, several pieces per worker (one pair's
    // solve can cost a hundred others'); a step with fewer closing contacts (resting pieces, one car's hit)
    // solves inline, where handing pieces over would cost more than it saves. Each solve writes only its own
    // answer, so they solve in any order, on any thread, to the same bits.
    const std::size_t pieces =
        inJobs == nullptr || inJobs->mParallelFor == nullptr || inJobs->mWorkerCount <= 1 ||
                closing < cParallelClosingContacts
            ? 1
            : std::min(closing_batches.size(),
                       cPiecesPerWorker * static_cast<std::size_t>(inJobs->mWorkerCount));
    const auto solve_piece = [&](std::size_t inPiece)
    {
        const std::size_t count = closing_batches.size();
        for (std::size_t i = inPiece * count / pieces; i < (inPiece + 1) * count / pieces; ++i)
            SolvePair(solves[closing_batches[i]], mSettings);
    };
    if (pieces <= 1)
        solve_piece(0);
    else
        ParallelFor(inJobs, static_cast<int>(pieces),
                    [&](int inPiece) { solve_piece(static_cast<std::size_t>(inPiece)); });

    // The contacts that push, in batch order; a step with an impulse not finite is refused whole.
    std::vector<std::vector<CollisionContact>> accepted(batches.size());
    std::vector<ImpactMemory> memories;
    for (std::size_t b = 0; b < batches.size(); ++b)
    {
        Result<AcceptedPair> pair = AcceptPairSolve(batches[b], solves[b], mSettings, accepted[b]);
        if (!pair)
            return pair.GetError();
        const PairVelocities& left = pair.Get().mLeft;
        if (pair.Get().mPushed || solves[b].mContinues)
            memories.push_back({batches[b].mA, batches[b].mB, batches[b].mTime, left.mLinearA,
                                left.mAngularBodyA, left.mLinearB, left.mAngularBodyB});
    }
    // Everything validated: commit. Memories of pairs that did not touch within the last steps expire.
    const double latest = batches.empty() ? 0.0
                                          : std::max_element(batches.begin(), batches.end(),
                                                             [](const ContactBatch& x, const ContactBatch& y)
                                                             { return x.mTime < y.mTime; })
                                                ->mTime;
    if (!batches.empty())
        std::erase_if(mImpactMemories, [&](const ImpactMemory& m) {
            return !(latest - m.mTime <= cImpactMemorySteps * inTimeStep);
        });
    index_memories(memories.size());
    for (const ImpactMemory& memory : memories)
    {
        const auto [found, is_new] =
            memory_of.TryInsert(memory.mA, memory.mB, static_cast<std::uint32_t>(mImpactMemories.size()));
        if (is_new)
            mImpactMemories.push_back(memory);
        else
            mImpactMemories[found] = memory;
    }
    for (std::size_t b = 0; b < batches.size(); ++b)
    {
        const SubmittedBody& slot_a = SubmittedBodyOf(inBodies, batches[b].mA);
        const SubmittedBody& slot_b = SubmittedBodyOf(inBodies, batches[b].mB);
        mGrouper.Add(batches[b].mA, batches[b].mB, accepted[b], slot_a.mDispatchEachStep || slot_b.mDispatchEachStep,
                     {ShapeBoxIn(slot_b.mState, slot_a.mState), ShapeBoxIn(slot_a.mState, slot_b.mState)});
    }
    return Status::Ok();
}

namespace
{

void Add(UpdateReport& ioReport, const UpdateReport& inMore)
{
    ioReport.mCollisionsDispatched += inMore.mCollisionsDispatched;
    ioReport.mObjectsDented += inMore.mObjectsDented;
    ioReport.mVerticesMoved += inMore.mVerticesMoved;
    ioReport.mSubmissionsDropped += inMore.mSubmissionsDropped;
}

} // namespace

UpdateReport DamageWorld::Update(double inTime)
{
    // The idle path: nothing in flight, no open collision, nothing submitted, no work. A non-finite time
    // closes nothing (and submissions wait for the next Update).
    Land();
    UpdateReport report = TakeLandedReport();
    if (!std::isfinite(inTime))
        return report;
    // intent: with deferred impulses the grouper now holds the contacts handed to the task that just landed,
    // as SubmitContacts would have left it at the Update that handed them over: closing at that Update's time
    // closes what it would have closed (a contact at exactly a window's end joins it first), one Update late
    const double close_at = mSettings.mDeferImpulses ? mHandedOverAt : inTime;
    mHandedOverAt = inTime;
    if (!mGrouper.HasOpen() && mPending.empty())
        return report;
    Add(report, Dispatch(mGrouper.HasOpen() ? mGrouper.TakeClosed(close_at) : std::vector<Collision>{}));
    return report;
}

UpdateReport DamageWorld::Flush()
{
    Land();
    SolvePendingHere();
    UpdateReport report = TakeLandedReport();
    if (mGrouper.HasOpen())
        Add(report, Dispatch(mGrouper.TakeAll()));
    Land();
    Add(report, TakeLandedReport());
    return report;
}

CrushSide DamageWorld::CrushSideOf(BodyId inBody) const
{
    // The body's first object with Campbell's crush model stands for its structure.
    for (ObjectId id : mBodies[inBody.mValue].mObjects)
    {
        const DeformableObject& object = mObjects[id.mValue].mObject.front();
        if (object.GetMaterial().mModel == ECrushModel::Campbell)
            return {&object.GetMaterial(), object.GetUpAxis(), &object.GetCrushBody().mLength,
                    object.GetCrushBody().mForward};
    }
    return {};
}

UpdateReport DamageWorld::Dispatch(std::vector<Collision> inCollisions)
{
    UpdateReport report;
    if (mSettings.mDeferDents)
    {
        if (inCollisions.empty() && mPending.empty())
            return report;
        if (mInFlight == nullptr)
            mInFlight = std::make_unique<InFlight>();
        std::vector<std::vector<DentTarget>> targets;
        const std::vector<DamageListener*> listeners = mListeners;
        for (Collision& collision : inCollisions)
        {
            ++report.mCollisionsDispatched;
            ShareCrushEnergy(collision, CrushSideOf(collision.mBodyA), CrushSideOf(collision.mBodyB));
            for (DamageListener* listener : listeners)
                if (IsListening(listener))
                    listener->OnBeforeCollision(collision);
            std::vector<DentTarget> collision_targets;
            for (const auto& [body, side] : {std::pair{collision.mBodyA, ECollisionSide::A}, std::pair{collision.mBodyB, ECollisionSide::B}})
                for (ObjectId id : mBodies[body.mValue].mObjects)
                    collision_targets.push_back({id, &mObjects[id.mValue].mObject.front(), side});
            targets.push_back(std::move(collision_targets));
        }
        // A listener that called the world against DamageListener's contract may have landed or dispatched
        // meanwhile: land whatever that started before this batch takes the slot.
        Land();
        InFlight& flight = *mInFlight;
        flight.mWorld = this;
        flight.mSubmissions = std::move(mPending);
        mPending.clear();
        flight.mTargets = std::move(targets);
        flight.mListeners = listeners;
        flight.mCollisions = std::move(inCollisions);
        flight.mDents.assign(flight.mCollisions.size(), {});
        flight.mTicket = mSettings.mJobs->mStartTask(mSettings.mJobs->mHost, &DamageWorld::RunDeferredDents, &flight);
        flight.mActive = true;
        return report;
    }
    std::vector<ObjectDent> dents;
    // Listeners may remove themselves (or others) from their callbacks: call the ones registered when the
    // dispatch began, skipping any removed meanwhile.
    const std::vector<DamageListener*> listeners = mListeners;
    for (Collision& collision : inCollisions)
    {
        ++report.mCollisionsDispatched;
        ShareCrushEnergy(collision, CrushSideOf(collision.mBodyA), CrushSideOf(collision.mBodyB));
        dents.clear();
        for (DamageListener* listener : listeners)
            if (IsListening(listener))
                listener->OnBeforeCollision(collision);
        // Objects of A, then of B; each body's objects in creation (id) order.
        for (const auto& [body, side] : {std::pair{collision.mBodyA, ECollisionSide::A}, std::pair{collision.mBodyB, ECollisionSide::B}})
            for (ObjectId id : mBodies[body.mValue].mObjects)
            {
                const ffd::DentReport dent =
                    DispatchedDent(mObjects[id.mValue].mObject.front().ApplyCollision(collision, side));
                report.mVerticesMoved += dent.mVerticesMoved;
                if (dent.mVerticesMoved > 0)
                    ++report.mObjectsDented;
                dents.push_back({id, dent});
            }
        for (DamageListener* listener : listeners)
            if (IsListening(listener))
                listener->OnCollision(collision, dents);
    }
    if (report.mObjectsDented > 0)
        ++mShapeRevision;
    return report;
}

bool DamageWorld::IsListening(const DamageListener* inListener) const
{
    return std::find(mListeners.begin(), mListeners.end(), inListener) != mListeners.end();
}

void DamageWorld::AddListener(DamageListener* inListener)
{
    CRUMPLE_ASSERT(inListener != nullptr, "AddListener: null listener");
    if (inListener != nullptr && std::find(mListeners.begin(), mListeners.end(), inListener) == mListeners.end())
        mListeners.push_back(inListener);
}

void DamageWorld::RemoveListener(DamageListener* inListener)
{
    std::erase(mListeners, inListener);
}

void DamageWorld::ResetDamage()
{
    Land();
    for (ObjectSlot& slot : mObjects)
        if (!slot.mObject.empty())
            slot.mObject.front().GetDeformer().Reset();
    ++mShapeRevision;
}

DamageState DamageWorld::GetDamageState() const
{
    WaitForDents(); // the controls are complete once the task has finished
    DamageState state;
    for (ObjectId id : GetObjectIds())
    {
        ObjectDamage damage;
        damage.mObject = id;
        for (const ffd::FfdLattice& zone : GetObject(id)->GetDeformer().GetZones())
            damage.mZones.push_back(zone.GetControlDisplacements());
        state.mObjects.push_back(std::move(damage));
    }
    return state;
}

std::vector<std::byte> DamageWorld::SaveDamage() const
{
    return EncodeDamageState(GetDamageState());
}

Status DamageWorld::SetDamageState(const DamageState& inState)
{
    Land();
    // All objects must match before any changes.
    const std::vector<ObjectId> ids = GetObjectIds();
    if (inState.mObjects.size() != ids.size())
        return MakeError(EError::StateMismatch, "damage state has " + std::to_string(inState.mObjects.size()) +
                                                    " objects, the world " + std::to_string(ids.size()));
    for (std::size_t i = 0; i < ids.size(); ++i)
    {
        const ObjectDamage& damage = inState.mObjects[i];
        // By slot index: a game that loads a save recreates its objects afresh (generation 0), while the
        // world that saved them may have reused slots.
        if (damage.mObject.mValue != ids[i].mValue)
            return MakeError(EError::StateMismatch, "damage state names object " + std::to_string(damage.mObject.mValue) +
                                                        " where the world has object " + std::to_string(ids[i].mValue));
        if (Status valid = GetObject(ids[i])->GetDeformer().ValidateControlDisplacements(damage.mZones); !valid)
            return MakeError(valid.GetError().mCode,
                             "object " + std::to_string(ids[i].mValue) + ": " + valid.GetError().mMessage);
    }
    for (std::size_t i = 0; i < ids.size(); ++i)
    {
        Status applied = GetMutableObject(ids[i])->GetDeformer().SetControlDisplacements(inState.mObjects[i].mZones);
        CRUMPLE_ASSERT(applied.IsValid(), "validated damage state was refused");
        (void)applied;
    }
    ++mShapeRevision;
    return Status::Ok();
}

Status DamageWorld::LoadDamage(std::span<const std::byte> inBytes)
{
    Result<DamageState> state = DecodeDamageState(inBytes);
    if (!state)
        return state.GetError();
    return SetDamageState(state.Get());
}

} // namespace crumple::plugin
