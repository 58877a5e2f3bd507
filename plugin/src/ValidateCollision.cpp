// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/plugin/Collision.h>

#include <cmath>
#include <string>

namespace crumple::plugin
{

namespace
{

// intent: NaN and Inf are a diverged caller (NonFinite); a finite value past a bound is OutOfRange
Error NotFiniteOrTooLarge(bool inFinite, const std::string& inWhat)
{
    return MakeError(inFinite ? EError::OutOfRange : EError::NonFinite, inWhat);
}

} // namespace

Status ValidateCollision(const Collision& inCollision)
{
    if (!std::isfinite(inCollision.mStartTime) || !std::isfinite(inCollision.mEndTime))
        return MakeError(EError::NonFinite, "Collision: a start or end time is not finite");
    for (const double energy : {inCollision.mCrushEnergyA, inCollision.mCrushEnergyB})
    {
        if (energy < 0.0)
            return MakeError(EError::InvalidArgument, "Collision: a crush energy is negative");
        if (!(energy <= cMaxCollisionEnergy))
            return NotFiniteOrTooLarge(std::isfinite(energy),
                                       "Collision: a crush energy is not finite or beyond 1e50 J");
    }
    for (const ShapeBox* box : {&inCollision.mShapeOfBOnA, &inCollision.mShapeOfAOnB})
        if (!(box->mCenter.cwiseAbs().maxCoeff() <= cMaxShapeBoxCoordinate) ||
            !(box->mHalfAxes.cwiseAbs().maxCoeff() <= cMaxShapeBoxCoordinate))
            return NotFiniteOrTooLarge(IsFinite(box->mCenter) && IsFinite(box->mHalfAxes),
                                       "Collision: a shape box is not finite or beyond 1e10 m");
    for (std::size_t i = 0; i < inCollision.mContacts.size(); ++i)
    {
        const CollisionContact& c = inCollision.mContacts[i];
        // intent: the message's prefix made only for a refusal
        const auto where = [i] { return "Collision: contact " + std::to_string(i) + " "; };
        if (!IsFinite(c.mPointOnA) || !IsFinite(c.mPointOnB) || !IsFinite(c.mLocalPointOnA) ||
            !IsFinite(c.mLocalPointOnB) || !IsFinite(c.mNormal) || !IsFinite(c.mLocalNormalOnA) ||
            !IsFinite(c.mLocalNormalOnB) || !std::isfinite(c.mPenetrationDepth) ||
            !std::isfinite(c.mApproachSpeed) || !std::isfinite(c.mTime) || !IsFinite(c.mFrictionImpulse) ||
            !IsFinite(c.mLocalFrictionOnA) || !IsFinite(c.mLocalFrictionOnB) || std::isnan(c.mFriction) ||
            std::isnan(c.mImpulse) || std::isnan(c.mAbsorbedEnergy))
            return MakeError(EError::NonFinite, where() + "has a NaN or Inf field");
        if (c.mImpulse < 0.0 || c.mAbsorbedEnergy < 0.0 || c.mFriction < 0.0)
            return MakeError(EError::InvalidArgument,
                             where() + "has a negative impulse, absorbed energy or friction coefficient");
        if (!(c.mImpulse <= cMaxCollisionImpulse) || !(c.mFrictionImpulse.norm() <= cMaxCollisionImpulse) ||
            !(c.mAbsorbedEnergy <= cMaxCollisionEnergy))
            return NotFiniteOrTooLarge(
                std::isfinite(c.mImpulse) && std::isfinite(c.mAbsorbedEnergy),
                where() + "has an impulse beyond 1e30 N s or an absorbed energy beyond 1e50 J");
        if (std::abs(c.mLocalNormalOnA.norm() - 1.0) > 1.0e-6 ||
            std::abs(c.mLocalNormalOnB.norm() - 1.0) > 1.0e-6)
            return MakeError(EError::InvalidArgument,
                             where() + "has a body-frame normal that is not a unit vector");
        // intent: friction within its cone (mu may be +inf), as FrictionalImpulses leaves it
        if (!c.mFrictionImpulse.isZero(0.0) &&
            !(c.mFrictionImpulse.norm() <= c.mFriction * c.mImpulse * (1.0 + 1.0e-9)))
            return MakeError(EError::InvalidArgument,
                             where() + "has a friction impulse outside its cone |t| <= mu j");
    }
    return Status::Ok();
}

} // namespace crumple::plugin
