// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Math.h>
#include <crumple/base/Result.h>

#include <vector>

namespace crumple::plugin
{

/// A rigid body that an engine adapter creates and owns for Crumple (BulletAdapter::CreateConvexBody,
/// OdeAdapter::CreateConvexBody): a destructible prop's fragment that broke loose (props::FragmentBody), or any
/// other debris. Its body frame sits at the centre of mass along the principal axes of inertia, the frame
/// engines need (ODE requires the centre of mass at the body origin, Bullet a diagonal local inertia).
struct CRUMPLE_API ConvexBodySettings
{
    double mMass = 1.0;                    ///< kg, in [1e-12, cMaxBodyMass] (a float engine's range)
    Vec3 mPrincipalInertia = Vec3::Ones(); ///< About the centre of mass along the body axes (kg m^2), each in
                                           ///< [1e-12, 1e30] and at most the sum of the other two (as every real
                                           ///< mass distribution)
    Vec3 mPosition = Vec3::Zero();         ///< Centre of mass, world frame (m)
    Mat3 mOrientation = Mat3::Identity();  ///< Body axes in world coordinates (columns): a rotation
    Vec3 mLinearVelocity = Vec3::Zero();   ///< Of the centre of mass, world frame (m/s)
    Vec3 mAngularVelocity = Vec3::Zero();  ///< World frame (rad/s)
    /// The collision shape: the convex hull of these points, body frame (m). At least 4 points that span a volume.
    std::vector<Vec3> mHullPoints;

    /// The inertia tensor about the centre of mass in world coordinates (kg m^2)
    Mat3 WorldInertia() const { return mOrientation * mPrincipalInertia.asDiagonal() * mOrientation.transpose(); }
};

/// Checks the settings at an adapter's boundary (finite values within the body-state ranges of BodyState.h,
/// positive mass and inertia obeying the triangle inequality to within 1e-9 relative, a proper rotation, a hull
/// that spans a volume); the message names the offending field.
CRUMPLE_API Status ValidateConvexBodySettings(const ConvexBodySettings& inSettings);

} // namespace crumple::plugin
