// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include "EngineCrash.h"
#include "ImpactSplitSolver.h"

#include <crumple/bullet/BulletAdapter.h>
#include <crumple/bullet/BulletBodyState.h>

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
    /// A loose piece's body (the adapter's CreateConvexBody in this scene's world)
    Result<plugin::BodyId> MakeDebrisBody(const plugin::ConvexBodySettings& inSettings);
    /// A prop's body (the adapter's CreatePropBody in this scene's world)
    Result<plugin::BodyId> MakePropBody(const plugin::PropBodySettings& inSettings);
    /// Removes a body MakeDebrisBody or MakePropBody made, from the engine and the damage world (the
    /// adapter's RemoveBody): a restarted level's props and pieces. Refused for any other id.
    Status RemoveMadeBody(plugin::BodyId inBody);
    /// The car's state as Crumple reads it (mass, world inertia, frame, velocities)
    plugin::BodyState GetCarState() const;
    /// Sets the car's velocities (m/s, rad/s, world): for contacts solved outside the engine
    void SetCarVelocity(const Vec3& inLinear, const Vec3& inAngular);
    /// The target vehicle's deformable object (invalid without one)
    plugin::ObjectId GetTargetObject() const { return mTargetObject; }
    CrashCounter& GetCounter() { return mCounter; }
    /// The damage body of the target (wall or pole; the ground when only driving)
    plugin::BodyId GetWallBody() const { return mWallBody; }

private:
    EngineCrashSettings mSettings;
    std::unique_ptr<btDefaultCollisionConfiguration> mConfiguration;
    std::unique_ptr<btCollisionDispatcher> mDispatcher;
    std::unique_ptr<btDbvtBroadphase> mBroadphase;
    std::unique_ptr<ImpactSplitSolver> mSolver;
    std::unique_ptr<btDiscreteDynamicsWorld> mWorld;
    std::vector<std::unique_ptr<btCollisionShape>> mShapes;
    std::vector<std::unique_ptr<btCollisionObject>> mObjects;
    btRigidBody* mCar = nullptr;
    std::unique_ptr<plugin::DamageWorld> mDamageOwner; ///< On the heap: the world never moves
    plugin::DamageWorld& mDamage;
    std::unique_ptr<bullet::BulletAdapter> mAdapter;
    plugin::ObjectId mCarObject;
    btRigidBody* mTarget = nullptr;
    plugin::ObjectId mTargetObject;
    plugin::BodyId mWallBody;
    CrashCounter mCounter;
};

} // namespace crumple::common
