// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "BoxMesh.h"
#include "BulletWallCrash.h"
#include "HeldWall.h"
#include "TurnedBlock.h"

#include <crumple/bullet/BulletAdapter.h>

#include <BulletDynamics/Vehicle/btRaycastVehicle.h>
#include <btBulletDynamicsCommon.h>
#include <catch2/catch.hpp>
#include "ScratchDirectory.h"

#include <crumple/base/FileBytes.h>
#include <crumple/plugin/DamageRecorder.h>
#include <crumple/plugin/ReplayDamage.h>

#include <filesystem>

#include <algorithm>
#include <cmath>

using namespace crumple;
using namespace crumple::plugin;
using namespace crumple::common;

namespace
{

// A minimal Bullet world with its own lifetime management.
struct BulletWorld
{
    BulletWorld()
        : mDispatcher(&mConfiguration), mWorld(&mDispatcher, &mBroadphase, &mSolver, &mConfiguration)
    {
        mWorld.setGravity(btVector3(0, 0, btScalar(-9.81)));
    }
    ~BulletWorld()
    {
        for (int i = mWorld.getNumCollisionObjects() - 1; i >= 0; --i)
            mWorld.removeCollisionObject(mWorld.getCollisionObjectArray()[i]);
    }
    btDefaultCollisionConfiguration mConfiguration;
    btCollisionDispatcher mDispatcher;
    btDbvtBroadphase mBroadphase;
    btSequentialImpulseConstraintSolver mSolver;
    btDiscreteDynamicsWorld mWorld;
};

// The game's own tick callbacks: they must keep running, with the game's user pointer.
struct GameHooks
{
    int mPre = 0, mPost = 0;
    std::vector<double> mStepImpulses; // per sub-step sum of m_appliedImpulse (N s)
};

void GamePreTick(btDynamicsWorld* inWorld, btScalar)
{
    static_cast<GameHooks*>(inWorld->getWorldUserInfo())->mPre++;
}

void GamePostTick(btDynamicsWorld* inWorld, btScalar)
{
    auto* hooks = static_cast<GameHooks*>(inWorld->getWorldUserInfo());
    hooks->mPost++;
    double sum = 0.0;
    for (int m = 0; m < inWorld->getDispatcher()->getNumManifolds(); ++m)
    {
        const btPersistentManifold* manifold = inWorld->getDispatcher()->getManifoldByIndexInternal(m);
        for (int p = 0; p < manifold->getNumContacts(); ++p)
            sum += static_cast<double>(manifold->getContactPoint(p).m_appliedImpulse);
    }
    hooks->mStepImpulses.push_back(sum);
}

} // namespace

TEST_CASE("Bullet: a sphere dropped on a plane gets (1+e) m v, and agrees with Bullet's solver", "[bullet]")
{
    BulletWorld bullet;
    GameHooks hooks;
    bullet.mWorld.setInternalTickCallback(&GamePreTick, &hooks, true);
    bullet.mWorld.setInternalTickCallback(&GamePostTick, &hooks, false);

    DamageWorldSettings settings;
    settings.mRestitution = 0.0; // Bullet's default restitution is 0
    std::unique_ptr<DamageWorld> damage_owner = std::move(DamageWorld::Create(settings).Get());
    DamageWorld& damage = *damage_owner;
    std::unique_ptr<bullet::BulletAdapter> adapter = std::move(bullet::BulletAdapter::Create(bullet.mWorld, damage).Get());

    btStaticPlaneShape plane_shape(btVector3(0, 0, 1), 0);
    btCollisionObject plane;
    plane.setCollisionShape(&plane_shape);
    bullet.mWorld.addCollisionObject(&plane);
    const double mass = 2.0, radius = 0.5, drop = 1.25;
    btSphereShape sphere_shape{btScalar(radius)};
    btVector3 inertia;
    sphere_shape.calculateLocalInertia(btScalar(mass), inertia);
    btRigidBody::btRigidBodyConstructionInfo info(btScalar(mass), nullptr, &sphere_shape, inertia);
    info.m_startWorldTransform.setOrigin(btVector3(0, 0, btScalar(radius + drop)));
    btRigidBody sphere(info);
    bullet.mWorld.addRigidBody(&sphere);
    REQUIRE(adapter->AddBody(plane));
    REQUIRE(adapter->AddBody(sphere));
    CHECK(adapter->AddBody(sphere).HasError());

    CrashCounter counter;
    damage.AddListener(&counter);
    const btScalar dt = btScalar(1.0 / 240.0);
    for (int i = 0; i < 240; ++i)
        bullet.mWorld.stepSimulation(dt, 1, dt);
    damage.Flush();

    // Chained: the game's callbacks ran every sub-step with the game's own user pointer.
    CHECK(hooks.mPre == 240);
    CHECK(hooks.mPost == 240);
    REQUIRE(counter.mCollisions >= 1);
    const Collision& impact = counter.mLog.front();
    double approach = 0.0;
    for (const CollisionContact& c : impact.mContacts)
        approach = std::max(approach, c.mApproachSpeed + 0.0);
    // The free-fall speed at impact, within the sub-step the contact was found in.
    const double v_fall = std::sqrt(2.0 * 9.81 * drop);
    CHECK(approach == Approx(v_fall).epsilon(0.05));
    // Crumple's impulse over the whole impact equals m v (e = 0), however Bullet split it into steps.
    CHECK(impact.TotalImpulse() == Approx(mass * v_fall).epsilon(0.02));
    // Bullet's solver spreads the impact over the speculative step and the touching one. Over the first
    // three steps with contact it applied m v plus three steps of gravity (the sphere then rests), each
    // m g dt: compare what is left with Crumple's, within one more step of gravity and 2 %.
    const double gravity_step = mass * 9.81 * static_cast<double>(dt);
    const auto first = std::find_if(hooks.mStepImpulses.begin(), hooks.mStepImpulses.end(), [](double j) { return j > 0.0; });
    REQUIRE(hooks.mStepImpulses.end() - first >= 3);
    const double bullet_impact = first[0] + first[1] + first[2] - 3.0 * gravity_step;
    INFO("Bullet applied " << bullet_impact << " N s over the impact, Crumple " << impact.TotalImpulse() << " N s");
    CHECK(std::abs(bullet_impact - impact.TotalImpulse()) <= gravity_step + 0.02 * impact.TotalImpulse());

    // The destructor puts the game's callbacks back.
    adapter.reset();
    const int before = hooks.mPost;
    bullet.mWorld.stepSimulation(dt, 1, dt);
    CHECK(hooks.mPost == before + 1);
    CHECK(bullet.mWorld.getWorldUserInfo() == &hooks);
    bullet.mWorld.removeRigidBody(&sphere);
    bullet.mWorld.removeCollisionObject(&plane);
}

TEST_CASE("Bullet: the box car crash dents the front, head-on and at 30 degrees", "[bullet]")
{
    for (double yaw : {0.0, 30.0})
    {
        EngineCrashSettings settings;
        settings.mYawDegrees = yaw;
        BulletWallCrash crash(settings);
        const EngineCrashResult result = crash.Run();
        INFO("yaw " << yaw << ": max dent " << result.mMaxDent << " m at " << result.mDentCentroid.transpose());
        CHECK(result.mCollisions >= 1);
        CHECK(result.mMaxDent > 0.1);
        CHECK(result.mMaxDent <= settings.mMaterial.mMaxInstantDeformation * 2.0 + 1.0e-9);
        CHECK(result.mDentCentroid.x() > 1.0); // the front of the car
        if (yaw > 0.0)
            CHECK(result.mDentCentroid.y() < -0.2); // yawed to +y, the front-right corner (body y < 0) hits first
    }
}

TEST_CASE("Bullet: a car driving on flat ground gets no damage", "[bullet]")
{
    EngineCrashSettings settings;
    settings.mDriveOnly = true;
    settings.mSpeed = 25.0;
    settings.mDuration = 1.0;
    settings.mMeasureAdapterTime = true;
    BulletWallCrash drive(settings);
    const EngineCrashResult result = drive.Run();
    CHECK(result.mMaxDent == 0.0);
    CHECK(drive.GetAdapter().GetLastStepStats().mContactsReported > 0); // it is on the ground all along
    // The adapter's own share of the step, on the game's thread: some, and far less than a step's 1/60 s.
    const double seconds = drive.GetAdapter().GetLastStepStats().mSeconds;
    CHECK(seconds > 0.0);
    CHECK(seconds < 1.0 / 60.0);
    // Unless asked for, the time is not measured (the clock is a system call): the same drive reports none.
    settings.mMeasureAdapterTime = false;
    BulletWallCrash unmeasured(settings);
    unmeasured.Run();
    CHECK(unmeasured.GetAdapter().GetLastStepStats().mContactsReported > 0);
    CHECK(unmeasured.GetAdapter().GetLastStepStats().mSeconds == 0.0);
}

TEST_CASE("Bullet: a compound chassis maps its children's contacts to its body", "[bullet]")
{
    BulletWorld bullet;
    std::unique_ptr<DamageWorld> damage_owner = std::move(DamageWorld::Create().Get());
    DamageWorld& damage = *damage_owner;
    std::unique_ptr<bullet::BulletAdapter> adapter = std::move(bullet::BulletAdapter::Create(bullet.mWorld, damage).Get());
    btStaticPlaneShape plane_shape(btVector3(0, 0, 1), 0);
    btCollisionObject plane;
    plane.setCollisionShape(&plane_shape);
    bullet.mWorld.addCollisionObject(&plane);
    REQUIRE(adapter->AddBody(plane));

    btBoxShape lower(btVector3(2, 1, 0.3f)), cabin(btVector3(1, 0.8f, 0.3f));
    btCompoundShape chassis;
    chassis.addChildShape(btTransform(btQuaternion::getIdentity(), btVector3(0, 0, 0)), &lower);
    chassis.addChildShape(btTransform(btQuaternion::getIdentity(), btVector3(0, 0, 0.6f)), &cabin);
    btVector3 inertia;
    chassis.calculateLocalInertia(1000, inertia);
    btRigidBody::btRigidBodyConstructionInfo info(1000, nullptr, &chassis, inertia);
    // Upside down, falling on its cabin from 2 m.
    info.m_startWorldTransform = btTransform(btQuaternion(btVector3(1, 0, 0), SIMD_PI), btVector3(0, 0, 3));
    btRigidBody car(info);
    bullet.mWorld.addRigidBody(&car);
    const BodyId car_body = adapter->AddBody(car).Get();
    CrashCounter counter;
    damage.AddListener(&counter);
    for (int i = 0; i < 120; ++i)
        bullet.mWorld.stepSimulation(btScalar(1.0 / 120.0), 1, btScalar(1.0 / 120.0));
    damage.Flush();
    REQUIRE(counter.mCollisions >= 1);
    CHECK(counter.mLog.front().mBodyB == car_body);
    // The roof (the cabin child, +z in the body frame) took the hit.
    CHECK(counter.mLog.front().mContacts.front().mLocalPointOnB.z() > 0.6);
    bullet.mWorld.removeRigidBody(&car);
    bullet.mWorld.removeCollisionObject(&plane);
}

TEST_CASE("Bullet: two worlds with their own adapters stay independent, and one world takes one adapter", "[bullet]")
{
    EngineCrashSettings head_on;
    EngineCrashSettings driving = head_on;
    driving.mDriveOnly = true;
    BulletWallCrash first(head_on);
    BulletWallCrash second(driving);
    for (int i = 0; i < 60; ++i)
    {
        first.Step();
        second.Step();
    }
    first.GetDamage().Flush();
    second.GetDamage().Flush();
    CHECK(first.GetCounter().mCollisions >= 1);
    CHECK(second.GetCounter().mCollisions == 0);
    CHECK(bullet::BulletAdapter::Create(first.GetWorld(), first.GetDamage()).HasError());
}

TEST_CASE("Bullet: a following hull takes the dented shape", "[bullet]")
{
    EngineCrashSettings settings;
    BulletWallCrash crash(settings);
    Result<btConvexHullShape*> hull = crash.GetAdapter().CreateFollowingHull(crash.GetCarObject(), 200);
    REQUIRE(hull);
    btVector3 min_before, max_before;
    hull.Get()->getAabb(btTransform::getIdentity(), min_before, max_before);
    crash.Run();
    btVector3 min_after, max_after;
    hull.Get()->getAabb(btTransform::getIdentity(), min_after, max_after);
    // The front of the hull moved back with the dent.
    CHECK(static_cast<double>(max_after.x()) < static_cast<double>(max_before.x()) - 0.05);
    CHECK(crash.GetAdapter().CreateFollowingHull(ObjectId{99}).HasError());
}

TEST_CASE("Bullet: a following hull inside a compound moves the compound's bounds, and follows a reset and a loaded state",
          "[bullet]")
{
    // The car's shape is a compound (a game's chassis): the hull and a small sphere at the centre. Declared
    // before the crash, so it outlives the car that uses it.
    btCompoundShape compound;
    btSphereShape centre(0.1f);
    EngineCrashSettings settings;
    BulletWallCrash crash(settings);
    btConvexHullShape* hull = crash.GetAdapter().CreateFollowingHull(crash.GetCarObject(), 200).Get();
    compound.addChildShape(btTransform::getIdentity(), hull);
    compound.addChildShape(btTransform::getIdentity(), &centre);
    crash.GetCar().setCollisionShape(&compound);
    // The pairs cached for the box the car had would run the box's collision algorithm on the compound.
    crash.GetWorld().getBroadphase()->getOverlappingPairCache()->cleanProxyFromPairs(crash.GetCar().getBroadphaseHandle(),
                                                                                     crash.GetWorld().getDispatcher());
    const auto front = [&](const btCollisionShape& inShape) {
        btVector3 low, high;
        inShape.getAabb(btTransform::getIdentity(), low, high);
        return static_cast<double>(high.x());
    };
    const double rest_front = front(*hull);
    REQUIRE(front(compound) == rest_front);

    crash.Run();
    const double dented_front = front(*hull);
    REQUIRE(dented_front < rest_front - 0.05); // the hull followed the dent
    // The compound's cached bounds followed it (they kept the undented front before)
    CHECK(front(compound) == dented_front);
    const std::vector<std::byte> saved = crash.GetDamage().SaveDamage();

    // Away from the wall and at rest, so that no new contact dents the car again.
    btRigidBody& car = crash.GetCar();
    btTransform away = car.getWorldTransform();
    away.setOrigin(away.getOrigin() - btVector3(20, 0, 0));
    car.setWorldTransform(away);
    if (car.getMotionState() != nullptr)
        car.getMotionState()->setWorldTransform(away);
    car.setLinearVelocity(btVector3(0, 0, 0));
    car.setAngularVelocity(btVector3(0, 0, 0));

    // A reset reaches the hull and the compound at the next step, and so does a loaded state.
    crash.GetDamage().ResetDamage();
    crash.Step();
    CHECK(front(*hull) == rest_front);
    CHECK(front(compound) == rest_front);
    REQUIRE(crash.GetDamage().LoadDamage(saved));
    crash.Step();
    CHECK(front(*hull) == dented_front);
    CHECK(front(compound) == dented_front);
}

TEST_CASE("Bullet: the same crash twice gives bitwise identical meshes", "[bullet][determinism]")
{
    EngineCrashSettings settings;
    settings.mYawDegrees = 30.0;
    const EngineCrashResult first = BulletWallCrash(settings).Run();
    const EngineCrashResult second = BulletWallCrash(settings).Run();
    // intent: a crash that dents (0.60 m at 30 degrees), so equal meshes are not two rest meshes
    REQUIRE(first.mMaxDent > 0.2);
    REQUIRE_FALSE(first.mDamage.empty());
    CHECK(first.mPositions == second.mPositions);
    CHECK(first.mDamage == second.mDamage);
}

TEST_CASE("Bullet: a recorded crash replays headless to bitwise identical meshes", "[bullet][replay]")
{
    const std::filesystem::path path = ScratchDirectory() / "bullet-crash.crumple";
    EngineCrashSettings settings;
    settings.mYawDegrees = 30.0;
    BulletWallCrash crash(settings);
    std::unique_ptr<DamageRecorder> recorder = std::move(DamageRecorder::Create(path, crash.GetDamage()).Get());
    const EngineCrashResult live = crash.Run();
    REQUIRE(recorder->Close());
    REQUIRE(recorder->GetCollisionCount() >= 1);
    Result<Replay> replay = DecodeReplay(ReadFileBytes(path).Get());
    REQUIRE(replay);
    Result<std::vector<ReplayedObject>> objects = ReplayDamage(replay.Get());
    REQUIRE(objects);
    REQUIRE(objects.Get().size() == 1);
    CHECK(objects.Get()[0].mDeformable.GetDeformer().GetPositions() == live.mPositions);
}

TEST_CASE("Bullet: a btRaycastVehicle driving on flat ground gets no damage", "[bullet]")
{
    BulletWorld bullet;
    std::unique_ptr<DamageWorld> damage_owner = std::move(DamageWorld::Create().Get());
    DamageWorld& damage = *damage_owner;
    std::unique_ptr<bullet::BulletAdapter> adapter = std::move(bullet::BulletAdapter::Create(bullet.mWorld, damage).Get());
    btStaticPlaneShape ground_shape(btVector3(0, 0, 1), 0);
    btRigidBody ground(btRigidBody::btRigidBodyConstructionInfo(0, nullptr, &ground_shape)); // raycast wheels need a rigid body
    bullet.mWorld.addRigidBody(&ground);
    REQUIRE(adapter->AddBody(ground));

    btBoxShape chassis_shape(btVector3(2.1f, 0.9f, 0.5f));
    btVector3 inertia;
    chassis_shape.calculateLocalInertia(1200, inertia);
    btRigidBody::btRigidBodyConstructionInfo info(1200, nullptr, &chassis_shape, inertia);
    info.m_startWorldTransform.setOrigin(btVector3(0, 0, 0.95f));
    btRigidBody chassis(info);
    chassis.setActivationState(DISABLE_DEACTIVATION);
    bullet.mWorld.addRigidBody(&chassis);
    btDefaultVehicleRaycaster raycaster(&bullet.mWorld);
    btRaycastVehicle::btVehicleTuning tuning;
    btRaycastVehicle vehicle(tuning, &chassis, &raycaster);
    vehicle.setCoordinateSystem(1, 2, 0);
    bullet.mWorld.addAction(&vehicle);
    for (int i = 0; i < 4; ++i)
    {
        btWheelInfo& wheel = vehicle.addWheel(btVector3(i < 2 ? 1.5f : -1.5f, i % 2 == 0 ? 0.8f : -0.8f, -0.2f), btVector3(0, 0, -1),
                                              btVector3(0, -1, 0), 0.35f, 0.35f, tuning, i < 2);
        wheel.m_suspensionStiffness = 30.0f;
        wheel.m_wheelsDampingRelaxation = 4.0f;
        wheel.m_wheelsDampingCompression = 3.0f;
        wheel.m_maxSuspensionForce = 60000.0f;
    }
    const BodyId car = adapter->AddBody(chassis).Get();
    DeformableObjectSettings body;
    body.mMesh = MakeBoxMesh(Vec3(2.1, 0.9, 0.5), {20, 8, 6});
    const ObjectId object = damage.CreateDeformableObject(car, body).Get();

    for (int step = 0; step < 180; ++step)
    {
        vehicle.applyEngineForce(4000, 2);
        vehicle.applyEngineForce(4000, 3);
        bullet.mWorld.stepSimulation(btScalar(1.0 / 60.0), 4, btScalar(1.0 / 240.0));
    }
    damage.Flush();
    CHECK(static_cast<double>(chassis.getLinearVelocity().x()) > 5.0); // it did drive
    CHECK(damage.GetObject(object)->GetDeformer().GetVertexEvaluationCount() == 0);
    bullet.mWorld.removeAction(&vehicle);
    bullet.mWorld.removeRigidBody(&chassis);
    bullet.mWorld.removeRigidBody(&ground);
}

TEST_CASE("Bullet: a convex body the adapter makes has the settings' mass, inertia, pose and velocities, and goes with RemoveBody",
          "[bullet]")
{
    BulletWorld world;
    world.mWorld.setGravity(btVector3(0, 0, 0));
    std::unique_ptr<DamageWorld> damage_owner = std::move(DamageWorld::Create().Get());
    DamageWorld& damage = *damage_owner;
    std::unique_ptr<bullet::BulletAdapter> adapter = std::move(bullet::BulletAdapter::Create(world.mWorld, damage).Get());

    // A 0.6 x 0.1 x 0.2 m, 12 kg block turned about an oblique axis, moving and spinning.
    const ConvexBodySettings settings = TurnedBlock();
    const int objects = world.mWorld.getNumCollisionObjects();
    const BodyId id = adapter->CreateConvexBody(settings).Get();
    btRigidBody* body = adapter->GetConvexBody(id);
    REQUIRE(body != nullptr);
    CHECK(adapter->FindBody(*body) == id);
    CHECK(world.mWorld.getNumCollisionObjects() == objects + 1);

    // Bullet keeps single precision here: compare to float round-off.
    constexpr double cFloat = 1.0e-5;
    CHECK(std::abs(1.0 / body->getInvMass() - settings.mMass) <= cFloat * settings.mMass);
    const btMatrix3x3& inverse = body->getInvInertiaTensorWorld();
    const Mat3 expected = settings.WorldInertia().inverse();
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            CHECK(std::abs(double(inverse[i][j]) - expected(i, j)) <= cFloat * expected.norm());
    const btVector3 position = body->getCenterOfMassPosition();
    CHECK((Vec3(position.x(), position.y(), position.z()) - settings.mPosition).norm() <= cFloat);
    const btVector3 v = body->getLinearVelocity(), w = body->getAngularVelocity();
    CHECK((Vec3(v.x(), v.y(), v.z()) - settings.mLinearVelocity).norm() <= cFloat * settings.mLinearVelocity.norm());
    CHECK((Vec3(w.x(), w.y(), w.z()) - settings.mAngularVelocity).norm() <= cFloat * settings.mAngularVelocity.norm());
    // The damage world knows it with the same mass.
    REQUIRE(damage.GetBodyState(id) != nullptr);
    CHECK(std::abs(damage.GetBodyState(id)->mMass - settings.mMass) <= cFloat * settings.mMass);

    // Free flight: its momentum stays.
    for (int step = 0; step < 30; ++step)
        world.mWorld.stepSimulation(btScalar(1.0 / 60.0), 1, btScalar(1.0 / 60.0));
    const btVector3 after = body->getLinearVelocity();
    CHECK((Vec3(after.x(), after.y(), after.z()) - settings.mLinearVelocity).norm() <= cFloat * settings.mLinearVelocity.norm());

    // Bad settings are refused and add nothing; RemoveBody takes the body out of both worlds.
    ConvexBodySettings flat = settings;
    for (Vec3& point : flat.mHullPoints)
        point.z() = 0.0;
    CHECK_FALSE(adapter->CreateConvexBody(flat));
    CHECK(world.mWorld.getNumCollisionObjects() == objects + 1);
    REQUIRE(adapter->RemoveBody(*body));
    CHECK(adapter->GetConvexBody(id) == nullptr);
    CHECK(damage.GetBodyState(id) == nullptr);
    CHECK(world.mWorld.getNumCollisionObjects() == objects);
    // One left for the adapter's destructor to take out of the world.
    REQUIRE(adapter->CreateConvexBody(settings));
    adapter.reset();
    CHECK(world.mWorld.getNumCollisionObjects() == objects);
}

TEST_CASE("Bullet: a held prop body stays at its pose without gravity, and its pieces can be replaced", "[bullet][props]")
{
    BulletWorld world;
    world.mWorld.setGravity(btVector3(0, 0, btScalar(-9.81)));
    std::unique_ptr<DamageWorld> damage_owner = std::move(DamageWorld::Create().Get());
    DamageWorld& damage = *damage_owner;
    std::unique_ptr<bullet::BulletAdapter> adapter = std::move(bullet::BulletAdapter::Create(world.mWorld, damage).Get());
    const int objects = world.mWorld.getNumCollisionObjects();

    const PropBodySettings settings = TurnedSlab();
    const BodyId id = adapter->CreatePropBody(settings).Get();
    btRigidBody* body = adapter->GetConvexBody(id);
    REQUIRE(body != nullptr);
    auto* compound = static_cast<btCompoundShape*>(body->getCollisionShape());
    CHECK(compound->getNumChildShapes() == 2);
    constexpr double cFloat = 1.0e-5;
    CHECK(std::abs(1.0 / body->getInvMass() - settings.mMass) <= cFloat * settings.mMass);

    // Pushed and under gravity, it is back at its pose, at rest, after every step.
    for (int step = 0; step < 20; ++step)
    {
        body->activate(true);
        body->setLinearVelocity(btVector3(3, -1, 2));
        body->setAngularVelocity(btVector3(0, 4, 0));
        world.mWorld.stepSimulation(btScalar(1.0 / 60.0), 1, btScalar(1.0 / 60.0));
        const btVector3 position = body->getCenterOfMassPosition();
        CHECK((Vec3(position.x(), position.y(), position.z()) - settings.mPosition).norm() <= cFloat);
        CHECK(body->getLinearVelocity().length() == 0.0f);
        CHECK(body->getAngularVelocity().length() == 0.0f);
    }

    // Given the velocity of the material a car struck, it is back at its pose moving so; refused, changing
    // nothing, for a body that is not held or a velocity that is not finite.
    const Vec3 struck(4.0, 0.5, 0.0);
    REQUIRE(adapter->SetHeldVelocity(id, struck));
    for (int step = 0; step < 3; ++step)
    {
        world.mWorld.stepSimulation(btScalar(1.0 / 60.0), 1, btScalar(1.0 / 60.0));
        const btVector3 position = body->getCenterOfMassPosition();
        CHECK((Vec3(position.x(), position.y(), position.z()) - settings.mPosition).norm() <= cFloat);
        const btVector3 v = body->getLinearVelocity();
        CHECK((Vec3(v.x(), v.y(), v.z()) - struck).norm() <= cFloat);
        CHECK(body->getAngularVelocity().length() == 0.0f);
    }
    CHECK(adapter->SetHeldVelocity(id, Vec3(std::nan(""), 0.0, 0.0)).GetError().mCode == EError::NonFinite);
    CHECK(adapter->SetHeldVelocity(id, Vec3(2.0e6, 0.0, 0.0)).GetError().mCode == EError::OutOfRange);
    CHECK(adapter->SetHeldVelocity(BodyId{}, struck).GetError().mCode == EError::OutOfRange);
    REQUIRE(adapter->SetHeldVelocity(id, Vec3::Zero()));
    world.mWorld.stepSimulation(btScalar(1.0 / 60.0), 1, btScalar(1.0 / 60.0));
    CHECK(body->getLinearVelocity().length() == 0.0f);

    // New pieces replace the shape; bad ones, and bodies that are not prop bodies, are refused.
    PropBodySettings one = settings;
    one.mPieces.pop_back();
    REQUIRE(adapter->SetPropPieces(id, one.mPieces));
    compound = static_cast<btCompoundShape*>(body->getCollisionShape());
    CHECK(compound->getNumChildShapes() == 1);
    CHECK(world.mWorld.getNumCollisionObjects() == objects + 1);
    CHECK(adapter->SetPropPieces(id, {}).HasError());
    std::vector<std::vector<Vec3>> flat = one.mPieces;
    for (Vec3& point : flat[0])
        point.z() = 0.0;
    CHECK(adapter->SetPropPieces(id, flat).HasError());
    CHECK(static_cast<btCompoundShape*>(body->getCollisionShape())->getNumChildShapes() == 1);
    const BodyId debris = adapter->CreateConvexBody(TurnedBlock()).Get();
    CHECK(adapter->SetPropPieces(debris, one.mPieces).GetError().mCode == EError::OutOfRange);
    PropBodySettings massless = settings;
    massless.mMass = 0.0;
    CHECK(adapter->CreatePropBody(massless).HasError());
    CHECK(world.mWorld.getNumCollisionObjects() == objects + 2);

    // A free prop body falls.
    const BodyId free = adapter->CreatePropBody(TurnedSlab(false)).Get();
    CHECK(adapter->IsHeldPropBody(id)); // what props::HeldPropEngine::mIsHeld asks
    CHECK_FALSE(adapter->IsHeldPropBody(free));
    CHECK_FALSE(adapter->IsHeldPropBody(BodyId{}));
    for (int step = 0; step < 10; ++step)
        world.mWorld.stepSimulation(btScalar(1.0 / 60.0), 1, btScalar(1.0 / 60.0));
    CHECK(adapter->GetConvexBody(free)->getLinearVelocity().z() < -1.0f);
    adapter.reset();
    CHECK(world.mWorld.getNumCollisionObjects() == objects);
}

namespace
{

// A ball touching a held wall (1 mm in) at height inY: the impulse it takes in one step of 1/120 s, and the
// mass the damage world saw the wall with. inContactMass: SetHeldMass's argument (0: none given).
double BallImpulseInOneStep(double inY, double inContactMass, double& outWallMassSeen)
{
    BulletWorld world;
    world.mWorld.setGravity(btVector3(0, 0, 0));
    std::unique_ptr<DamageWorld> damage = std::move(DamageWorld::Create().Get());
    std::unique_ptr<bullet::BulletAdapter> adapter =
        std::move(bullet::BulletAdapter::Create(world.mWorld, *damage).Get());
    const BodyId wall = adapter->CreatePropBody(HeldWall()).Get();
    ConvexBodySettings ball_settings = WallBall(inY);
    ball_settings.mPosition.x() = -0.05 - 0.1 + 0.001;
    const BodyId ball = adapter->CreateConvexBody(ball_settings).Get();
    if (inContactMass > 0.0)
        REQUIRE(adapter->SetHeldMass(wall, inContactMass));
    world.mWorld.stepSimulation(btScalar(1.0 / 120.0), 1, btScalar(1.0 / 120.0));
    outWallMassSeen = damage->GetBodyState(wall)->mMass;
    return WallBallImpulse(static_cast<double>(adapter->GetConvexBody(ball)->getLinearVelocity().x()));
}

} // namespace

TEST_CASE("Bullet: a held prop body given a contact mass meets a blow anywhere as a point mass of it",
          "[bullet][props]")
{
    constexpr double cContactMass = 10.0; // kg
    double seen = 0.0;
    // As made (50 kg, turning), a blow 1.5 m from the centre meets 1 / (1/m + r^2 / I_z) = 18.6 kg; impulses
    // go as the reduced masses (the engine's push out of the 1 mm adds the same to every approach).
    const double own_inertia_z = HeldWall().mPrincipalInertia.z();
    const double off_centre_mass = 1.0 / (1.0 / 50.0 + 1.5 * 1.5 / own_inertia_z);
    const double own_centre = BallImpulseInOneStep(0.0, 0.0, seen);
    CHECK(seen == Approx(50.0).epsilon(1e-6));
    const double own_off_centre = BallImpulseInOneStep(1.5, 0.0, seen);
    CHECK(own_off_centre / own_centre ==
          Approx(WallBallReducedMass(off_centre_mass) / WallBallReducedMass(50.0)).epsilon(0.01));
    // Given 10 kg: the same 10 kg at the centre and off it, in the engine and in the damage world.
    const double given_centre = BallImpulseInOneStep(0.0, cContactMass, seen);
    CHECK(seen == Approx(cContactMass).epsilon(1e-6));
    const double given_off_centre = BallImpulseInOneStep(1.5, cContactMass, seen);
    CHECK(seen == Approx(cContactMass).epsilon(1e-6));
    CHECK(given_centre / own_centre ==
          Approx(WallBallReducedMass(cContactMass) / WallBallReducedMass(50.0)).epsilon(0.01));
    CHECK(given_off_centre == Approx(given_centre).epsilon(1e-3));

    // 0 gives the body its own mass and inertia back; bad masses and bodies that are not held are refused,
    // changing nothing.
    BulletWorld world;
    std::unique_ptr<DamageWorld> damage = std::move(DamageWorld::Create().Get());
    std::unique_ptr<bullet::BulletAdapter> adapter =
        std::move(bullet::BulletAdapter::Create(world.mWorld, *damage).Get());
    const BodyId wall = adapter->CreatePropBody(HeldWall()).Get();
    btRigidBody& body = *adapter->GetConvexBody(wall);
    const btVector3 own_inverse_inertia = body.getInvInertiaDiagLocal();
    REQUIRE(adapter->SetHeldMass(wall, cContactMass));
    CHECK(body.getInvMass() == Approx(1.0 / cContactMass).epsilon(1e-6));
    CHECK(body.getInvInertiaDiagLocal().length() == 0.0f);
    CHECK(body.getGravity().length() == 0.0f);
    CHECK(adapter->SetHeldMass(wall, -1.0).GetError().mCode == EError::OutOfRange);
    CHECK(adapter->SetHeldMass(wall, 2.0e12).GetError().mCode == EError::OutOfRange);
    CHECK(adapter->SetHeldMass(wall, std::nan("")).GetError().mCode == EError::NonFinite);
    const BodyId free_body = adapter->CreateConvexBody(WallBall(0.0)).Get();
    CHECK(adapter->SetHeldMass(free_body, 1.0).GetError().mCode == EError::OutOfRange);
    CHECK(adapter->SetHeldMass(BodyId{}, 1.0).GetError().mCode == EError::OutOfRange);
    CHECK(body.getInvMass() == Approx(1.0 / cContactMass).epsilon(1e-6));
    REQUIRE(adapter->SetHeldMass(wall, 0.0));
    CHECK(body.getInvMass() == Approx(1.0 / 50.0).epsilon(1e-6));
    CHECK(body.getInvInertiaDiagLocal() == own_inverse_inertia);
}

TEST_CASE("Bullet: a body state carries its collision shape's bounds, a plane's out to the state's range", "[bullet]")
{
    // A 2 x 4 x 6 m box turned about z: its bounds are in its own frame, not the world's.
    btBoxShape box(btVector3(1, 2, 3));
    btRigidBody::btRigidBodyConstructionInfo info(10, nullptr, &box, btVector3(1, 1, 1));
    info.m_startWorldTransform = btTransform(btQuaternion(btVector3(0, 0, 1), btScalar(0.7)), btVector3(5, -3, 2));
    btRigidBody body(info);
    const BodyState state = bullet::BulletBodyState(body);
    REQUIRE(state.mHasShapeBounds);
    CHECK(state.mShapeMin.isApprox(Vec3(-1, -2, -3), 1.0e-6));
    CHECK(state.mShapeMax.isApprox(Vec3(1, 2, 3), 1.0e-6));
    CHECK(ValidateBodyState(state));

    btStaticPlaneShape plane(btVector3(0, 0, 1), 0);
    btCollisionObject ground;
    ground.setCollisionShape(&plane);
    const BodyState ground_state = bullet::BulletBodyState(ground);
    REQUIRE(ground_state.mHasShapeBounds);
    CHECK(ground_state.mShapeMax.x() == cMaxBodyPosition);
    CHECK(ground_state.mShapeMin.y() == -cMaxBodyPosition);
    CHECK(ValidateBodyState(ground_state));
}

TEST_CASE(
    "Bullet: a kinematic body made the usual Bullet way (mass 0, CF_KINEMATIC_OBJECT) is kinematic, with "
    "its velocity, and its hit dents",
    "[bullet]")
{
    // A 1 x 4 x 4 m ram moved by the game through its motion state at 10 m/s into a parked 1,500 kg box car:
    // btRigidBody marks a zero-mass body CF_STATIC_OBJECT, and the game adds CF_KINEMATIC_OBJECT to it.
    BulletWorld bullet;
    bullet.mWorld.setGravity(btVector3(0, 0, 0));
    std::unique_ptr<DamageWorld> damage_owner = std::move(DamageWorld::Create().Get());
    DamageWorld& damage = *damage_owner;
    std::unique_ptr<bullet::BulletAdapter> adapter =
        std::move(bullet::BulletAdapter::Create(bullet.mWorld, damage).Get());
    const Vec3 half(2.0, 0.9, 0.7);
    btBoxShape car_shape(btVector3(btScalar(half.x()), btScalar(half.y()), btScalar(half.z())));
    btVector3 inertia;
    car_shape.calculateLocalInertia(1500, inertia);
    btDefaultMotionState car_motion(btTransform(btQuaternion::getIdentity(), btVector3(0, 0, 2)));
    btRigidBody car(btRigidBody::btRigidBodyConstructionInfo(1500, &car_motion, &car_shape, inertia));
    btBoxShape ram_shape(btVector3(0.5, 2, 2));
    btDefaultMotionState ram_motion(btTransform(btQuaternion::getIdentity(), btVector3(2.6f, 0, 2)));
    btRigidBody ram(btRigidBody::btRigidBodyConstructionInfo(0, &ram_motion, &ram_shape));
    ram.setCollisionFlags(ram.getCollisionFlags() | btCollisionObject::CF_KINEMATIC_OBJECT);
    ram.setActivationState(DISABLE_DEACTIVATION);
    REQUIRE(ram.isStaticObject()); // what Bullet leaves on it: the case
    bullet.mWorld.addRigidBody(&car);
    bullet.mWorld.addRigidBody(&ram);
    const BodyId car_body = adapter->AddBody(car).Get();
    const BodyId ram_body = adapter->AddBody(ram).Get();
    REQUIRE(damage.GetBodyState(ram_body)->mMotionType == EMotionType::Kinematic);
    DeformableObjectSettings body;
    body.mMesh = common::MakeBoxMesh(half, {16, 8, 6});
    const Result<ObjectId> car_object = damage.CreateDeformableObject(car_body, body);
    REQUIRE(car_object);
    CrashCounter counter;
    damage.AddListener(&counter);
    const double speed = 10.0, step = 1.0 / 60.0;
    bool moving_seen = false;
    for (int i = 0; i < 20; ++i)
    {
        btTransform pose;
        ram_motion.getWorldTransform(pose);
        pose.setOrigin(pose.getOrigin() - btVector3(btScalar(speed * step), 0, 0));
        ram_motion.setWorldTransform(pose);
        bullet.mWorld.stepSimulation(btScalar(step), 1, btScalar(step));
        // intent: the state Crumple holds for the ram is the velocity Bullet gave it from its motion
        moving_seen = moving_seen || damage.GetBodyState(ram_body)->mLinearVelocity.x() < -0.99 * speed;
    }
    damage.Flush();
    CHECK(moving_seen);
    REQUIRE(counter.mCollisions >= 1);
    // The car at rest takes the ram's (1 + e) m v along -x, as from a body of infinite mass.
    double impulse = 0.0;
    for (const Collision& collision : counter.mLog)
        impulse += collision.TotalImpulse();
    CHECK(impulse == Approx((1.0 + damage.GetSettings().mRestitution) * 1500.0 * speed).epsilon(1.0e-3));
    const std::vector<Vec3>& positions = damage.GetObject(car_object.Get())->GetDeformer().GetPositions();
    double front = -1e9;
    for (const Vec3& p : positions)
        front = std::max(front, p.x());
    CHECK(front < half.x() - 0.02); // the struck front crushed back
    damage.RemoveListener(&counter);
    bullet.mWorld.removeRigidBody(&ram);
    bullet.mWorld.removeRigidBody(&car);
}

TEST_CASE("Bullet: a body the game removes from the damage world itself leaves the other bodies' damage on",
          "[bullet]")
{
    // A crate on the ground and a car driving into a wall at 10 m/s; the game removes the crate's damage body
    // (DamageWorld::RemoveBody, not the adapter's): the crate's contacts named a dead body, and the world
    // refused each step's whole batch, the car's with it.
    BulletWorld bullet;
    std::unique_ptr<DamageWorld> damage_owner = std::move(DamageWorld::Create().Get());
    DamageWorld& damage = *damage_owner;
    std::unique_ptr<bullet::BulletAdapter> adapter =
        std::move(bullet::BulletAdapter::Create(bullet.mWorld, damage).Get());
    btBoxShape ground_shape(btVector3(50, 50, 1)), crate_shape(btVector3(0.3f, 0.3f, 0.3f)),
        car_shape(btVector3(2, 0.9f, 0.7f)), wall_shape(btVector3(1, 5, 5));
    const auto make = [&](btCollisionShape& inShape, double inMass, const btVector3& inAt)
    {
        btVector3 inertia(0, 0, 0);
        if (inMass > 0.0)
            inShape.calculateLocalInertia(btScalar(inMass), inertia);
        btRigidBody::btRigidBodyConstructionInfo info(btScalar(inMass), nullptr, &inShape, inertia);
        info.m_startWorldTransform = btTransform(btQuaternion::getIdentity(), inAt);
        auto body = std::make_unique<btRigidBody>(info);
        bullet.mWorld.addRigidBody(body.get());
        return body;
    };
    const std::unique_ptr<btRigidBody> ground = make(ground_shape, 0.0, btVector3(0, 0, -1));
    const std::unique_ptr<btRigidBody> crate = make(crate_shape, 20.0, btVector3(-10, 0, 0.3f));
    const std::unique_ptr<btRigidBody> car = make(car_shape, 1500.0, btVector3(0, 0, 0.7f));
    const std::unique_ptr<btRigidBody> wall = make(wall_shape, 0.0, btVector3(6, 0, 2));
    car->setLinearVelocity(btVector3(10, 0, 0));
    REQUIRE(adapter->AddBody(*ground));
    const BodyId crate_body = adapter->AddBody(*crate).Get();
    const BodyId car_body = adapter->AddBody(*car).Get();
    REQUIRE(adapter->AddBody(*wall));
    DeformableObjectSettings body;
    body.mMesh = common::MakeBoxMesh(Vec3(2.0, 0.9, 0.7), {16, 8, 6});
    REQUIRE(damage.CreateDeformableObject(car_body, body));
    CrashCounter counter;
    damage.AddListener(&counter);
    for (int i = 0; i < 3; ++i)
        bullet.mWorld.stepSimulation(btScalar(1.0 / 60.0), 1, btScalar(1.0 / 60.0));
    REQUIRE(damage.RemoveBody(crate_body));
    int refused = 0;
    for (int i = 0; i < 60; ++i)
    {
        bullet.mWorld.stepSimulation(btScalar(1.0 / 60.0), 1, btScalar(1.0 / 60.0));
        refused += adapter->GetLastStepStats().mContactsRefused;
    }
    damage.Flush();
    CHECK(refused == 0);
    REQUIRE(counter.mCollisions >= 1);
    bool car_hit_wall = false;
    for (const Collision& collision : counter.mLog)
        car_hit_wall = car_hit_wall || ((collision.mBodyA == car_body || collision.mBodyB == car_body) &&
                                        collision.TotalImpulse() > 0.5 * 1500.0 * 10.0);
    CHECK(car_hit_wall);
    CHECK(adapter->FindBody(*crate) == crate_body); // still registered with the adapter
    damage.RemoveListener(&counter);
    for (btRigidBody* b : {wall.get(), car.get(), crate.get(), ground.get()})
        bullet.mWorld.removeRigidBody(b);
}
