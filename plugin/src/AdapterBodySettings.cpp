// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// Validation of the bodies engine adapters create for Crumple: debris (ConvexBodySettings) and props
// (PropBodySettings).
#include <crumple/plugin/BodyState.h>
#include <crumple/plugin/ConvexBodySettings.h>
#include <crumple/plugin/PropBodySettings.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>

namespace crumple::plugin
{

namespace
{

bool Within(const Vec3& inValue, double inBound)
{
    return IsFinite(inValue) && inValue.cwiseAbs().maxCoeff() <= inBound;
}

// Mass, inertia, pose and velocities of a body an adapter makes; inName prefixes the messages.
Status ValidateRigidBody(const std::string& inName, double inMass, const Vec3& inInertia, const Vec3& inPosition,
                         const Mat3& inOrientation, const Vec3& inLinearVelocity, const Vec3& inAngularVelocity)
{
    // intent: an engine in single precision (Bullet's default build) turns a mass below about 1e-38 kg into 0 (a
    // static body) and an inertia that small into an infinite one: the bounds keep the inverses within
    // cMaxInverseInertia, and the largest inertia within a body of cMaxBodyMass spanning cMaxBodyPosition.
    if (!(inMass >= 1.0 / cMaxInverseInertia && inMass <= cMaxBodyMass))
        return MakeError(EError::InvalidArgument, inName + ".mMass must be in [1e-12, 1e12] kg");
    if (!IsFinite(inInertia) || !(inInertia.minCoeff() >= 1.0 / cMaxInverseInertia) ||
        !(inInertia.maxCoeff() <= cMaxBodyMass * cMaxBodyPosition * cMaxBodyPosition))
        return MakeError(EError::InvalidArgument, inName + ".mPrincipalInertia must be in [1e-12, 1e30] kg m^2");
    for (int axis = 0; axis < 3; ++axis)
        if (!(inInertia[axis] <= (inInertia.sum() - inInertia[axis]) * (1.0 + 1.0e-9)))
            return MakeError(EError::InvalidArgument, inName + ".mPrincipalInertia: no mass distribution has one "
                                                               "principal moment above the sum of the other two");
    if (!Within(inPosition, cMaxBodyPosition))
        return MakeError(EError::InvalidArgument, inName + ".mPosition must be finite, each coordinate within 1e9 m");
    // intent: within single-precision round-off, as a body state's (the engines normalize their rotations)
    if (!IsRotation(inOrientation, cRotationTolerance))
        return MakeError(EError::InvalidArgument, inName + ".mOrientation must be a rotation");
    if (!Within(inLinearVelocity, cMaxBodySpeed))
        return MakeError(EError::InvalidArgument, inName + ".mLinearVelocity must be finite, within 1e6 m/s");
    if (!Within(inAngularVelocity, cMaxBodyAngularSpeed))
        return MakeError(EError::InvalidArgument, inName + ".mAngularVelocity must be finite, within 1e6 rad/s");
    return Status::Ok();
}

// Points of one convex hull; inName names them in the messages, with [inPiece] where inPiece >= 0.
Status ValidateHull(const char* inName, std::ptrdiff_t inPiece, const std::vector<Vec3>& inPoints)
{
    // intent: the name is built for a refusal only: a prop's pieces are checked every step its FEM moves
    const auto name = [&]
    {
        std::string named = inName;
        if (inPiece >= 0)
            named.append("[").append(std::to_string(inPiece)).append("]");
        return named;
    };
    const std::vector<Vec3>& points = inPoints;
    if (points.size() < 4)
        return MakeError(EError::DegenerateGeometry, name() + ": a hull needs at least 4 points");
    // intent: one square root, not one per point (a loose piece's hull has a point per FEM node: 1,500 in
    // the racing fence's, checked on the game's thread when it breaks)
    double squared_extent = 0.0;
    for (const Vec3& point : points)
    {
        if (!Within(point, cMaxBodyPosition))
            return MakeError(EError::InvalidArgument, name() + " must be finite, within 1e9 m");
        squared_extent = std::max(squared_extent, (point - points[0]).squaredNorm());
    }
    const double extent = std::sqrt(squared_extent);
    // intent: the points span a volume: some tetrahedron of them is not flat against the points' extent;
    // the first point off a trial plane by more than that settles it
    const double flat = 1.0e-9 * extent;
    for (std::size_t i = 1; i < points.size(); ++i)
        for (std::size_t j = i + 1; j < points.size(); ++j)
        {
            const Vec3 normal = (points[i] - points[0]).cross(points[j] - points[0]);
            if (normal.norm() <= 1.0e-9 * extent * extent)
                continue;
            const Vec3 unit = normal.normalized();
            for (const Vec3& point : points)
                if (std::abs(unit.dot(point - points[0])) > flat)
                    return Status::Ok();
        }
    return MakeError(EError::DegenerateGeometry, name() + " are flat: they span no volume");
}

} // namespace

Status ValidateConvexBodySettings(const ConvexBodySettings& inSettings)
{
    if (Status body = ValidateRigidBody("ConvexBodySettings", inSettings.mMass, inSettings.mPrincipalInertia,
                                        inSettings.mPosition, inSettings.mOrientation, inSettings.mLinearVelocity,
                                        inSettings.mAngularVelocity);
        !body)
        return body;
    return ValidateHull("ConvexBodySettings.mHullPoints", -1, inSettings.mHullPoints);
}

Status ValidatePropPieces(const std::vector<std::vector<Vec3>>& inPieces)
{
    if (inPieces.empty())
        return MakeError(EError::DegenerateGeometry, "PropBodySettings.mPieces: a prop body needs at least one piece");
    for (std::size_t piece = 0; piece < inPieces.size(); ++piece)
        if (Status hull =
                ValidateHull("PropBodySettings.mPieces", static_cast<std::ptrdiff_t>(piece), inPieces[piece]);
            !hull)
            return hull;
    return Status::Ok();
}

Status ValidateHeldVelocity(const Vec3& inVelocity)
{
    if (!IsFinite(inVelocity))
        return MakeError(EError::NonFinite, "SetHeldVelocity: the velocity must be finite");
    if (!(inVelocity.norm() <= cMaxBodySpeed))
        return MakeError(EError::OutOfRange, "SetHeldVelocity: the velocity must be at most 1e6 m/s");
    return Status::Ok();
}

Status ValidateHeldMass(double inMass)
{
    if (!std::isfinite(inMass))
        return MakeError(EError::NonFinite, "SetHeldMass: the mass must be finite");
    if (!(inMass == 0.0 || (inMass >= 1.0e-12 && inMass <= cMaxBodyMass)))
        return MakeError(EError::OutOfRange,
                         "SetHeldMass: the mass must be 0 (the body's own) or in [1e-12, 1e12] kg");
    return Status::Ok();
}

Status ValidatePropBodySettings(const PropBodySettings& inSettings)
{
    if (Status body = ValidateRigidBody("PropBodySettings", inSettings.mMass, inSettings.mPrincipalInertia,
                                        inSettings.mPosition, inSettings.mOrientation, Vec3::Zero(), Vec3::Zero());
        !body)
        return body;
    return ValidatePropPieces(inSettings.mPieces);
}

} // namespace crumple::plugin
