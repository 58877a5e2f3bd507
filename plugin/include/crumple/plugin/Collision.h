// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Math.h>
#include <crumple/base/Result.h>
#include <crumple/plugin/Ids.h>

#include <array>
#include <cstdint>
#include <vector>

namespace crumple::plugin
{

/// Which body of a collision an object belongs to.
enum class ECollisionSide
{
    A, ///< The collision's mBodyA: dents go along +normal
    B, ///< The collision's mBodyB: dents go along -normal
};

/// One contact of a collision, on the surfaces, with its impulse. Stored with mBodyA < mBodyB of its
/// Collision (the contact is flipped on arrival when the engine named the bodies the other way round).
struct CRUMPLE_API CollisionContact
{
    Vec3 mPointOnA = Vec3::Zero();      ///< Surface point on A, world frame at mTime (m)
    Vec3 mPointOnB = Vec3::Zero();      ///< Surface point on B, world frame at mTime (m)
    Vec3 mLocalPointOnA = Vec3::Zero(); ///< The same point in A's body frame (m)
    Vec3 mLocalPointOnB = Vec3::Zero(); ///< The same point in B's body frame (m)
    Vec3 mNormal = Vec3::UnitZ();       ///< Unit normal from B to A, world frame
    Vec3 mLocalNormalOnA = Vec3::UnitZ(); ///< The normal in A's body frame (points out of A's dent: into A is +n)
    Vec3 mLocalNormalOnB = Vec3::UnitZ(); ///< The normal in B's body frame
    double mPenetrationDepth = 0.0;     ///< As reported (m)
    double mImpulse = 0.0;              ///< Baraff impulse magnitude (N s), > 0: +n on A, -n on B
    double mFriction = 0.0;             ///< The contact's Coulomb coefficient, as submitted (ContactEvent::mFriction)
    Vec3 mFrictionImpulse = Vec3::Zero(); ///< Tangential impulse on A (N s), world frame, perpendicular to mNormal,
                                          ///< |.| <= mFriction mImpulse; B takes its opposite (FrictionalImpulses)
    Vec3 mLocalFrictionOnA = Vec3::Zero(); ///< The friction impulse on A in A's body frame (N s)
    Vec3 mLocalFrictionOnB = Vec3::Zero(); ///< The friction impulse on B (the opposite of A's) in B's body frame (N s)
    double mApproachSpeed = 0.0;        ///< Closing speed before the solver, -v_rel (m/s): > 0, except at a resting
                                        ///< contact that friction at the others pressed onto B (FrictionalImpulses)
    /// Kinetic energy the impulse took out of the pair (J): J ((1 - e) v + (1 + e) s) / 2 with the world's
    /// restitution e, the approach speed v and the speculative speed s (gap / step) the impulse left alone;
    /// what the two bodies' structures absorb between them (exact for the contacts of one step, solved together).
    /// The normal impulse's share only: what friction takes out (sliding, scraping) crushes nothing
    double mAbsorbedEnergy = 0.0;
    double mTime = 0.0;                 ///< Step time (s)

    /// The whole impulse on A, normal and friction (N s), world frame; B takes its opposite
    Vec3 ImpulseOnA() const { return mImpulse * mNormal + mFrictionImpulse; }
};

/// A body's collision shape seen from another body: the shape's bounding box (BodyState::mShapeMin, mShapeMax)
/// in the other body's frame, as a centre and three half axes. The crush planner takes the impactor's face
/// from it (CrushPlan): how far across the crush direction the impactor reaches, a wall past the car's
/// outline, a pole only its own width.
struct CRUMPLE_API ShapeBox
{
    Vec3 mCenter = Vec3::Zero();   ///< Box centre (m)
    Mat3 mHalfAxes = Mat3::Zero(); ///< Columns: the box's half axes (m)
    bool mKnown = false;           ///< False: the body did not state its shape (BodyState::mHasShapeBounds)

    /// The interval the box covers along the unit axis inAxis, {low, high} (m).
    std::array<double, 2> ExtentAlong(const Vec3& inAxis) const
    {
        const double centre = inAxis.dot(mCenter);
        const double half = (mHalfAxes.transpose() * inAxis).cwiseAbs().sum();
        return {centre - half, centre + half};
    }
};

/// Contacts of one body pair grouped over a time window: one physical impact.
struct CRUMPLE_API Collision
{
    BodyId mBodyA;                  ///< Lower body id of the pair
    BodyId mBodyB;                  ///< Higher body id of the pair
    double mStartTime = 0.0;        ///< Time of the first contact (s)
    double mEndTime = 0.0;          ///< Time of the last contact (s)
    std::uint64_t mSequence = 0;    ///< Creation order in its world, the last tie-breaker of dispatch order
    std::vector<CollisionContact> mContacts; ///< In arrival order
    /// The absorbed energy each side's crush takes (J), set when the collision is dispatched
    /// (CrushEnergyShares): used by objects with the Campbell crush model, recorded for replays
    double mCrushEnergyA = 0.0;
    double mCrushEnergyB = 0.0;
    /// Each body's collision shape in the other's frame at the collision's first step: B's in A's frame
    /// (the impactor a crush of A meets) and A's in B's. Unknown where the body did not state its shape.
    ShapeBox mShapeOfBOnA;
    ShapeBox mShapeOfAOnB;

    /// Sum of the contact impulses (N s)
    double TotalImpulse() const
    {
        double total = 0.0;
        for (const CollisionContact& c : mContacts)
            total += c.mImpulse;
        return total;
    }
    /// Sum of the contacts' absorbed energies (J)
    double AbsorbedEnergy() const
    {
        double total = 0.0;
        for (const CollisionContact& c : mContacts)
            total += c.mAbsorbedEnergy;
        return total;
    }
};

/// What a collision can hold: bodies within BodyState's ranges give impulses of at most about 1e28 N s and
/// energies of about 1e44 J; the bounds leave room above those and keep sums over a collision's contacts
/// finite.
inline constexpr double cMaxCollisionImpulse = 1.0e30; ///< N s
inline constexpr double cMaxCollisionEnergy = 1.0e50;  ///< J
/// Shape boxes within BodyState's ranges, seen from a body within them, lie within a few 1e9 m.
inline constexpr double cMaxShapeBoxCoordinate = 1.0e10; ///< m

/// Checks a collision made outside a DamageWorld (by hand, or read from a file) before it dents anything:
/// every field finite (else EError::NonFinite), impulses, absorbed and crush energies >= 0 and friction
/// coefficients >= 0 (EError::InvalidArgument), within cMaxCollisionImpulse, cMaxCollisionEnergy and
/// cMaxShapeBoxCoordinate (EError::OutOfRange), body-frame normals of unit length to 1e-6 and friction
/// impulses inside their cone (EError::InvalidArgument). Every collision a DamageWorld dispatches passes.
CRUMPLE_API Status ValidateCollision(const Collision& inCollision);

} // namespace crumple::plugin
