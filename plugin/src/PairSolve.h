// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

// One body pair's joint impulse solve within an engine step, as precompute and solve (STYLE rule 16): the
// prepare step reads the world and runs in order, the solve reads only its own data (so a burst's pairs solve
// on any threads), the accept step turns the answer into the collision's contacts. Private to the plugin.

#include "ContactBatches.h"

#include <crumple/base/Result.h>
#include <crumple/plugin/BaraffImpulse.h>
#include <crumple/plugin/DamageWorldSettings.h>
#include <crumple/plugin/FrictionalImpulses.h>

#include <cstddef>
#include <vector>

namespace crumple::plugin
{

/// The velocities a pair's impulse left its bodies moving at (DamageWorld's impact memory): linear in the
/// world (m/s), angular in each body's own frame (rad/s), so a spin stays with the body the engine turns.
struct PairVelocities
{
    Vec3 mLinearA = Vec3::Zero();      ///< A's centre of mass, world frame (m/s)
    Vec3 mAngularBodyA = Vec3::Zero(); ///< A's spin, A's body frame (rad/s)
    Vec3 mLinearB = Vec3::Zero();      ///< B's centre of mass, world frame (m/s)
    Vec3 mAngularBodyB = Vec3::Zero(); ///< B's spin, B's body frame (rad/s)
};

/// A pair's batch as its solve takes it, and the answer.
struct PairSolve
{
    BodyState mStateA;                     ///< A as solved: a continued impact's remembered velocities
    BodyState mStateB;                     ///< B likewise
    bool mContinues = false;               ///< Solved from remembered velocities
    std::vector<ImpulseContact> mContacts; ///< The batch's contacts at their surface points' midpoints
    std::size_t mClosing = 0; ///< How many close faster than the resting speed (the solve's work)
    std::vector<ContactImpulse> mImpulses; ///< One per contact, once solved
};

/// Prepares ioBatch's solve from its bodies' states inA and inB: from inContinued's velocities where the pair
/// continues an impact (null where not), each contact's speculative speed (its gap over inTimeStep s, unless
/// the engine resolves predicted hits whole: DamageWorldSettings::mSpeculativeContacts), and a manifold of
/// more than mMaxContactsPerPair contacts reduced to that many closing ones (ioBatch's contacts replaced).
PairSolve PreparePairSolve(ContactBatch& ioBatch, const BodyState& inA, const BodyState& inB,
                           const PairVelocities* inContinued, double inTimeStep,
                           const DamageWorldSettings& inSettings);

/// The prepared pair's impulses (FrictionalImpulses) into ioSolve.mImpulses; reads nothing else.
void SolvePair(PairSolve& ioSolve, const DamageWorldSettings& inSettings);

/// inSolve's contacts that push, appended to ioAccepted as the collision's contacts (impulses, approach
/// speeds, absorbed energies, body-frame copies), and the velocities the impulses leave the pair moving at
/// (mPushed: whether any contact pushed). NonFinite where an impulse is not finite, InvalidArgument where the
/// pair was not solved (a host's parallel for skipped its piece): nothing appended then is to be used, the
/// caller drops the step.
struct AcceptedPair
{
    PairVelocities mLeft; ///< The velocities after the impulses
    bool mPushed = false; ///< Some contact took an impulse
};
Result<AcceptedPair> AcceptPairSolve(const ContactBatch& inBatch, const PairSolve& inSolve,
                                     const DamageWorldSettings& inSettings,
                                     std::vector<CollisionContact>& ioAccepted);

} // namespace crumple::plugin
