// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "PairSolve.h"

#include <crumple/plugin/ContactReduction.h>

#include <algorithm>
#include <cmath>

namespace crumple::plugin
{

PairSolve PreparePairSolve(ContactBatch& ioBatch, const BodyState& inA, const BodyState& inB,
                           const PairVelocities* inContinued, double inTimeStep,
                           const DamageWorldSettings& inSettings)
{
    PairSolve solve;
    BodyState& state_a = solve.mStateA;
    BodyState& state_b = solve.mStateB;
    state_a = inA;
    state_b = inB;
    solve.mContinues = inContinued != nullptr;
    if (solve.mContinues)
    {
        state_a.mLinearVelocity = inContinued->mLinearA;
        state_a.mAngularVelocity = state_a.mTransform.mRotation * inContinued->mAngularBodyA;
        state_b.mLinearVelocity = inContinued->mLinearB;
        state_b.mAngularVelocity = state_b.mTransform.mRotation * inContinued->mAngularBodyB;
    }
    // intent: a contact reported before touching (a gap g within the engine's margin) constrains only the
    // approach beyond s = g / dt (the rest comes with the next step's contact), unless the engine resolves a
    // hit it predicts within the step whole (ESpeculativeContacts::ResolveWhole): then such a contact
    // (closing beyond s faster than resting) is resolved as a touching one, rebound included
    const bool resolve_whole = inSettings.mSpeculativeContacts == ESpeculativeContacts::ResolveWhole;
    const auto speculative_speed = [&](const CollisionContact& inContact)
    {
        if (!(inTimeStep > 0.0))
            return 0.0;
        const double s = std::max(-inContact.mPenetrationDepth, 0.0) / inTimeStep;
        if (!resolve_whole || s == 0.0)
            return s;
        const double v = RelativeNormalVelocity(
            state_a, state_b, 0.5 * (inContact.mPointOnA + inContact.mPointOnB), inContact.mNormal);
        return v + s < -inSettings.mRestingSpeed ? 0.0 : s;
    };
    if (ioBatch.mContacts.size() > inSettings.mMaxContactsPerPair)
    {
        // A large manifold: only closing contacts can take an impulse (the solve leaves the others at zero),
        // so the resting ones go first; the closing ones are then reduced to a bounded set.
        std::vector<CollisionContact> closing;
        for (const CollisionContact& c : ioBatch.mContacts)
            if (RelativeNormalVelocity(state_a, state_b, 0.5 * (c.mPointOnA + c.mPointOnB), c.mNormal) +
                    speculative_speed(c) <
                -inSettings.mRestingSpeed)
                closing.push_back(c);
        ioBatch.mContacts = ReduceContacts(closing, inSettings.mMaxContactsPerPair);
    }
    for (const CollisionContact& c : ioBatch.mContacts)
    {
        const ImpulseContact& contact = solve.mContacts.emplace_back(
            0.5 * (c.mPointOnA + c.mPointOnB), c.mNormal, speculative_speed(c), c.mFriction);
        if (RelativeNormalVelocity(state_a, state_b, contact.mPoint, contact.mNormal) +
                contact.mSpeculativeSpeed <
            -inSettings.mRestingSpeed)
            ++solve.mClosing;
    }
    return solve;
}

void SolvePair(PairSolve& ioSolve, const DamageWorldSettings& inSettings)
{
    ioSolve.mImpulses =
        FrictionalImpulses(ioSolve.mStateA, ioSolve.mStateB, ioSolve.mContacts, inSettings.mRestitution,
                           inSettings.mRestingSpeed, inSettings.mFrictionSolve);
}

Result<AcceptedPair> AcceptPairSolve(const ContactBatch& inBatch, const PairSolve& inSolve,
                                     const DamageWorldSettings& inSettings,
                                     std::vector<CollisionContact>& ioAccepted)
{
    // intent: a host's parallel for that skipped a piece left its pairs unsolved: refused, not read past
    if (inSolve.mImpulses.size() != inBatch.mContacts.size())
        return MakeError(EError::InvalidArgument,
                         "a pair's impulses were not solved: the job system's parallel for skipped a piece");
    const BodyState& state_a = inSolve.mStateA;
    const BodyState& state_b = inSolve.mStateB;
    const std::vector<ContactImpulse>& impulses = inSolve.mImpulses;
    AcceptedPair accepted;
    PairVelocities& left = accepted.mLeft;
    left.mLinearA = state_a.mLinearVelocity;
    left.mLinearB = state_b.mLinearVelocity;
    Vec3 spin_a = state_a.mAngularVelocity, spin_b = state_b.mAngularVelocity; // world frame
    for (std::size_t i = 0; i < inBatch.mContacts.size(); ++i)
    {
        if (!std::isfinite(impulses[i].mNormal) || !IsFinite(impulses[i].mFriction))
            return MakeError(EError::NonFinite, "contact impulse is not finite: check the bodies' masses");
        if (!(impulses[i].mNormal > 0.0))
            continue;
        accepted.mPushed = true;
        CollisionContact contact = inBatch.mContacts[i];
        contact.mImpulse = impulses[i].mNormal;
        contact.mFrictionImpulse = impulses[i].mFriction;
        const ImpulseContact& solved = inSolve.mContacts[i];
        contact.mApproachSpeed = -RelativeNormalVelocity(state_a, state_b, solved.mPoint, contact.mNormal);
        // The impulse took the closing speed v beyond the speculative s = gap / dt to a rebound of e (v - s):
        // kinetic energy J (v + s - e (v - s)) / 2 left the pair.
        const double v = std::max(contact.mApproachSpeed, 0.0), s = solved.mSpeculativeSpeed;
        const double e = inSettings.mRestitution;
        contact.mAbsorbedEnergy = 0.5 * impulses[i].mNormal * ((1.0 - e) * v + (1.0 + e) * s);
        contact.mLocalPointOnA = state_a.mTransform.ToBody(contact.mPointOnA);
        contact.mLocalPointOnB = state_b.mTransform.ToBody(contact.mPointOnB);
        contact.mLocalNormalOnA = state_a.mTransform.DirectionToBody(contact.mNormal);
        contact.mLocalNormalOnB = state_b.mTransform.DirectionToBody(contact.mNormal);
        contact.mLocalFrictionOnA = state_a.mTransform.DirectionToBody(contact.mFrictionImpulse);
        contact.mLocalFrictionOnB = state_b.mTransform.DirectionToBody(-contact.mFrictionImpulse);
        ioAccepted.push_back(contact);
        // The impulse +J n + t on A and its opposite on B changes the velocities it leaves.
        const Vec3 impulse = contact.ImpulseOnA();
        const Vec3& point = solved.mPoint;
        left.mLinearA += state_a.InverseMass() * impulse;
        spin_a += state_a.InverseInertia() * (point - state_a.mCenterOfMass).cross(impulse);
        left.mLinearB -= state_b.InverseMass() * impulse;
        spin_b -= state_b.InverseInertia() * (point - state_b.mCenterOfMass).cross(impulse);
    }
    left.mAngularBodyA = state_a.mTransform.mRotation.transpose() * spin_a;
    left.mAngularBodyB = state_b.mTransform.mRotation.transpose() * spin_b;
    return accepted;
}

} // namespace crumple::plugin
