// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/plugin/CollisionGrouper.h>

#include <algorithm>
#include <cmath>

namespace crumple::plugin
{

namespace
{

bool DispatchesBefore(const Collision& inLeft, const Collision& inRight)
{
    if (inLeft.mStartTime != inRight.mStartTime)
        return inLeft.mStartTime < inRight.mStartTime;
    if (inLeft.mBodyA != inRight.mBodyA)
        return inLeft.mBodyA < inRight.mBodyA;
    if (inLeft.mBodyB != inRight.mBodyB)
        return inLeft.mBodyB < inRight.mBodyB;
    return inLeft.mSequence < inRight.mSequence;
}

} // namespace

Result<CollisionGrouper> CollisionGrouper::Create(const CollisionGrouperSettings& inSettings)
{
    if (!(std::isfinite(inSettings.mTimeWindow) && inSettings.mTimeWindow > 0.0))
        return MakeError(EError::InvalidArgument, "CollisionGrouperSettings.mTimeWindow must be finite and > 0 s");
    if (!(std::isfinite(inSettings.mGroupDistance) && inSettings.mGroupDistance >= 0.0))
        return MakeError(EError::InvalidArgument, "CollisionGrouperSettings.mGroupDistance must be finite and >= 0 m");
    return CollisionGrouper(inSettings);
}

double CollisionGrouper::WindowOf(const Collision& inCollision) const
{
    return std::find(mEachStep.begin(), mEachStep.end(), inCollision.mSequence) != mEachStep.end() ? 0.0 : mSettings.mTimeWindow;
}

void CollisionGrouper::Add(BodyId inBodyA, BodyId inBodyB, std::span<const CollisionContact> inContacts, bool inEachStep,
                           const std::array<ShapeBox, 2>& inShapes)
{
    if (inContacts.empty())
        return;
    const double time = inContacts.front().mTime;
    const double distance_squared = mSettings.mGroupDistance * mSettings.mGroupDistance;
    auto near = [&](const Collision& inCollision) {
        for (const CollisionContact& old_contact : inCollision.mContacts)
            for (const CollisionContact& new_contact : inContacts)
                if ((old_contact.mLocalPointOnA - new_contact.mLocalPointOnA).squaredNorm() <= distance_squared)
                    return true;
        return false;
    };
    for (Collision& collision : mOpen)
    {
        if (collision.mBodyA != inBodyA || collision.mBodyB != inBodyB)
            continue;
        if (time < collision.mStartTime || time > collision.mStartTime + WindowOf(collision) || !near(collision))
            continue;
        collision.mContacts.insert(collision.mContacts.end(), inContacts.begin(), inContacts.end());
        collision.mEndTime = std::max(collision.mEndTime, time);
        return;
    }
    Collision collision;
    collision.mBodyA = inBodyA;
    collision.mBodyB = inBodyB;
    collision.mStartTime = time;
    collision.mEndTime = time;
    collision.mSequence = mNextSequence++;
    collision.mContacts.assign(inContacts.begin(), inContacts.end());
    collision.mShapeOfBOnA = inShapes[0];
    collision.mShapeOfAOnB = inShapes[1];
    if (inEachStep)
        mEachStep.push_back(collision.mSequence);
    mOpen.push_back(std::move(collision));
}

std::vector<Collision> CollisionGrouper::TakeClosed(double inTime)
{
    std::vector<Collision> closed;
    if (mOpen.empty())
        return closed;
    // Stable partition keeps the open ones in creation order.
    auto first_closed = std::stable_partition(mOpen.begin(), mOpen.end(), [&](const Collision& c) {
        return inTime < c.mStartTime + WindowOf(c);
    });
    closed.assign(std::make_move_iterator(first_closed), std::make_move_iterator(mOpen.end()));
    mOpen.erase(first_closed, mOpen.end());
    ForgetClosedEachStep();
    std::sort(closed.begin(), closed.end(), DispatchesBefore);
    return closed;
}

void CollisionGrouper::ForgetClosedEachStep()
{
    std::erase_if(mEachStep, [&](std::uint64_t inSequence) {
        return std::none_of(mOpen.begin(), mOpen.end(), [&](const Collision& c) { return c.mSequence == inSequence; });
    });
}

std::vector<Collision> CollisionGrouper::TakeAll()
{
    std::vector<Collision> all = std::move(mOpen);
    mOpen.clear();
    mEachStep.clear();
    std::sort(all.begin(), all.end(), DispatchesBefore);
    return all;
}

void CollisionGrouper::Forget(BodyId inBody)
{
    std::erase_if(mOpen, [&](const Collision& c) { return c.mBodyA == inBody || c.mBodyB == inBody; });
    ForgetClosedEachStep();
}

} // namespace crumple::plugin
