// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "FuzzWorld.h"

#include "BoxMesh.h"

#include <array>
#include <cstdlib>
#include <vector>

namespace crumple::fuzz
{

namespace
{

const Vec3 cHalfExtents(2.1, 0.9, 0.7);

plugin::DeformableObjectSettings CarSettings()
{
    plugin::DeformableObjectSettings settings;
    settings.mMesh = common::MakeBoxMesh(cHalfExtents, common::BoxSegmentsForTriangles(cHalfExtents, 2000));
    return settings;
}

// Aborts on a failure: the fuzz targets need this world, and cannot run without it.
template <class T>
T Must(Result<T> inResult)
{
    if (inResult.HasError())
        std::abort();
    return std::move(inResult.Get());
}

} // namespace

FuzzWorld::FuzzWorld() : mCarSettings(CarSettings()), mWorldOwner(Must(plugin::DamageWorld::Create())), mWorld(*mWorldOwner)
{
    plugin::BodyState car;
    car.mMass = 1200.0;
    car.mInverseInertiaWorld = Mat3::Identity() * (1.0 / 1500.0);
    car.mLinearVelocity = Vec3(15.0, 0.0, 0.0);
    // Both bodies state their shapes, so the seed recordings carry known shape boxes (replay format 11).
    car.mHasShapeBounds = true;
    car.mShapeMin = -cHalfExtents;
    car.mShapeMax = cHalfExtents;
    plugin::BodyState wall;
    wall.mMotionType = plugin::EMotionType::Static;
    wall.mHasShapeBounds = true;
    wall.mShapeMin = Vec3(cHalfExtents.x(), -5.0, -3.0);
    wall.mShapeMax = Vec3(cHalfExtents.x() + 2.0, 5.0, 3.0);
    mCar = Must(mWorld.CreateBody(car));
    mWall = Must(mWorld.CreateBody(wall));
    (void)Must(mWorld.CreateDeformableObject(mCar, mCarSettings));
}

void FuzzWorld::Dent()
{
    // Four contacts at the front face's corners, normal from the wall (B) to the car (A): -x.
    std::vector<plugin::ContactEvent> contacts;
    for (double y : {-0.8, 0.8})
        for (double z : {-0.6, 0.6})
        {
            plugin::ContactEvent contact;
            contact.mBodyA = mCar;
            contact.mBodyB = mWall;
            contact.mPointOnA = Vec3(cHalfExtents.x(), y, z);
            contact.mPointOnB = contact.mPointOnA;
            contact.mNormal = -Vec3::UnitX();
            contacts.push_back(contact);
        }
    if (mWorld.SubmitContacts(contacts).HasError())
        std::abort();
    mWorld.Flush();
}

} // namespace crumple::fuzz
