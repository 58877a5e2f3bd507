// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include "RaceScene.h"

#include <memory>
#include <vector>

class btBoxShape;
class btCollisionDispatcher;
class btCollisionObject;
class btDbvtBroadphase;
class btDefaultCollisionConfiguration;
class btDefaultMotionState;
class btDefaultVehicleRaycaster;
class btDiscreteDynamicsWorld;
class btRaycastVehicle;
class btRigidBody;
class btSequentialImpulseConstraintSolver;
class btStaticPlaneShape;

namespace crumple::bullet
{
class BulletAdapter;
}

namespace crumple::samples
{

/// The racing course (RaceCourse) in Bullet: a btRaycastVehicle whose body is the racing car mesh
/// (RaceCarMesh) on a static ground plane, three concrete barriers as collision objects, the parked car, and
/// the destructible props, with Crumple attached through the BulletAdapter (or not:
/// RaceSceneSettings::mAttach).
class BulletRaceScene final : public RaceScene
{
public:
    static Result<std::unique_ptr<BulletRaceScene>> Create(const RaceSceneSettings& inSettings);
    ~BulletRaceScene() override;

    Status StepFrame(const RaceNewBodies& inNewBodies) override;
    Transform GetCarPose() const override;
    Transform GetParkedPose() const override;

private:
    explicit BulletRaceScene(const RaceSceneSettings& inSettings);

    // In construction order (members are destroyed in reverse: the adapter before the engine's world).
    std::unique_ptr<btDefaultCollisionConfiguration> mConfiguration;
    std::unique_ptr<btCollisionDispatcher> mDispatcher;
    std::unique_ptr<btDbvtBroadphase> mBroadphase;
    std::unique_ptr<btSequentialImpulseConstraintSolver> mSolver;
    std::unique_ptr<btDiscreteDynamicsWorld> mWorld;
    std::unique_ptr<bullet::BulletAdapter> mAdapter;
    std::unique_ptr<btStaticPlaneShape> mGroundShape;
    std::unique_ptr<btRigidBody> mGround;
    std::unique_ptr<btBoxShape> mBarrierShape;
    std::vector<std::unique_ptr<btCollisionObject>> mBarriers;
    std::unique_ptr<btBoxShape> mChassisShape;
    std::unique_ptr<btDefaultMotionState> mCarMotion;
    std::unique_ptr<btRigidBody> mCar;
    std::unique_ptr<btDefaultVehicleRaycaster> mRaycaster;
    std::unique_ptr<btRaycastVehicle> mVehicle;
    std::unique_ptr<btBoxShape> mParkedShape;
    std::unique_ptr<btDefaultMotionState> mParkedMotion;
    std::unique_ptr<btRigidBody> mParked;
    double mWheelBase = 0.0; ///< m, for the driver's steering
};

} // namespace crumple::samples
