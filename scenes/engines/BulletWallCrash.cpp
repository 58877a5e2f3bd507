// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "BulletWallCrash.h"

#include <cmath>
#include <numbers>
#include <string>

namespace crumple::common
{

using namespace crumple::plugin;

BulletWallCrash::BulletWallCrash(const EngineCrashSettings& inSettings)
    : mSettings(inSettings), mDamageOwner(std::move(DamageWorld::Create(inSettings.mWorld).Get())), mDamage(*mDamageOwner)
{
    mConfiguration = std::make_unique<btDefaultCollisionConfiguration>();
    mDispatcher = std::make_unique<btCollisionDispatcher>(mConfiguration.get());
    mBroadphase = std::make_unique<btDbvtBroadphase>();
    mSolver = std::make_unique<ImpactSplitSolver>();
    mWorld = std::make_unique<btDiscreteDynamicsWorld>(mDispatcher.get(), mBroadphase.get(), mSolver.get(), mConfiguration.get());
    // Bullet pushes a body out of a penetration shallower than 4 cm (its default) by adding velocity
    // (Baumgarte), which rebounds a 20 km/h car at twice the restitution. Split impulses correct position
    // without velocity; resting contacts with the ground (under 5 mm) keep Baumgarte, which holds a parked
    // car still; every other contact splits however shallow (ImpactSplitSolver).
    mWorld->getSolverInfo().m_splitImpulse = 1;
    mWorld->getSolverInfo().m_splitImpulsePenetrationThreshold = btScalar(-0.005);
    // Bullet's solver limits friction along one tangent per contact by default (the slip's direction when the
    // point appeared): a corner that then slides across it meets no friction, and from a 20 km/h car glancing
    // off a wall turned 60 degrees the engine took 12 % less momentum than Crumple's Coulomb impulse says
    // (crumple-crash's impulse_momentum check failed). Two fixed tangents
    // perpendicular to the normal, each bounded by mu times the normal impulse, are the friction pyramid of
    // ODE's contacts in the ODE scene (dContactApprox1, no dContactFDir1), so both engines solve one model.
    mWorld->getSolverInfo().m_solverMode |=
        SOLVER_USE_2_FRICTION_DIRECTIONS | SOLVER_DISABLE_VELOCITY_DEPENDENT_FRICTION_DIRECTION;
    mWorld->setGravity(btVector3(0, 0, btScalar(inSettings.mFloating ? 0.0 : -cCrashGravity)));
    if (inSettings.mAttach)
    {
        bullet::BulletAdapterSettings adapter;
        adapter.mMeasureCpuTime = inSettings.mMeasureAdapterTime;
        mAdapter = std::move(bullet::BulletAdapter::Create(*mWorld, mDamage, adapter).Get());
    }

    // Bullet bounces a pair by the product of the two bodies' restitutions: sqrt(e) on every body of the
    // crash makes each pair rebound as Crumple's impulses assume (DamageWorldSettings::mRestitution), so the
    // engine's change of the car's momentum is the impulse Crumple dents with.
    const auto restitution = btScalar(std::sqrt(inSettings.mWorld.mRestitution));
    // Friction combines the same way: sqrt(mFriction) per body gives every pair the coefficient ODE's
    // contacts take directly.
    const auto friction = btScalar(std::sqrt(inSettings.mFriction));
    // Ground z = 0 and, unless only driving, a wall whose face is the plane x = 0.
    auto add_static = [&](std::unique_ptr<btCollisionShape> inShape, const btVector3& inOrigin,
                          btScalar inFriction) {
        auto object = std::make_unique<btCollisionObject>();
        object->setCollisionShape(inShape.get());
        object->setWorldTransform(btTransform(btQuaternion::getIdentity(), inOrigin));
        object->setFriction(inFriction);
        object->setRestitution(restitution);
        mWorld->addCollisionObject(object.get());
        if (mAdapter != nullptr)
            mWallBody = mAdapter->AddBody(*object).Get(); // the last one added is the target
        mShapes.push_back(std::move(inShape));
        mObjects.push_back(std::move(object));
    };
    // The ground is a box, not a btStaticPlaneShape: against a plane Bullet keeps one or two points of a box
    // that slides 15 cm a step (the manifold's points go stale), and the car rocks from corner to corner and
    // sinks (3.2 cm and 0.105 rad/s over 0.6 s at 64 km/h); the box-box detector gives the whole face each
    // step. 400 m square, its top at z = 0.
    if (!inSettings.mFloating)
    {
        add_static(std::make_unique<btBoxShape>(btVector3(200, 200, 1)), btVector3(0, 0, -1),
                   friction > 0 ? btScalar(inSettings.mGroundFriction) / friction : btScalar(0));
        mSolver->SetGround(mObjects.back().get());
        // intent: the ground is quiet, as the props' loose pieces are: pieces on it make no collisions
        // (DamageWorld::SetQuiet); the cars' contacts with it are solved as before
        if (mAdapter != nullptr)
            (void)mDamage.SetQuiet(mWallBody, true); // the ground's body, just added
    }
    if (inSettings.mTargetVehicle)
    {
        // A second car, a dynamic box on the ground.
        const TargetVehicleSettings& target = *inSettings.mTargetVehicle;
        const Vec3& th = target.mHalfExtents;
        auto target_shape = std::make_unique<btBoxShape>(btVector3(btScalar(th.x()), btScalar(th.y()), btScalar(th.z())));
        btVector3 target_inertia;
        target_shape->calculateLocalInertia(btScalar(target.mMass), target_inertia);
        const Transform place = TargetVehicleStart(target);
        const double target_yaw = target.mYawDegrees * std::numbers::pi / 180.0;
        btRigidBody::btRigidBodyConstructionInfo target_info(btScalar(target.mMass), nullptr, target_shape.get(), target_inertia);
        target_info.m_startWorldTransform = btTransform(btQuaternion(btVector3(0, 0, 1), btScalar(target_yaw)),
                                                        btVector3(btScalar(place.mTranslation.x()), btScalar(place.mTranslation.y()),
                                                                  btScalar(place.mTranslation.z())));
        target_info.m_friction = friction;
        target_info.m_restitution = restitution;
        auto target_body = std::make_unique<btRigidBody>(target_info);
        target_body->setLinearVelocity(btVector3(btScalar(target.mSpeed * std::cos(target_yaw)),
                                                 btScalar(target.mSpeed * std::sin(target_yaw)), 0));
        target_body->setActivationState(DISABLE_DEACTIVATION);
        mWorld->addRigidBody(target_body.get());
        mTarget = target_body.get();
        mShapes.push_back(std::move(target_shape));
        mObjects.push_back(std::move(target_body));
    }
    else if (!inSettings.mDriveOnly && !inSettings.mFloating && inSettings.mPoleRadius > 0.0)
    {
        // A 24-sided prism with polyhedral features rather than btCylinderShapeZ: Bullet meets a box and a
        // cylinder at one point per step (GJK/EPA), alternately on the box's top and bottom edge, which pitches
        // the car and crushes its roof edge; polyhedral contact clipping reports the line contact (ODE's
        // box-cylinder collider reports it too).
        auto pole = std::make_unique<btConvexHullShape>();
        constexpr int cSides = 24;
        for (int i = 0; i < cSides; ++i)
        {
            const double angle = 2.0 * std::numbers::pi * i / cSides;
            const btScalar x = btScalar(inSettings.mPoleRadius * std::cos(angle));
            const btScalar y = btScalar(inSettings.mPoleRadius * std::sin(angle));
            pole->addPoint(btVector3(x, y, -3), false);
            pole->addPoint(btVector3(x, y, 3), i + 1 == cSides);
        }
        pole->setMargin(0);
        pole->initializePolyhedralFeatures();
        mWorld->getDispatchInfo().m_enableSatConvex = true; // separating axis, then clip the two hulls' faces
        add_static(std::move(pole), btVector3(0, 0, 3), friction);
    }
    else if (!inSettings.mDriveOnly && !inSettings.mFloating && inSettings.mOverlapFraction < 1.0)
    {
        // A 2 m thick, 10 m wide wall from y = edge to edge + 10.
        const double edge = CrashWallLeftEdge(inSettings);
        add_static(std::make_unique<btBoxShape>(btVector3(1, 5, 3)), btVector3(1, btScalar(edge + 5.0), 3), friction);
    }
    else if (!inSettings.mDriveOnly && !inSettings.mFloating)
    {
        // A 2 m thick wall whose face is the plane through the origin turned by mWallAngleDegrees.
        const double angle = inSettings.mWallAngleDegrees * std::numbers::pi / 180.0;
        add_static(std::make_unique<btBoxShape>(btVector3(1, 10, 3)),
                   btVector3(btScalar(std::cos(angle)), btScalar(std::sin(angle)), 3), friction);
        mObjects.back()->setWorldTransform(btTransform(btQuaternion(btVector3(0, 0, 1), btScalar(angle)),
                                                       mObjects.back()->getWorldTransform().getOrigin()));
    }

    // Scenery: crates in a grid beside the road (not registered with Crumple).
    if (inSettings.mSceneryBoxes > 0)
        mShapes.push_back(std::make_unique<btBoxShape>(btVector3(0.5f, 0.5f, 0.5f)));
    for (int i = 0; i < inSettings.mSceneryBoxes; ++i)
    {
        btCollisionShape* crate_shape = mShapes.back().get();
        btVector3 crate_inertia;
        crate_shape->calculateLocalInertia(50, crate_inertia);
        btRigidBody::btRigidBodyConstructionInfo crate_info(50, nullptr, crate_shape, crate_inertia);
        crate_info.m_startWorldTransform.setOrigin(btVector3(btScalar(-30 + 2 * (i % 20)), btScalar(15 + 2 * (i / 20)), 0.5f));
        auto crate = std::make_unique<btRigidBody>(crate_info);
        crate->setActivationState(DISABLE_DEACTIVATION); // keep the engine busy, as moving scenery would
        mWorld->addRigidBody(crate.get());
        mObjects.push_back(std::move(crate));
    }

    // The car: a box resting on the ground, yawed, its nearest point mGap before the wall.
    const Vec3& h = inSettings.mHalfExtents;
    const double yaw = inSettings.mYawDegrees * std::numbers::pi / 180.0;
    auto shape = std::make_unique<btBoxShape>(btVector3(btScalar(h.x()), btScalar(h.y()), btScalar(h.z())));
    shape->initializePolyhedralFeatures(); // multi-point manifolds against convex hulls (the pole)
    btVector3 inertia;
    shape->calculateLocalInertia(btScalar(inSettings.mMass), inertia);
    if (inSettings.mInertia)
        inertia = btVector3(btScalar(inSettings.mInertia->x()), btScalar(inSettings.mInertia->y()),
                            btScalar(inSettings.mInertia->z()));
    const Vec3 origin = CrashCarStart(inSettings).mTranslation;
    const btTransform start(btQuaternion(btVector3(0, 0, 1), btScalar(yaw)),
                            btVector3(btScalar(origin.x()), btScalar(origin.y()), btScalar(origin.z())));
    btRigidBody::btRigidBodyConstructionInfo info(btScalar(inSettings.mMass), nullptr, shape.get(), inertia);
    info.m_startWorldTransform = start;
    info.m_friction = friction;
    info.m_restitution = restitution;
    auto car = std::make_unique<btRigidBody>(info);
    car->setLinearVelocity(btVector3(btScalar(inSettings.mSpeed), 0, 0));
    car->setActivationState(DISABLE_DEACTIVATION);
    mWorld->addRigidBody(car.get());
    mCar = car.get();
    mShapes.push_back(std::move(shape));
    mObjects.push_back(std::move(car));
    if (mAdapter == nullptr)
        return;
    const BodyId car_body = mAdapter->AddBody(*mCar).Get();
    mCarObject = mDamage.CreateDeformableObject(car_body, CrashCarObject(inSettings)).Get();
    if (mTarget != nullptr)
        mTargetObject = mDamage.CreateDeformableObject(mAdapter->AddBody(*mTarget).Get(),
                                                       TargetVehicleObject(*inSettings.mTargetVehicle)).Get();
    mDamage.AddListener(&mCounter);
}

BulletWallCrash::~BulletWallCrash()
{
    mAdapter.reset();
    for (auto& object : mObjects)
    {
        if (object == nullptr)
            continue; // removed mid-run
        if (btRigidBody* body = btRigidBody::upcast(object.get()))
            mWorld->removeRigidBody(body);
        else
            mWorld->removeCollisionObject(object.get());
    }
}

Result<plugin::BodyId> BulletWallCrash::MakeDebrisBody(const plugin::ConvexBodySettings& inSettings)
{
    return mAdapter->CreateConvexBody(inSettings);
}

Result<plugin::BodyId> BulletWallCrash::MakePropBody(const plugin::PropBodySettings& inSettings)
{
    return mAdapter->CreatePropBody(inSettings);
}

Status BulletWallCrash::RemoveMadeBody(plugin::BodyId inBody)
{
    btRigidBody* body = mAdapter->GetConvexBody(inBody);
    if (body == nullptr)
        return MakeError(EError::OutOfRange, "BulletWallCrash::RemoveMadeBody: body " +
                                                 std::to_string(inBody.mValue) + " is none the scene made");
    return mAdapter->RemoveBody(*body);
}

plugin::BodyState BulletWallCrash::GetCarState() const
{
    return bullet::BulletBodyState(*mCar);
}

void BulletWallCrash::SetCarVelocity(const Vec3& inLinear, const Vec3& inAngular)
{
    mCar->setLinearVelocity(btVector3(btScalar(inLinear.x()), btScalar(inLinear.y()), btScalar(inLinear.z())));
    mCar->setAngularVelocity(btVector3(btScalar(inAngular.x()), btScalar(inAngular.y()), btScalar(inAngular.z())));
}

void BulletWallCrash::Step()
{
    const auto dt = btScalar(mSettings.mTimeStep);
    mWorld->stepSimulation(dt, 1, dt);
}

EngineCrashResult BulletWallCrash::Run()
{
    return RunEngineCrash(*this, mSettings, mAdapter != nullptr);
}

} // namespace crumple::common
