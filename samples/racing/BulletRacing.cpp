// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// A scripted racing session in Bullet: a btRaycastVehicle with a deformable body (the Khronos Toy Car from
// ../shared/data when present, else a procedural box) accelerates down a straight, scrapes along concrete
// barriers angled into the road, breaks through a wooden fence whose pieces fly (a destructible prop: FEM,
// fracture, pieces made engine bodies) and hits a parked car (samples/common/RaceSession.h has the course).
// Prints one line per collision; writes a replay file, the deformed meshes (OBJ) and PNG pictures.
#include "BoxMesh.h"
#include "RaceFence.h"
#include "RaceSession.h"
#include "ThreadJobSystem.h"

#include <crumple/ffd/BoundingBox.h>
#include <crumple/bullet/BulletAdapter.h>

#include <BulletDynamics/Vehicle/btRaycastVehicle.h>
#include <btBulletDynamicsCommon.h>

#include <cmath>
#include <cstdio>

using namespace crumple;
using namespace crumple::plugin;
using namespace crumple::samples;

namespace
{

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

int main(int argc, char** argv)
{
    RaceOptions options;
    if (const int code = ParseRaceOptions(argc, argv, "crumple-racing-bullet",
                                          "A btRaycastVehicle with a deformable body scrapes along barriers, breaks through a fence, "
                                          "then hits a parked car.",
                                          options);
        code >= 0)
        return code;

    const ffd::TriangleMesh car_mesh = RaceCarMesh();
    const ffd::AlignedBox bounds = ffd::BoundingBox(car_mesh.mPositions);
    const Vec3 lo = bounds.mMin, hi = bounds.mMax;
    const Vec3 half = 0.5 * (hi - lo);

    btDefaultCollisionConfiguration configuration;
    btCollisionDispatcher dispatcher(&configuration);
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    btDiscreteDynamicsWorld world(&dispatcher, &broadphase, &solver, &configuration);
    world.setGravity(btVector3(0, 0, btScalar(-9.81)));
    // The game's job system (here: threads started per parallel for), handed to Crumple for dents.
    const common::ThreadJobSystem jobs(options.mThreads);
    DamageWorldSettings damage_settings;
    damage_settings.mJobs = options.mThreads > 1 || options.mDeferDents ? &jobs.Get() : nullptr;
    damage_settings.mDeferDents = options.mDeferDents;
    std::unique_ptr<DamageWorld> damage_owner = std::move(DamageWorld::Create(damage_settings).Get());
    DamageWorld& damage = *damage_owner;
    std::unique_ptr<bullet::BulletAdapter> adapter = std::move(bullet::BulletAdapter::Create(world, damage).Get());
    std::map<BodyId, std::string> names;

    // The ground is a static btRigidBody: btDefaultVehicleRaycaster only lets wheels stand on rigid bodies.
    btStaticPlaneShape ground_shape(btVector3(0, 0, 1), 0);
    btRigidBody ground(btRigidBody::btRigidBodyConstructionInfo(0, nullptr, &ground_shape));
    ground.setFriction(btScalar(0.9));
    world.addRigidBody(&ground);
    names[adapter->AddBody(ground).Get()] = "ground";

    btBoxShape barrier_shape(ToBullet(RaceCourse::BarrierHalfExtents()));
    std::vector<std::unique_ptr<btCollisionObject>> barriers;
    for (const Transform& pose : RaceCourse::Barriers())
    {
        auto barrier = std::make_unique<btCollisionObject>();
        barrier->setCollisionShape(&barrier_shape);
        barrier->setWorldTransform(ToBullet(pose));
        world.addCollisionObject(barrier.get());
        names[adapter->AddBody(*barrier).Get()] = "barrier " + std::to_string(barriers.size() + 1);
        barriers.push_back(std::move(barrier));
    }

    // The racing car: a chassis box around the body mesh on four raycast wheels.
    btBoxShape chassis_shape(btVector3(btScalar(half.x()), btScalar(half.y()), btScalar(0.8 * half.z())));
    const double mass = 1200.0;
    btVector3 inertia;
    chassis_shape.calculateLocalInertia(btScalar(mass), inertia);
    // Wheels reach 0.3 h + 0.35 + 0.35 m below the centre of mass; start at the loaded ride height.
    const double ride_height = 0.3 * half.z() + 0.7 - 0.05;
    btDefaultMotionState car_motion(btTransform(btQuaternion::getIdentity(), btVector3(0, 0, btScalar(ride_height))));
    btRigidBody car(btRigidBody::btRigidBodyConstructionInfo(btScalar(mass), &car_motion, &chassis_shape, inertia));
    car.setActivationState(DISABLE_DEACTIVATION);
    world.addRigidBody(&car);
    btDefaultVehicleRaycaster raycaster(&world);
    btRaycastVehicle::btVehicleTuning tuning;
    btRaycastVehicle vehicle(tuning, &car, &raycaster);
    vehicle.setCoordinateSystem(1, 2, 0); // right = y, up = z, forward = x
    world.addAction(&vehicle);
    for (int i = 0; i < 4; ++i)
    {
        const bool front = i < 2;
        const btVector3 connection(btScalar((front ? 0.7 : -0.7) * half.x()), btScalar((i % 2 == 0 ? 0.8 : -0.8) * half.y()),
                                   btScalar(-0.3 * half.z()));
        btWheelInfo& wheel = vehicle.addWheel(connection, btVector3(0, 0, -1), btVector3(0, -1, 0), 0.35f, 0.35f, tuning, front);
        wheel.m_suspensionStiffness = 30.0f;
        wheel.m_wheelsDampingRelaxation = 4.0f;
        wheel.m_wheelsDampingCompression = 3.0f;
        wheel.m_frictionSlip = 1.2f;
        wheel.m_rollInfluence = 0.1f;
        wheel.m_maxSuspensionForce = 60000.0f; // Bullet's default (6,000 N) cannot hold a 1.2 t car landing
    }
    const BodyId car_body = adapter->AddBody(car).Get();
    names[car_body] = "racing car";
    DeformableObjectSettings car_object;
    car_object.mMesh = car_mesh;
    const DeformableObject& car_deformable = *damage.GetObject(damage.CreateDeformableObject(car_body, car_object).Get());

    // The parked car.
    btBoxShape parked_shape(ToBullet(RaceCourse::ParkedHalfExtents()));
    btVector3 parked_inertia;
    parked_shape.calculateLocalInertia(btScalar(RaceCourse::cParkedMass), parked_inertia);
    btDefaultMotionState parked_motion(ToBullet(RaceCourse::ParkedCar()));
    btRigidBody::btRigidBodyConstructionInfo parked_info(btScalar(RaceCourse::cParkedMass), &parked_motion, &parked_shape, parked_inertia);
    parked_info.m_friction = 0.8f;
    btRigidBody parked(parked_info);
    world.addRigidBody(&parked);
    const BodyId parked_body = adapter->AddBody(parked).Get();
    names[parked_body] = "parked car";
    DeformableObjectSettings parked_object;
    parked_object.mMesh = common::MakeBoxMesh(RaceCourse::ParkedHalfExtents(), {42, 18, 14});
    const DeformableObject& parked_deformable = *damage.GetObject(damage.CreateDeformableObject(parked_body, parked_object).Get());

    const double dt = 1.0 / 60.0; // a frame: four engine steps of 1/240 s
    // The destructible fence: the adapter makes and holds its body, RaceFence steps its FEM after each engine step.
    bullet::BulletAdapter& bodies = *adapter;
    Result<std::unique_ptr<RaceFence>> fence = RaceFence::Create(
        damage, {.mMakePropBody = [&bodies](const PropBodySettings& inBody) { return bodies.CreatePropBody(inBody); },
                 .mHeld = {.mCreatePieceBody = [&bodies](const ConvexBodySettings& inBody) { return bodies.CreateConvexBody(inBody); },
                           .mSetPropPieces = [&bodies](BodyId inBody, const std::vector<std::vector<Vec3>>& inPieces) { return bodies.SetPropPieces(inBody, inPieces); },
                           .mSetHeldVelocity = [&bodies](BodyId inBody, const Vec3& inVelocity) { return bodies.SetHeldVelocity(inBody, inVelocity); },
                           .mIsHeld = [&bodies](BodyId inBody) { return bodies.IsHeldPropBody(inBody); }}}, dt / 4.0);
    if (!fence)
    {
        std::fprintf(stderr, "crumple-racing-bullet: the fence: %s\n", fence.GetError().mMessage.c_str());
        return 2;
    }
    names[fence.Get()->GetBody()] = "fence";

    Result<std::unique_ptr<RaceSession>> session = RaceSession::Create(options, damage, names);
    if (!session)
    {
        std::fprintf(stderr, "crumple-racing-bullet: %s\n", session.GetError().mMessage.c_str());
        return 2;
    }
    if (Status recorded = fence.Get()->AttachRecorder(&session.Get()->GetRecorder()); !recorded)
    {
        std::fprintf(stderr, "crumple-racing-bullet: %s\n", recorded.GetError().mMessage.c_str());
        return 2;
    }
    session.Get()->PaintCar(car_deformable, "before.png");

    // Drive: full throttle to the target speed, then hold it; a frame every 0.1 s.
    const int steps = static_cast<int>(std::lround(options.mDuration / dt));
    std::vector<BodyId> pieces;
    Status finished = Status::Ok();
    for (int step = 0; step < steps && finished; ++step)
    {
        const double speed = static_cast<double>(vehicle.getCurrentSpeedKmHour()) / 3.6;
        for (int wheel = 2; wheel < 4; ++wheel)
            vehicle.applyEngineForce(speed < options.mSpeed ? btScalar(6000) : btScalar(0), wheel);
        session.Get()->BeginFrame();
        // Four engine steps of 1/240 s, the fence's FEM after each: the held fence body takes the struck
        // timbers' velocity at every step (a frame's worth of steps against a fence at rest would take from
        // the car what four fences would).
        for (int sub = 0; sub < 4 && finished; ++sub)
        {
            world.stepSimulation(btScalar(dt / 4.0), 0); // exactly one step of 1/240 s
            finished = fence.Get()->Step(dt / 4.0, pieces);
            session.Get()->NamePieces(pieces, "fence piece");
            pieces.clear();
        }
        session.Get()->EndFrame();
        if (step % 6 == 0)
            session.Get()->PaintFrame(car_deformable, ToTransform(car.getWorldTransform()), parked_deformable,
                                      ToTransform(parked.getWorldTransform()), *fence.Get());
    }
    if (finished)
        finished = session.Get()->Finish(damage, car_deformable, parked_deformable, *fence.Get());

    world.removeAction(&vehicle);
    world.removeRigidBody(&parked);
    world.removeRigidBody(&car);
    for (const auto& barrier : barriers)
        world.removeCollisionObject(barrier.get());
    world.removeRigidBody(&ground);
    if (!finished)
    {
        std::fprintf(stderr, "crumple-racing-bullet: %s\n", finished.GetError().mMessage.c_str());
        return 2;
    }
    return 0;
}
