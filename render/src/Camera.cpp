// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/base/Assert.h>
#include <crumple/render/Camera.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace crumple::render
{

namespace
{

/// Cosine above which the view direction and the up hint count as parallel.
constexpr double cParallelCosine = 0.9999;

/// Degrees to radians.
double Radians(double inDegrees)
{
    return inDegrees * std::numbers::pi / 180.0;
}

/// The world axis least aligned with inDirection (unit), a safe up hint.
Vec3 LeastAlignedAxis(const Vec3& inDirection)
{
    const Vec3 magnitude = inDirection.cwiseAbs();
    if (magnitude.z() <= magnitude.x() && magnitude.z() <= magnitude.y())
        return Vec3::UnitZ();
    return magnitude.y() <= magnitude.x() ? Vec3::UnitY() : Vec3::UnitX();
}

} // namespace

Status Camera::Validate() const
{
    // Finite values and ranges, each with the offending field in the message.
    if (!IsFinite(mEye) || !IsFinite(mTarget) || !IsFinite(mUp) || !IsFinite(mFovYDegrees) ||
        !IsFinite(mNear) || !IsFinite(mFar))
        return MakeError(EError::NonFinite, "Camera has a NaN or Inf field");
    if (!(mFovYDegrees > 0.0 && mFovYDegrees < 180.0))
        return MakeError(EError::InvalidArgument,
                         "Camera.mFovYDegrees = " + std::to_string(mFovYDegrees) + " must be in (0, 180)");
    if (!(mNear > 0.0) || !(mFar > mNear))
        return MakeError(EError::InvalidArgument, "Camera.mNear = " + std::to_string(mNear) + " m, mFar = " +
                                                      std::to_string(mFar) + " m: need 0 < mNear < mFar");

    // A view direction and an up hint that is not parallel to it.
    const Vec3 forward = mTarget - mEye;
    if (forward.norm() <= 0.0)
        return MakeError(EError::DegenerateGeometry, "Camera.mEye equals Camera.mTarget: no view direction");
    if (mUp.norm() <= 0.0 || std::abs(forward.normalized().dot(mUp.normalized())) > cParallelCosine)
        return MakeError(EError::DegenerateGeometry, "Camera.mUp is zero or parallel to the view direction");
    return Status::Ok();
}

Mat3 Camera::GetViewRotation() const
{
    // Rows: image right, image up, backwards (OpenGL's view space looks down -z).
    const Vec3 forward = (mTarget - mEye).normalized();
    const Vec3 right = forward.cross(mUp).normalized();
    const Vec3 up = right.cross(forward);
    Mat3 rotation;
    rotation.row(0) = right.transpose();
    rotation.row(1) = up.transpose();
    rotation.row(2) = -forward.transpose();
    return rotation;
}

Eigen::Matrix4d Camera::GetViewMatrix() const
{
    const Mat3 rotation = GetViewRotation();
    Eigen::Matrix4d view = Eigen::Matrix4d::Identity();
    view.topLeftCorner<3, 3>() = rotation;
    view.topRightCorner<3, 1>() = -rotation * mEye;
    return view;
}

Eigen::Matrix4d Camera::GetProjectionMatrix(double inAspect) const
{
    // gluPerspective: clip depth -1 at mNear, +1 at mFar.
    CRUMPLE_ASSERT(inAspect > 0.0, "aspect must be > 0");
    const double focal = 1.0 / std::tan(0.5 * Radians(mFovYDegrees));
    Eigen::Matrix4d projection = Eigen::Matrix4d::Zero();
    projection(0, 0) = focal / inAspect;
    projection(1, 1) = focal;
    projection(2, 2) = (mFar + mNear) / (mNear - mFar);
    projection(2, 3) = 2.0 * mFar * mNear / (mNear - mFar);
    projection(3, 2) = -1.0;
    return projection;
}

Camera Camera::LookAtBounds(const Vec3& inMin, const Vec3& inMax, const Vec3& inDirection, const Vec3& inUp,
                            double inFovYDegrees, double inAspect)
{
    CRUMPLE_ASSERT(IsFinite(inMin) && IsFinite(inMax) && (inMin.array() <= inMax.array()).all(),
                   "bounds must be finite with min <= max");
    CRUMPLE_ASSERT(inDirection.norm() > 0.0, "view direction must not be zero");
    CRUMPLE_ASSERT(inFovYDegrees > 0.0 && inFovYDegrees < 180.0 && inAspect > 0.0,
                   "bad field of view or aspect");

    // Bounds grown to at least 1 mm so a point or a flat panel still gives a valid camera.
    const Vec3 centre = 0.5 * (inMin + inMax);
    const Vec3 half = (0.5 * (inMax - inMin)).cwiseMax(Vec3::Constant(1.0e-3));
    const double radius = half.norm();
    const Vec3 direction =
        inDirection.norm() > 0.0 ? inDirection.normalized() : Vec3(1.0, -1.0, 1.0).normalized();

    // Camera basis as GetViewRotation makes it.
    Camera camera;
    camera.mTarget = centre;
    const bool up_usable = inUp.norm() > 0.0 && std::abs(direction.dot(inUp.normalized())) <= cParallelCosine;
    camera.mUp = up_usable ? Vec3(inUp.normalized()) : LeastAlignedAxis(direction);
    camera.mFovYDegrees = inFovYDegrees;
    const Vec3 right = (-direction).cross(camera.mUp).normalized();
    const Vec3 up = right.cross(-direction);

    // Distance from the centre so every corner of the box is inside both fields of view with a 5 % margin:
    // corner c at depth (distance - c.direction) needs |c.right| <= depth tan(half_x) / 1.05, same for up.
    const double tan_y = std::tan(0.5 * Radians(inFovYDegrees)) / 1.05;
    const double tan_x = std::tan(0.5 * Radians(inFovYDegrees)) * inAspect / 1.05;
    double distance = 0.0;
    double nearest = -radius;
    for (int corner = 0; corner < 8; ++corner)
    {
        const Vec3 offset((corner & 1) ? half.x() : -half.x(), (corner & 2) ? half.y() : -half.y(),
                          (corner & 4) ? half.z() : -half.z());
        const double towards_eye = offset.dot(direction);
        nearest = std::max(nearest, towards_eye);
        distance = std::max(distance, towards_eye + std::max(std::abs(offset.dot(right)) / tan_x,
                                                             std::abs(offset.dot(up)) / tan_y));
    }
    distance = std::max(distance, nearest + 0.1 * radius);

    // Near and far enclose the box with room to spare.
    camera.mEye = centre + distance * direction;
    camera.mNear = std::max(0.5 * (distance - nearest), 1.0e-4 * distance);
    camera.mFar = distance + 2.0 * radius;
    return camera;
}

Camera Camera::LookAtBounds(const Vec3& inMin, const Vec3& inMax, EView inView, const Vec3& inUp,
                            const Vec3& inForward, double inFovYDegrees, double inAspect)
{
    CRUMPLE_ASSERT(std::abs(inUp.norm() - 1.0) < 1.0e-6 && std::abs(inForward.norm() - 1.0) < 1.0e-6 &&
                       std::abs(inUp.dot(inForward)) < 1.0e-6,
                   "up and forward must be perpendicular unit vectors");

    // Directions from the box towards the eye in the vehicle frame (left = up x forward).
    const Vec3 left = inUp.cross(inForward);
    switch (inView)
    {
    case EView::Front:
        return LookAtBounds(inMin, inMax, inForward, inUp, inFovYDegrees, inAspect);
    case EView::Side:
        return LookAtBounds(inMin, inMax, -left, inUp, inFovYDegrees, inAspect);
    case EView::Top:
        return LookAtBounds(inMin, inMax, inUp, inForward, inFovYDegrees, inAspect);
    case EView::Iso:
        break;
    }
    return LookAtBounds(inMin, inMax, inForward - left + inUp, inUp, inFovYDegrees, inAspect);
}

} // namespace crumple::render
