// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/plugin/BodyState.h>
#include <crumple/plugin/ConvexBodySettings.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace crumple::plugin
{

Status ValidateConvexBodySettings(const ConvexBodySettings& inSettings)
{
    if (!(inSettings.mMass > 0.0 && inSettings.mMass <= cMaxBodyMass))
        return MakeError(EError::InvalidArgument, "ConvexBodySettings.mMass must be in (0, 1e12] kg");
    const Vec3& inertia = inSettings.mPrincipalInertia;
    if (!IsFinite(inertia) || !(inertia.minCoeff() > 0.0))
        return MakeError(EError::InvalidArgument, "ConvexBodySettings.mPrincipalInertia must be finite and > 0 kg m^2");
    for (int axis = 0; axis < 3; ++axis)
        if (!(inertia[axis] <= (inertia.sum() - inertia[axis]) * (1.0 + 1.0e-9)))
            return MakeError(EError::InvalidArgument, "ConvexBodySettings.mPrincipalInertia: no mass distribution has one "
                                                      "principal moment above the sum of the other two");
    auto within = [](const Vec3& inValue, double inBound) { return IsFinite(inValue) && inValue.cwiseAbs().maxCoeff() <= inBound; };
    if (!within(inSettings.mPosition, cMaxBodyPosition))
        return MakeError(EError::InvalidArgument, "ConvexBodySettings.mPosition must be finite, each coordinate within 1e9 m");
    if (!IsRotation(inSettings.mOrientation, 1.0e-6))
        return MakeError(EError::InvalidArgument, "ConvexBodySettings.mOrientation must be a rotation");
    if (!within(inSettings.mLinearVelocity, cMaxBodySpeed))
        return MakeError(EError::InvalidArgument, "ConvexBodySettings.mLinearVelocity must be finite, within 1e6 m/s");
    if (!within(inSettings.mAngularVelocity, cMaxBodyAngularSpeed))
        return MakeError(EError::InvalidArgument, "ConvexBodySettings.mAngularVelocity must be finite, within 1e6 rad/s");
    const std::vector<Vec3>& points = inSettings.mHullPoints;
    if (points.size() < 4)
        return MakeError(EError::DegenerateGeometry, "ConvexBodySettings.mHullPoints: a hull needs at least 4 points");
    double extent = 0.0;
    for (const Vec3& point : points)
    {
        if (!within(point, cMaxBodyPosition))
            return MakeError(EError::InvalidArgument, "ConvexBodySettings.mHullPoints must be finite, within 1e9 m");
        extent = std::max(extent, (point - points[0]).norm());
    }
    // intent: the points span a volume: some tetrahedron of them is not flat against the points' extent
    double largest = 0.0;
    for (std::size_t i = 1; i < points.size(); ++i)
        for (std::size_t j = i + 1; j < points.size() && largest == 0.0; ++j)
        {
            const Vec3 normal = (points[i] - points[0]).cross(points[j] - points[0]);
            if (normal.norm() <= 1.0e-9 * extent * extent)
                continue;
            for (const Vec3& point : points)
                largest = std::max(largest, std::abs(normal.normalized().dot(point - points[0])));
            if (largest <= 1.0e-9 * extent)
                largest = 0.0;
        }
    if (!(largest > 0.0))
        return MakeError(EError::DegenerateGeometry, "ConvexBodySettings.mHullPoints are flat: they span no volume");
    return Status::Ok();
}

} // namespace crumple::plugin
