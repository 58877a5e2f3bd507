// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>

namespace crumple
{

/// Vectors and matrices of the CPU path: double precision, SI units, right-handed.
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Quat = Eigen::Quaterniond;

/// True when every component is finite (no NaN, no Inf).
template <class Derived>
inline bool IsFinite(const Eigen::MatrixBase<Derived>& inValue)
{
    return inValue.allFinite();
}
inline bool IsFinite(double inValue)
{
    return std::isfinite(inValue);
}

/// A rigid transform from a body frame to the world: x_world = mRotation * x_body + mTranslation.
struct CRUMPLE_API Transform
{
    Mat3 mRotation = Mat3::Identity(); ///< Body axes in world coordinates (columns), orthonormal, det +1
    Vec3 mTranslation = Vec3::Zero();  ///< Body origin in world coordinates (m)

    Vec3 ToWorld(const Vec3& inBodyPoint) const { return mRotation * inBodyPoint + mTranslation; }
    Vec3 ToBody(const Vec3& inWorldPoint) const { return mRotation.transpose() * (inWorldPoint - mTranslation); }
    Vec3 DirectionToBody(const Vec3& inWorldDirection) const { return mRotation.transpose() * inWorldDirection; }
};

/// True when inRotation is orthonormal with determinant +1 to within inTolerance.
inline bool IsRotation(const Mat3& inRotation, double inTolerance = 1.0e-9)
{
    return IsFinite(inRotation) && (inRotation.transpose() * inRotation - Mat3::Identity()).norm() < inTolerance &&
           std::abs(inRotation.determinant() - 1.0) < inTolerance;
}

/// The smallest of 1, 2, 2.5 and 5 times a power of ten that is at least inValue (> 0, finite; to within
/// 1e-9 relative, so a value already round stays): round scale tops and grid steps for pictures and plots.
inline double RoundUpToNiceNumber(double inValue)
{
    const double decade = std::pow(10.0, std::floor(std::log10(inValue)));
    for (double step : {1.0, 2.0, 2.5, 5.0})
        if (inValue <= step * decade * (1.0 + 1.0e-9))
            return step * decade;
    return 10.0 * decade;
}

} // namespace crumple
