// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "BulletRaceScene.h"
#include "BoxMesh.h"
#include "RaceProps.h"
#include "RaceSession.h"

#include <crumple/bullet/BulletAdapter.h>
#include <crumple/ffd/BoundingBox.h>

#include <BulletDynamics/Vehicle/btRaycastVehicle.h>
#include <btBulletDynamicsCommon.h>

namespace crumple::samples
{

using namespace crumple::plugin;

namespace
{

constexpr double cFrame = 1.0 / 60.0; // a frame: four engine steps of 1/240 s

Transform ToTransform(const btTransform& inTransform)
{
    Transform t;
    const btMatrix3x3& b = inTransform.getBasis();
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            t.mRotation(r, c) = static_cast<double>(b[r][c]);
    t.mRotation = Quat(t.mRotation).normalized().toRotationMatrix();
    t.mTranslation = Vec3(inTransform.getOrigin().x(), inTransform.getOrigin().y(), inTransform.getOrigin().z());
    return t;
}

btTransform ToBullet(const Transform& inTransform)
{
    const Quat q(inTransform.mRotation);
    return btTransform(btQuaternion(btScalar(q.x()), btScalar(q.y()), btScalar(q.z()), btScalar(q.w())),
                       btVector3(btScalar(inTransform.mTranslation.x()), btScalar(inTransform.mTranslation.y()),
                                 btScalar(inTransform.mTranslation.z())));
}

btVector3 ToBullet(const Vec3& inV)
{
    return btVector3(btScalar(inV.x()), btScalar(inV.y()), btScalar(inV.z()));
}

} // namespace

Result<std::unique_ptr<BulletRaceScene>> BulletRaceScene::Create(const RaceSceneSettings& inSettings)
{
    std::unique_ptr<BulletRaceScene> scene(new BulletRaceScene(inSettings));
    BulletRaceScene& s = *scene;
    const ffd::TriangleMesh car_mesh = RaceCarMesh();
    const ffd::AlignedBox bounds = ffd::BoundingBox(car_mesh.mPositions);
    const Vec3 half = 0.5 * (bounds.mMax - bounds.mMin);

    s.mConfiguration = std::make_unique<btDefaultCollisionConfiguration>();
    s.mDispatcher = std::make_unique<btCollisionDispatcher>(s.mConfiguration.get());
    s.mBroadphase = std::make_unique<btDbvtBroadphase>();
    s.mSolver = std::make_unique<btSequentialImpulseConstraintSolver>();
    s.mWorld = std::make_unique<btDiscreteDynamicsWorld>(s.mDispatcher.get(), s.mBroadphase.get(), s.mSolver.get(),
                                                         s.mConfiguration.get());
    s.mWorld->setGravity(btVector3(0, 0, btScalar(RaceCourse::Gravity().z())));
    if (inSettings.mAttach)
    {
        if (Status created = s.CreateDamageWorld(); !created)
            return created.GetError();
        // The sample prints Crumple's share of every frame: the adapter measures its callbacks' CPU time.
        bullet::BulletAdapterSettings adapter_settings;
        adapter_settings.mMeasureCpuTime = true;
        Result<std::unique_ptr<bullet::BulletAdapter>> adapter = bullet::BulletAdapter::Create(*s.mWorld, *s.mDamage, adapter_settings);
        if (!adapter)
            return adapter.GetError();
        s.mAdapter = std::move(adapter).Get();
    }
    // Crumple's handle of a body, when it is attached. The ground and the course's barriers are quiet
    // (DamageWorld::SetQuiet), as the props' loose pieces are: pieces rattling on them make no collisions.
    const auto add = [&s](btCollisionObject& ioObject, const std::string& inName,
                          bool inQuiet) -> Result<BodyId>
    {
        if (s.mAdapter == nullptr)
            return BodyId{};
        Result<BodyId> body = s.mAdapter->AddBody(ioObject);
        if (!body)
            return body;
        s.mNames[body.Get()] = inName;
        if (Status quiet = s.mDamage->SetQuiet(body.Get(), inQuiet); !quiet)
            return quiet.GetError();
        return body;
    };

    // The ground is a static btRigidBody: btDefaultVehicleRaycaster only lets wheels stand on rigid bodies.
    s.mGroundShape = std::make_unique<btStaticPlaneShape>(btVector3(0, 0, 1), 0);
    s.mGround = std::make_unique<btRigidBody>(btRigidBody::btRigidBodyConstructionInfo(0, nullptr, s.mGroundShape.get()));
    s.mGround->setFriction(btScalar(0.9));
    s.mWorld->addRigidBody(s.mGround.get());
    if (Result<BodyId> added = add(*s.mGround, "ground", true); !added)
        return added.GetError();

    s.mBarrierShape = std::make_unique<btBoxShape>(ToBullet(RaceCourse::BarrierHalfExtents()));
    for (const Transform& pose : RaceCourse::Barriers())
    {
        auto barrier = std::make_unique<btCollisionObject>();
        barrier->setCollisionShape(s.mBarrierShape.get());
        barrier->setWorldTransform(ToBullet(pose));
        // intent: held by the scene before anything can fail, so that its destructor takes it out of the world
        s.mWorld->addCollisionObject(barrier.get());
        s.mBarriers.push_back(std::move(barrier));
        if (Result<BodyId> added =
                add(*s.mBarriers.back(), "barrier " + std::to_string(s.mBarriers.size()), true);
            !added)
            return added.GetError();
    }

    // The racing car: a chassis box around the body mesh on four raycast wheels.
    s.mChassisShape = std::make_unique<btBoxShape>(btVector3(btScalar(half.x()), btScalar(half.y()), btScalar(0.8 * half.z())));
    const double mass = 1200.0;
    btVector3 inertia;
    s.mChassisShape->calculateLocalInertia(btScalar(mass), inertia);
    // Wheels reach 0.3 h + 0.35 + 0.35 m below the centre of mass; start at the loaded ride height.
    const double ride_height = 0.3 * half.z() + 0.7 - 0.05;
    s.mCarMotion = std::make_unique<btDefaultMotionState>(btTransform(btQuaternion::getIdentity(), btVector3(0, 0, btScalar(ride_height))));
    s.mCar = std::make_unique<btRigidBody>(
        btRigidBody::btRigidBodyConstructionInfo(btScalar(mass), s.mCarMotion.get(), s.mChassisShape.get(), inertia));
    s.mCar->setActivationState(DISABLE_DEACTIVATION);
    s.mWorld->addRigidBody(s.mCar.get());
    s.mRaycaster = std::make_unique<btDefaultVehicleRaycaster>(s.mWorld.get());
    btRaycastVehicle::btVehicleTuning tuning;
    s.mVehicle = std::make_unique<btRaycastVehicle>(tuning, s.mCar.get(), s.mRaycaster.get());
    s.mVehicle->setCoordinateSystem(1, 2, 0); // right = y, up = z, forward = x
    s.mWorld->addAction(s.mVehicle.get());
    s.mWheelBase = 1.4 * half.x();
    for (int i = 0; i < 4; ++i)
    {
        const bool front = i < 2;
        const btVector3 connection(btScalar((front ? 0.7 : -0.7) * half.x()), btScalar((i % 2 == 0 ? 0.8 : -0.8) * half.y()),
                                   btScalar(-0.3 * half.z()));
        btWheelInfo& wheel = s.mVehicle->addWheel(connection, btVector3(0, 0, -1), btVector3(0, -1, 0), 0.35f, 0.35f, tuning, front);
        wheel.m_suspensionStiffness = 30.0f;
        wheel.m_wheelsDampingRelaxation = 4.0f;
        wheel.m_wheelsDampingCompression = 3.0f;
        wheel.m_frictionSlip = 1.2f;
        wheel.m_rollInfluence = 0.1f;
        wheel.m_maxSuspensionForce = 60000.0f; // Bullet's default (6,000 N) cannot hold a 1.2 t car landing
    }
    Result<BodyId> car_body = add(*s.mCar, "racing car", false);
    if (!car_body)
        return car_body.GetError();
    if (s.mDamage != nullptr)
    {
        Result<const DeformableObject*> car = s.CreateCarObject(car_body.Get(), car_mesh);
        if (!car)
            return car.GetError();
        s.mCarObject = car.Get();
    }

    // The parked car.
    s.mParkedShape = std::make_unique<btBoxShape>(ToBullet(RaceCourse::ParkedHalfExtents()));
    btVector3 parked_inertia;
    s.mParkedShape->calculateLocalInertia(btScalar(RaceCourse::cParkedMass), parked_inertia);
    s.mParkedMotion = std::make_unique<btDefaultMotionState>(ToBullet(RaceCourse::ParkedCar()));
    btRigidBody::btRigidBodyConstructionInfo parked_info(btScalar(RaceCourse::cParkedMass), s.mParkedMotion.get(),
                                                         s.mParkedShape.get(), parked_inertia);
    parked_info.m_friction = 0.8f;
    s.mParked = std::make_unique<btRigidBody>(parked_info);
    s.mWorld->addRigidBody(s.mParked.get());
    Result<BodyId> parked_body = add(*s.mParked, "parked car", false);
    if (!parked_body)
        return parked_body.GetError();
    if (s.mDamage == nullptr)
        return scene;
    Result<const DeformableObject*> parked = s.CreateCarObject(parked_body.Get(), common::MakeBoxMesh(RaceCourse::ParkedHalfExtents(), {42, 18, 14}));
    if (!parked)
        return parked.GetError();
    s.mParkedObject = parked.Get();

    // The destructible props: the adapter makes and holds their bodies, RaceProps steps their FEM after each
    // engine step.
    bullet::BulletAdapter& bodies = *s.mAdapter;
    Result<std::unique_ptr<RaceProps>> props = RaceProps::Create(
        *s.mDamage,
        {.mMakePropBody = [&bodies](const PropBodySettings& inBody) { return bodies.CreatePropBody(inBody); },
         .mHeld = HeldPropCalls(bodies, [&bodies](const ConvexBodySettings& inBody)
                                { return bodies.CreateConvexBody(inBody); })},
        cFrame / 4.0, s.mSettings.mPropsOffThread);
    if (Status kept = s.KeepProps(std::move(props)); !kept)
        return kept.GetError();
    return scene;
}

BulletRaceScene::BulletRaceScene(const RaceSceneSettings& inSettings) : RaceScene(inSettings)
{
}

BulletRaceScene::~BulletRaceScene()
{
    // The props before the adapter that holds their bodies; the game's bodies leave the world before the
    // world and the adapter go (the props' and pieces' bodies are the adapter's own).
    mProps.reset();
    if (mWorld == nullptr)
        return;
    if (mVehicle != nullptr)
        mWorld->removeAction(mVehicle.get());
    for (btRigidBody* body : {mParked.get(), mCar.get()})
        if (body != nullptr)
            mWorld->removeRigidBody(body);
    for (const auto& barrier : mBarriers)
        mWorld->removeCollisionObject(barrier.get());
    if (mGround != nullptr)
        mWorld->removeRigidBody(mGround.get());
}

Status BulletRaceScene::StepFrame(const RaceNewBodies& inNewBodies)
{
    // Drive: full throttle to the target speed, then hold it.
    const double speed = static_cast<double>(mVehicle->getCurrentSpeedKmHour()) / 3.6;
    for (int wheel = 2; wheel < 4; ++wheel)
        mVehicle->applyEngineForce(speed < mSettings.mSpeed ? btScalar(6000) : btScalar(0), wheel);
    // Steer: back to the course line (Bullet's steering value turns a wheel about the up axis, to the left)
    const double steering = RaceCourse::SteeringAngle(GetCarPose(), mWheelBase);
    for (int wheel = 0; wheel < 2; ++wheel)
        mVehicle->setSteeringValue(btScalar(steering), wheel);
    mFrameCrumpleMs = 0.0;
    for (int sub = 0; sub < 4; ++sub)
    {
        mWorld->stepSimulation(btScalar(cFrame / 4.0), 0); // exactly one step of 1/240 s
        if (mAdapter != nullptr)
            mFrameCrumpleMs += 1.0e3 * mAdapter->GetLastStepStats().mSeconds;
        if (Status stepped = StepProps(cFrame / 4.0, inNewBodies); !stepped)
            return stepped;
    }
    return Status::Ok();
}

Transform BulletRaceScene::GetCarPose() const
{
    return ToTransform(mCar->getWorldTransform());
}

Transform BulletRaceScene::GetParkedPose() const
{
    return ToTransform(mParked->getWorldTransform());
}

} // namespace crumple::samples
