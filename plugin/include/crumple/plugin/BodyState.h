// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

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
struct BodyState
{
    EMotionType mMotionType = EMotionType::Dynamic; ///< See EMotionType
    double mMass = 1.0;                         ///< Mass (kg), > 0 for dynamic bodies; ignored otherwise
    Mat3 mInverseInertiaWorld = Mat3::Identity(); ///< Inverse inertia tensor about the centre of mass, world frame
                                                  ///< (1/(kg m^2)), symmetric positive semi-definite; ignored unless dynamic
    Transform mTransform;                       ///< Body frame (the frame of its mesh and FFD zones) to world
    Vec3 mCenterOfMass = Vec3::Zero();          ///< Centre of mass, world frame (m)
    Vec3 mLinearVelocity = Vec3::Zero();        ///< Velocity of the centre of mass, world frame (m/s)
    Vec3 mAngularVelocity = Vec3::Zero();       ///< Angular velocity, world frame (rad/s)

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

/// Checks a body state at the API boundary: finite values, positive mass, symmetric PSD inverse inertia and
/// a proper rotation. The message names the offending field.
Status ValidateBodyState(const BodyState& inState);

} // namespace crumple::plugin
