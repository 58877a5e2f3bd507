// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include "EngineCrash.h"

#include <crumple/bullet/BulletAdapter.h>

#include <btBulletDynamicsCommon.h>

#include <memory>

namespace crumple::common
{

/// EngineCrashSettings run in Bullet (btDiscreteDynamicsWorld, fixed internal step).
class BulletWallCrash
{
public:
    explicit BulletWallCrash(const EngineCrashSettings& inSettings);
    ~BulletWallCrash();

    /// Steps to the end and summarizes.
    EngineCrashResult Run();
    /// One engine step of mTimeStep.
    void Step();

    btDiscreteDynamicsWorld& GetWorld() { return *mWorld; }
    btRigidBody& GetCar() { return *mCar; }
    bullet::BulletAdapter& GetAdapter() { return *mAdapter; }
    plugin::DamageWorld& GetDamage() { return mDamage; }
    plugin::ObjectId GetCarObject() const { return mCarObject; }
    /// The barrier's damage body (invalid without one)
    plugin::BodyId GetBarrierBody() const { return mBarrierBody; }
    /// Takes the barrier out of the engine (the car drives on); nothing without one.
    void RemoveBarrier();
    /// The target vehicle's deformable object (invalid without one)
    plugin::ObjectId GetTargetObject() const { return mTargetObject; }
    CrashCounter& GetCounter() { return mCounter; }

private:
    EngineCrashSettings mSettings;
    std::unique_ptr<btDefaultCollisionConfiguration> mConfiguration;
    std::unique_ptr<btCollisionDispatcher> mDispatcher;
    std::unique_ptr<btDbvtBroadphase> mBroadphase;
    std::unique_ptr<btSequentialImpulseConstraintSolver> mSolver;
    std::unique_ptr<btDiscreteDynamicsWorld> mWorld;
    std::vector<std::unique_ptr<btCollisionShape>> mShapes;
    std::vector<std::unique_ptr<btCollisionObject>> mObjects;
    btRigidBody* mCar = nullptr;
    plugin::DamageWorld mDamage;
    std::unique_ptr<bullet::BulletAdapter> mAdapter;
    plugin::ObjectId mCarObject;
    btRigidBody* mTarget = nullptr;
    btCollisionObject* mBarrier = nullptr;
    plugin::BodyId mBarrierBody;
    plugin::ObjectId mTargetObject;
    CrashCounter mCounter;
};

} // namespace crumple::common
