// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "EngineCrash.h"
#include "BoxMesh.h"

#include <cmath>
#include <limits>
#include <numbers>

namespace crumple::common
{

using namespace crumple::plugin;

EngineCrashResult SummarizeCrash(const DamageWorld& inWorld, ObjectId inCar, int inCollisions, double inTotalImpulse)
{
    EngineCrashResult result;
    const ffd::FfdDeformer& car = inWorld.GetObject(inCar)->GetDeformer();
    const std::vector<Vec3>& rest = car.GetRestMesh().mPositions;
    double weight = 0.0;
    for (std::size_t v = 0; v < rest.size(); ++v)
    {
        const double d = (car.GetPositions()[v] - rest[v]).norm();
        result.mMaxDent = std::max(result.mMaxDent, d);
        result.mDentCentroid += d * rest[v];
        weight += d;
    }
    if (weight > 0.0)
        result.mDentCentroid /= weight;
    result.mCollisions = inCollisions;
    result.mTotalImpulse = inTotalImpulse;
    result.mPositions = car.GetPositions();
    result.mDamage = inWorld.SaveDamage();
    return result;
}

Vec3 ImpulseOnBody(std::span<const Collision> inLog, BodyId inBody)
{
    Vec3 impulse = Vec3::Zero();
    for (const Collision& collision : inLog)
        for (const CollisionContact& contact : collision.mContacts)
        {
            if (collision.mBodyA == inBody)
                impulse += contact.ImpulseOnA();
            else if (collision.mBodyB == inBody)
                impulse -= contact.ImpulseOnA();
        }
    return impulse;
}

void CrashCounter::OnCollision(const Collision& inCollision, std::span<const ObjectDent> inDents)
{
    ++mCollisions;
    for (const ObjectDent& dent : inDents)
    {
        mLimitedDents += dent.mReport.IsLimited() ? 1 : 0;
        mStackedUpDents += dent.mReport.mStackedUp;
    }
    mTotalImpulse += inCollision.TotalImpulse();
    mLog.push_back(inCollision);
}

std::vector<std::pair<std::string, EngineCrashSettings>> ImpactMatrix(double inKmH, double inFriction)
{
    EngineCrashSettings base;
    base.mSpeed = inKmH / 3.6;
    base.mDuration = 0.3;
    base.mTriangles = 2000;
    base.mFriction = inFriction; // the wall's and the other car's; with 0 the normal impulses act alone
    base.mGroundFriction = 0.0;
    const std::string speed = std::to_string(static_cast<int>(inKmH)) + " km/h ";
    std::vector<std::pair<std::string, EngineCrashSettings>> crashes{{speed + "frontal", base}};
    // intent: each other impact is the frontal one with what makes it that impact
    const auto add = [&](const std::string& inName, const auto& inChange)
    {
        EngineCrashSettings crash = base;
        inChange(crash);
        crashes.emplace_back(speed + inName, crash);
    };
    add("40 % offset", [](EngineCrashSettings& ioCrash) { ioCrash.mOverlapFraction = 0.4; });
    add("30-degree wall", [](EngineCrashSettings& ioCrash) { ioCrash.mWallAngleDegrees = 30.0; });
    // Glancing: with friction the corner slides along the wall through the whole impact.
    add("45-degree wall", [](EngineCrashSettings& ioCrash) { ioCrash.mWallAngleDegrees = 45.0; });
    add("pole", [](EngineCrashSettings& ioCrash) { ioCrash.mPoleRadius = 0.127; });
    // A racing hit: into the rear corner of a parked car, and into its side (two dynamic bodies).
    add("rear-end into a parked car's corner",
        [](EngineCrashSettings& ioCrash)
        {
            ioCrash.mTargetVehicle = TargetVehicleSettings{};
            ioCrash.mTargetVehicle->mYawDegrees = 0.0;
            ioCrash.mTargetVehicle->mOffset = 0.8;
        });
    add("into a parked car's side",
        [](EngineCrashSettings& ioCrash) { ioCrash.mTargetVehicle = TargetVehicleSettings{}; });
    return crashes;
}

DeformableObjectSettings CrashCarObject(const EngineCrashSettings& inSettings)
{
    DeformableObjectSettings object;
    object.mMesh = inSettings.mCarMesh ? *inSettings.mCarMesh
                                       : MakeBoxMesh(inSettings.mHalfExtents,
                                                     BoxSegmentsForTriangles(inSettings.mHalfExtents, inSettings.mTriangles));
    object.mMaterial = inSettings.mMaterial;
    object.mFittedControlCount = inSettings.mControlCount;
    object.mFittedControlSpacing = inSettings.mControlSpacing;
    object.mFitSpacingToOccupantCell = inSettings.mFitSpacingToOccupantCell;
    object.mFittedMaxTotalDeformation = inSettings.mMaxTotalDeformation;
    object.mDeformer.mZones = inSettings.mZones;
    if (inSettings.mCarMesh)
        object.mDeformer.mRigidParts = inSettings.mCarRigidParts;
    return object;
}

Transform CrashCarStart(const EngineCrashSettings& inSettings)
{
    if (inSettings.mPoleRadius > 0.0)
    {
        // A pole at the origin: the car's nearest point mGap before its surface, at y = mOffset.
        Transform start;
        start.mRotation = Eigen::AngleAxisd(inSettings.mYawDegrees * std::numbers::pi / 180.0, Vec3::UnitZ()).toRotationMatrix();
        double reach = 0.0;
        for (double sx : {-1.0, 1.0})
            for (double sy : {-1.0, 1.0})
                reach = std::max(reach, (start.mRotation * Vec3(sx * inSettings.mHalfExtents.x(), sy * inSettings.mHalfExtents.y(), 0.0)).x());
        start.mTranslation = Vec3(-inSettings.mPoleRadius - inSettings.mGap - reach, inSettings.mOffset, inSettings.mHalfExtents.z());
        return start;
    }
    // Wall face: the plane n . x = 0 with n = (cos a, sin a, 0) pointing into the wall.
    const double angle = inSettings.mWallAngleDegrees * std::numbers::pi / 180.0;
    const Vec3 normal(std::cos(angle), std::sin(angle), 0.0);
    Transform start;
    start.mRotation = Eigen::AngleAxisd(inSettings.mYawDegrees * std::numbers::pi / 180.0, Vec3::UnitZ()).toRotationMatrix();
    const Vec3& h = inSettings.mHalfExtents;
    double reach = -std::numeric_limits<double>::infinity();
    for (double sx : {-1.0, 1.0})
        for (double sy : {-1.0, 1.0})
            reach = std::max(reach, normal.dot(start.mRotation * Vec3(sx * h.x(), sy * h.y(), 0.0)));
    // n . (c + corner) = -gap for the nearest corner, with c = (x, offset, h.z).
    const double x = (-inSettings.mGap - reach - normal.y() * inSettings.mOffset) / normal.x();
    start.mTranslation = Vec3(x, inSettings.mOffset, h.z());
    return start;
}

Transform TargetVehicleStart(const TargetVehicleSettings& inTarget)
{
    Transform start;
    start.mRotation = Eigen::AngleAxisd(inTarget.mYawDegrees * std::numbers::pi / 180.0, Vec3::UnitZ()).toRotationMatrix();
    double reach = 0.0;
    for (double sx : {-1.0, 1.0})
        for (double sy : {-1.0, 1.0})
            reach = std::max(reach, -(start.mRotation * Vec3(sx * inTarget.mHalfExtents.x(), sy * inTarget.mHalfExtents.y(), 0.0)).x());
    start.mTranslation = Vec3(reach, inTarget.mOffset, inTarget.mHalfExtents.z());
    return start;
}

DeformableObjectSettings TargetVehicleObject(const TargetVehicleSettings& inTarget)
{
    DeformableObjectSettings object;
    object.mMesh = MakeBoxMesh(inTarget.mHalfExtents, BoxSegmentsForTriangles(inTarget.mHalfExtents, 4000));
    object.mMaterial = inTarget.mMaterial;
    object.mFittedControlCount = {10, 6, 6};
    return object;
}

double CrashWallLeftEdge(const EngineCrashSettings& inSettings)
{
    // The wall spans y >= edge: it overlaps mOverlapFraction of the car's width on the car's +y side.
    return inSettings.mOffset + inSettings.mHalfExtents.y() - 2.0 * inSettings.mHalfExtents.y() * inSettings.mOverlapFraction;
}

} // namespace crumple::common
