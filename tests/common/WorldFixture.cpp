// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "WorldFixture.h"
#include "BoxMesh.h"
#include "ImpulseBodies.h"

#include <cstring>

namespace crumple::common
{

using namespace crumple::plugin;

WorldFixture::WorldFixture(int inTriangles, std::array<int, 3> inControlCount, const DamageWorldSettings& inSettings)
    : mWorldOwner(std::move(DamageWorld::Create(inSettings).Get())), mWorld(*mWorldOwner)
{
    BodyState floor;
    floor.mMotionType = EMotionType::Static;
    mFloor = mWorld.CreateBody(floor).Get();
    BodyState wall;
    wall.mMotionType = EMotionType::Static;
    mWall = mWorld.CreateBody(wall).Get();
    mCar = mWorld.CreateBody(CarState(0.0)).Get();

    DeformableObjectSettings car;
    car.mMesh = MakeBoxMesh(mHalfExtents, BoxSegmentsForTriangles(mHalfExtents, inTriangles));
    car.mFittedControlCount = inControlCount;
    mCarObject = mWorld.CreateDeformableObject(mCar, car).Get();
}

BodyState WorldFixture::CarState(double inSpeed) const
{
    return BoxCarBeforeWall(mMass, mHalfExtents, inSpeed);
}

ContactEvent WorldFixture::FrontContact(double inY, double inZ, double inTime, double inDepth) const
{
    ContactEvent contact;
    contact.mBodyA = mCar;
    contact.mBodyB = mWall;
    contact.mPointOnA = Vec3(inDepth, inY, inZ); // the car's front has sunk inDepth past the wall
    contact.mPointOnB = Vec3(0.0, inY, inZ);
    contact.mNormal = -Vec3::UnitX(); // from the wall to the car
    contact.mPenetrationDepth = inDepth;
    contact.mTime = inTime;
    return contact;
}

} // namespace crumple::common
