// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "EngineCrash.h"
#include "BoxMesh.h"

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

void CrashCounter::OnCollision(const Collision& inCollision, std::span<const ObjectDent>)
{
    ++mCollisions;
    mTotalImpulse += inCollision.TotalImpulse();
    mLog.push_back(inCollision);
}

DeformableObjectSettings CrashCarObject(const EngineCrashSettings& inSettings)
{
    DeformableObjectSettings object;
    object.mMesh = MakeBoxMesh(inSettings.mHalfExtents, BoxSegmentsForTriangles(inSettings.mHalfExtents, inSettings.mTriangles));
    object.mMaterial = inSettings.mMaterial;
    object.mFittedControlCount = inSettings.mControlCount;
    return object;
}

} // namespace crumple::common
