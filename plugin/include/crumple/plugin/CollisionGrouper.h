// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Result.h>
#include <crumple/plugin/Collision.h>

#include <array>
#include <span>
#include <vector>

namespace crumple::plugin
{

/// Settings of a CollisionGrouper.
struct CRUMPLE_API CollisionGrouperSettings
{
    double mTimeWindow = 0.05;   ///< A collision stays open this long after its first contact (s), > 0
    double mGroupDistance = 0.5; ///< A contact joins a collision when within this distance of one of its
                                 ///< contacts, measured in body A's frame so a moving car does not split it (m)
};

/// Groups contacts into collisions (D4MD section 6.2: engines report contacts one step at a time, so the
/// contacts of one impact arrive over several steps). Collisions close when their window has passed and
/// come out ordered by (start time, body A, body B, creation sequence): deterministic, never by pointer.
class CRUMPLE_API CollisionGrouper
{
public:
    /// Validates the settings.
    static Result<CollisionGrouper> Create(const CollisionGrouperSettings& inSettings);

    /// Adds contacts that one engine step reported for the ordered pair (inBodyA < inBodyB), all at the
    /// same time. They stay together (the engine reported them as one manifold, however far apart: a box
    /// face's corners) and join the oldest open collision of the pair whose window holds their time and one
    /// of whose contacts lies within the group distance of one of theirs; otherwise they open a new one.
    /// inEachStep: the contacts form a collision of their own that closes at their own time (a window of
    /// zero), for bodies whose collisions must be dispatched at every step (DamageWorld::SetDispatchEachStep).
    /// inShapes: each body's shape in the other's frame (Collision::mShapeOfBOnA, mShapeOfAOnB), kept by a
    /// collision they open.
    void Add(BodyId inBodyA, BodyId inBodyB, std::span<const CollisionContact> inContacts, bool inEachStep = false,
             const std::array<ShapeBox, 2>& inShapes = {});

    /// Removes and returns, in dispatch order, the collisions whose window has closed at inTime
    /// (inTime >= start + window).
    std::vector<Collision> TakeClosed(double inTime);
    /// Removes and returns every open collision, in dispatch order.
    std::vector<Collision> TakeAll();
    /// Drops open collisions that involve inBody (the body was removed).
    void Forget(BodyId inBody);

    bool HasOpen() const { return !mOpen.empty(); }
    std::size_t GetOpenCount() const { return mOpen.size(); }
    const CollisionGrouperSettings& GetSettings() const { return mSettings; }

private:
    explicit CollisionGrouper(const CollisionGrouperSettings& inSettings) : mSettings(inSettings) {}

    CollisionGrouperSettings mSettings;
    std::vector<Collision> mOpen; ///< In creation order
    std::vector<std::uint64_t> mEachStep; ///< Sequences of the open collisions with a window of zero
    double WindowOf(const Collision& inCollision) const;
    void ForgetClosedEachStep();
    std::uint64_t mNextSequence = 0;
};

} // namespace crumple::plugin
