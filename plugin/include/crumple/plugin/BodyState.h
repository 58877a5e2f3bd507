// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Math.h>
#include <crumple/base/Result.h>

namespace crumple::plugin
{

/// How a body moves: static and kinematic bodies have infinite mass for impulses.
enum class EMotionType
{
    Dynamic,   ///< Moved by the engine's solver; finite mass and inertia
    Kinematic, ///< Moved by the game; velocity counts, mass is infinite
    Static,    ///< Never moves; velocity is ignored
};

/// Everything a Baraff impulse needs to know about a body, snapshotted by the adapter *before* the engine's
/// solver runs (post-solve velocities have already resolved the impact and would give zero impulse).
struct CRUMPLE_API BodyState
{
    EMotionType mMotionType = EMotionType::Dynamic; ///< See EMotionType
    double mMass = 1.0; ///< Mass (kg), in [cMinBodyMass, cMaxBodyMass] for dynamic bodies; ignored otherwise
    Mat3 mInverseInertiaWorld = Mat3::Identity(); ///< Inverse inertia tensor about the centre of mass, world frame
                                                  ///< (1/(kg m^2)), symmetric positive semi-definite; ignored unless dynamic
    Transform mTransform;                       ///< Body frame (the frame of its mesh and FFD zones) to world
    Vec3 mCenterOfMass = Vec3::Zero();          ///< Centre of mass, world frame (m)
    Vec3 mLinearVelocity = Vec3::Zero();        ///< Velocity of the centre of mass, world frame (m/s)
    Vec3 mAngularVelocity = Vec3::Zero();       ///< Angular velocity, world frame (rad/s)
    /// The body's collision shape's bounding box in its body frame (m): where a crush of another body meets
    /// it (Collision::mShapeOfBOnA). The adapters state it from the engine's shape; an unbounded shape (a
    /// plane) is stated out to cMaxBodyPosition. Without it a crush takes the impactor's face to be as wide as
    /// the contacts it made.
    bool mHasShapeBounds = false;
    Vec3 mShapeMin = Vec3::Zero();
    Vec3 mShapeMax = Vec3::Zero();

    /// 1/m, 0 for static and kinematic bodies (1/kg)
    double InverseMass() const { return mMotionType == EMotionType::Dynamic ? 1.0 / mMass : 0.0; }
    /// World inverse inertia, zero for static and kinematic bodies
    Mat3 InverseInertia() const { return mMotionType == EMotionType::Dynamic ? mInverseInertiaWorld : Mat3::Zero(); }
    /// Velocity of the material point at world position inPoint (m/s); zero for static bodies
    Vec3 PointVelocity(const Vec3& inPoint) const
    {
        if (mMotionType == EMotionType::Static)
            return Vec3::Zero();
        return mLinearVelocity + mAngularVelocity.cross(inPoint - mCenterOfMass);
    }
};

/// Accepted ranges of a body state, far beyond any simulated vehicle or prop, and far enough inside the double
/// range that impulses (at most about 1e28 N s) and the energies of dents (about 1e44 J) cannot overflow.
constexpr double cMaxBodyMass = 1.0e12;       ///< kg
constexpr double cMinBodyMass = 1.0e-12; ///< kg, of a dynamic body (a subnormal mass has an infinite inverse)
constexpr double cMaxBodySpeed = 1.0e6;       ///< m/s, of the centre of mass
constexpr double cMaxBodyAngularSpeed = 1.0e6; ///< rad/s
constexpr double cMaxBodyPosition = 1.0e9;    ///< m, any coordinate of the centre of mass or the frame
constexpr double cMaxInverseInertia = 1.0e12; ///< 1/(kg m^2), any entry of the world inverse inertia

/// How far from a proper rotation mTransform.mRotation may be (largest entry of R R^T - I), and how far from
/// symmetric mInverseInertiaWorld (largest entry of M - M^T over M's largest): an engine in single precision
/// (Jolt, PhysX, Bullet's default build) hands over rotations orthonormal only to about 1.2e-6 and world
/// inverse inertias R D R^T asymmetric by up to 1.6e-7 (measured over 1e5 random float rotations).
constexpr double cRotationTolerance = 1.0e-5;
constexpr double cInverseInertiaAsymmetry = 1.0e-5;

/// Checks a body state at the API boundary: a motion type of the enum, finite values within the ranges above,
/// positive mass, symmetric PSD inverse inertia and a proper rotation (within the tolerances above). The
/// message names the offending field.
CRUMPLE_API Status ValidateBodyState(const BodyState& inState);

/// The state as a DamageWorld keeps it: a valid state (ValidateBodyState) whose rotation is farther than 1e-6
/// from orthonormal comes back re-orthonormalized (through its quaternion), and an inverse inertia farther
/// than 1e-9 from symmetric comes back as its symmetric part; anything else comes back bit for bit (a double
/// precision engine's states are never touched).
CRUMPLE_API BodyState CanonicalBodyState(const BodyState& inState);

} // namespace crumple::plugin
