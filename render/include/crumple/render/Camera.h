// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Math.h>
#include <crumple/base/Result.h>

#include <Eigen/Core>

namespace crumple::render
{

/// Preset directions for Camera::LookAtBounds, named for a vehicle frame (forward, up; left = up x forward).
enum class EView
{
    Front, ///< Eye ahead of the box, looking back along -forward; left of the vehicle on the image's right
    Side,  ///< Eye on the right of the box (-left), looking left; forward points to the image's right
    Top,   ///< Eye above the box, looking down; forward points to the image's top
    Iso,   ///< Eye ahead, right and above (forward - left + up): three faces visible
};

/// A perspective pinhole camera in the world frame (m, right-handed). The image's up is mUp projected onto
/// the image plane; +x of the image is (mTarget - mEye) x mUp.
struct CRUMPLE_API Camera
{
    Vec3 mEye{3.0, -3.0, 2.0};   ///< Eye position, world frame (m)
    Vec3 mTarget = Vec3::Zero(); ///< Point looked at, world frame (m), != mEye
    Vec3 mUp = Vec3::UnitZ();    ///< Up hint, world frame, not parallel to mTarget - mEye (need not be unit)
    double mFovYDegrees = 30.0;  ///< Vertical field of view (degrees), in (0, 180)
    double mNear = 0.05;         ///< Near clip distance along the view direction (m), > 0
    double mFar = 100.0;         ///< Far clip distance (m), > mNear

    /// Checks every field (finite, ranges above, eye != target, up not parallel to the view direction).
    Status Validate() const;

    /// World to view transform (OpenGL convention: view looks down -z, y up), 4 by 4.
    Eigen::Matrix4d GetViewMatrix() const;
    /// View rotation only (rows: image right, image up, backwards), 3 by 3; GetViewMatrix without
    /// translation.
    Mat3 GetViewRotation() const;
    /// View to clip transform (OpenGL clip space, depth -1..1), 4 by 4.
    /// @param[in] inAspect image width / height, > 0
    Eigen::Matrix4d GetProjectionMatrix(double inAspect) const;

    /// A camera that frames the box [inMin, inMax] (m, world frame) seen from inDirection, looking at its
    /// centre: the eye is as close as it can be with all eight corners inside both fields of view (5 %
    /// margin), and near and far enclose the box.
    /// @param[in] inDirection   from the box centre towards the eye, world frame (need not be unit, != 0)
    /// @param[in] inUp          up hint, world frame; a perpendicular axis is used when parallel to
    /// inDirection
    /// @param[in] inFovYDegrees vertical field of view (degrees), in (0, 180)
    /// @param[in] inAspect      image width / height, > 0
    static Camera LookAtBounds(const Vec3& inMin, const Vec3& inMax, const Vec3& inDirection,
                               const Vec3& inUp = Vec3::UnitZ(), double inFovYDegrees = 30.0,
                               double inAspect = 1.0);

    /// LookAtBounds from a preset view. Defaults fit a vehicle frame with x forward and z up; pass other axes
    /// for other conventions (e.g. inUp = +y, inForward = -z for a y-up mesh facing -z).
    /// @param[in] inUp      the mesh's up axis, world frame, unit
    /// @param[in] inForward the mesh's forward axis, world frame, unit, perpendicular to inUp
    static Camera LookAtBounds(const Vec3& inMin, const Vec3& inMax, EView inView,
                               const Vec3& inUp = Vec3::UnitZ(), const Vec3& inForward = Vec3::UnitX(),
                               double inFovYDegrees = 30.0, double inAspect = 1.0);
};

} // namespace crumple::render
