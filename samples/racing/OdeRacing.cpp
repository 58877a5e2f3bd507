// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// The racing session of BulletRacing.cpp in ODE: a chassis on four sphere wheels held by hinge-2 joints
// (suspension and a rear-wheel motor), on the same course. The game adds one line to its near callback
// (OdeAdapter::OnCollide) and one after dWorldQuickStep (OdeAdapter::AfterStep).
#include "BoxMesh.h"
#include "RaceFence.h"
#include "RaceSession.h"
#include "ThreadJobSystem.h"

#include <crumple/ffd/BoundingBox.h>
#include <crumple/ode/OdeAdapter.h>

#include <ode/ode.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

using namespace crumple;
using namespace crumple::plugin;
using namespace crumple::samples;

namespace
{

Transform PoseOf(dBodyID inBody)
{
    const dReal* r = dBodyGetRotation(inBody);
    const dReal* p = dBodyGetPosition(inBody);
    Mat3 rotation;
    for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 3; ++col)
            rotation(row, col) = r[row * 4 + col];
    return {Quat(rotation).normalized().toRotationMatrix(), Vec3(p[0], p[1], p[2])};
}

// The scene and what the near callback needs.
struct OdeScene
{
    dWorldID mWorld = nullptr;
    dSpaceID mSpace = nullptr;
    dJointGroupID mContacts = nullptr;
    ode::OdeAdapter* mAdapter = nullptr;
    std::vector<dBodyID> mHeldBodies; ///< Held prop bodies (the fence), put back at their pose every step

    static void Near(void* inData, dGeomID inGeom1, dGeomID inGeom2)
    {
        auto* scene = static_cast<OdeScene*>(inData);
        dBodyID b1 = dGeomGetBody(inGeom1), b2 = dGeomGetBody(inGeom2);
        if (b1 != nullptr && b2 != nullptr && dAreConnected(b1, b2) != 0)
            return; // the chassis and its own wheels
        std::array<dContact, 8> contacts{};
        const int count = dCollide(inGeom1, inGeom2, static_cast<int>(contacts.size()), &contacts[0].geom, sizeof(dContact));
        if (count <= 0)
            return;
        scene->mAdapter->OnCollide(inGeom1, inGeom2, std::span<const dContact>(contacts.data(), static_cast<std::size_t>(count))); // Crumple
        for (int i = 0; i < count; ++i)
        {
            dContact& contact = contacts[static_cast<std::size_t>(i)];
            contact.surface.mode = dContactSoftERP | dContactSoftCFM | dContactApprox1;
            // Tyres grip; bodywork slides along barriers and other cars.
            const bool tyre = dGeomGetClass(inGeom1) == dSphereClass || dGeomGetClass(inGeom2) == dSphereClass;
            contact.surface.mu = tyre ? 1.2 : 0.3;
            // Stiff contacts: an impact is stopped within a step, as Crumple's per-step impulses assume
            // (soft contacts leave approach for later steps, which then counts again).
            // A held prop body is put back where it stands after every step, over a car that pushed into it:
            // error reduction would push the two apart with velocity no impulse accounts for. Its contacts
            // resolve velocities only (as Bullet's split impulse does).
            const bool held = std::find(scene->mHeldBodies.begin(), scene->mHeldBodies.end(), b1) != scene->mHeldBodies.end() ||
                              std::find(scene->mHeldBodies.begin(), scene->mHeldBodies.end(), b2) != scene->mHeldBodies.end();
            contact.surface.soft_erp = held ? 0.0 : 0.2;
            contact.surface.soft_cfm = 1.0e-5;
            dJointAttach(dJointCreateContact(scene->mWorld, scene->mContacts, &contact), b1, b2);
        }
    }
};

} // namespace

int main(int argc, char** argv)
{
    RaceOptions options;
    options.mOut = "racing-ode-output";
    if (const int code = ParseRaceOptions(argc, argv, "crumple-racing-ode",
                                          "An ODE car with a deformable body scrapes along barriers, breaks through a fence, then "
                                          "hits a parked car.",
                                          options);
        code >= 0)
        return code;

    const ffd::TriangleMesh car_mesh = RaceCarMesh();
    const ffd::AlignedBox bounds = ffd::BoundingBox(car_mesh.mPositions);
    const Vec3 lo = bounds.mMin, hi = bounds.mMax;
    const Vec3 half = 0.5 * (hi - lo);

    dInitODE2(0);
    OdeScene scene;
    scene.mWorld = dWorldCreate();
    dWorldSetGravity(scene.mWorld, 0, 0, -9.81);
    dWorldSetQuickStepNumIterations(scene.mWorld, 50);
    scene.mSpace = dHashSpaceCreate(nullptr);
    scene.mContacts = dJointGroupCreate(0);
    // The game's job system (here: threads started per parallel for), handed to Crumple for dents.
    const common::ThreadJobSystem jobs(options.mThreads);
    DamageWorldSettings damage_settings;
    damage_settings.mJobs = options.mThreads > 1 || options.mDeferDents ? &jobs.Get() : nullptr;
    damage_settings.mDeferDents = options.mDeferDents;
    std::unique_ptr<DamageWorld> damage_owner = std::move(DamageWorld::Create(damage_settings).Get());
    DamageWorld& damage = *damage_owner;
    std::unique_ptr<ode::OdeAdapter> adapter = std::move(ode::OdeAdapter::Create(damage).Get());
    scene.mAdapter = adapter.get();
    std::map<BodyId, std::string> names{{adapter->GetEnvironment(), "ground"}};

    dCreatePlane(scene.mSpace, 0, 0, 1, 0);
    const Vec3 barrier_half = RaceCourse::BarrierHalfExtents();
    for (const Transform& pose : RaceCourse::Barriers())
    {
        dGeomID barrier = dCreateBox(scene.mSpace, 2 * barrier_half.x(), 2 * barrier_half.y(), 2 * barrier_half.z());
        dGeomSetPosition(barrier, pose.mTranslation.x(), pose.mTranslation.y(), pose.mTranslation.z());
        dMatrix3 rotation;
        dRFromAxisAndAngle(rotation, 0, 0, 1, RaceCourse::cBarrierYaw);
        dGeomSetRotation(barrier, rotation);
        names[adapter->AddStaticGeom(barrier).Get()] = "barrier " + std::to_string(names.size());
    }

    // The car: chassis box around the body mesh, wheels of 0.35 m (inside its footprint, so the body, not a
    // wheel, meets the barriers) on hinge-2 joints (axis 1 steering,
    // locked; axis 2 the axle, motorized at the rear), the joint's suspension ERP/CFM giving the springs.
    const double mass = 1200.0, wheel_radius = 0.35;
    const double ride_height = wheel_radius + 0.3 * half.z() + 0.3; // wheels just touching the ground
    dBodyID chassis = dBodyCreate(scene.mWorld);
    dMass chassis_mass;
    dMassSetBoxTotal(&chassis_mass, mass, 2 * half.x(), 2 * half.y(), 1.6 * half.z());
    dBodySetMass(chassis, &chassis_mass);
    dBodySetPosition(chassis, 0, 0, ride_height);
    dBodySetAutoDisableFlag(chassis, 0);
    dGeomSetBody(dCreateBox(scene.mSpace, 2 * half.x(), 2 * half.y(), 1.6 * half.z()), chassis);
    std::array<dJointID, 4> hinges{};
    for (int i = 0; i < 4; ++i)
    {
        const bool front = i < 2;
        const Vec3 at((front ? 0.7 : -0.7) * half.x(), (i % 2 == 0 ? 0.6 : -0.6) * half.y(), ride_height - 0.3 * half.z() - 0.3);
        dBodyID wheel = dBodyCreate(scene.mWorld);
        dMass wheel_mass;
        dMassSetSphereTotal(&wheel_mass, 40.0, wheel_radius);
        dBodySetMass(wheel, &wheel_mass);
        dBodySetPosition(wheel, at.x(), at.y(), at.z());
        dGeomSetBody(dCreateSphere(scene.mSpace, wheel_radius), wheel);
        dJointID hinge = dJointCreateHinge2(scene.mWorld, nullptr);
        dJointAttach(hinge, chassis, wheel);
        dJointSetHinge2Anchor(hinge, at.x(), at.y(), at.z());
        const dReal axis1[3] = {0, 0, 1}, axis2[3] = {0, 1, 0};
        dJointSetHinge2Axes(hinge, axis1, axis2);
        dJointSetHinge2Param(hinge, dParamSuspensionERP, 0.4);
        dJointSetHinge2Param(hinge, dParamSuspensionCFM, 2.0e-5);
        dJointSetHinge2Param(hinge, dParamLoStop, 0);
        dJointSetHinge2Param(hinge, dParamHiStop, 0);
        hinges[static_cast<std::size_t>(i)] = hinge;
    }
    const BodyId car_body = adapter->AddBody(chassis).Get();
    names[car_body] = "racing car";
    DeformableObjectSettings car_object;
    car_object.mMesh = car_mesh;
    const DeformableObject& car_deformable = *damage.GetObject(damage.CreateDeformableObject(car_body, car_object).Get());

    // The parked car.
    const Vec3 parked_half = RaceCourse::ParkedHalfExtents();
    const Transform parked_pose = RaceCourse::ParkedCar();
    dBodyID parked = dBodyCreate(scene.mWorld);
    dMass parked_mass;
    dMassSetBoxTotal(&parked_mass, RaceCourse::cParkedMass, 2 * parked_half.x(), 2 * parked_half.y(), 2 * parked_half.z());
    dBodySetMass(parked, &parked_mass);
    dBodySetPosition(parked, parked_pose.mTranslation.x(), parked_pose.mTranslation.y(), parked_pose.mTranslation.z());
    dGeomSetBody(dCreateBox(scene.mSpace, 2 * parked_half.x(), 2 * parked_half.y(), 2 * parked_half.z()), parked);
    const BodyId parked_body = adapter->AddBody(parked).Get();
    names[parked_body] = "parked car";
    DeformableObjectSettings parked_object;
    parked_object.mMesh = common::MakeBoxMesh(parked_half, {42, 18, 14});
    const DeformableObject& parked_deformable = *damage.GetObject(damage.CreateDeformableObject(parked_body, parked_object).Get());

    const double dt = 1.0 / 240.0;
    // The destructible fence: the adapter makes and holds its body, RaceFence steps its FEM after each engine step.
    ode::OdeAdapter& bodies = *adapter;
    Result<std::unique_ptr<RaceFence>> fence = RaceFence::Create(
        damage, {.mMakePropBody =
                     [&bodies, &scene](const PropBodySettings& inBody) {
                         Result<BodyId> made = bodies.CreatePropBody(scene.mWorld, scene.mSpace, inBody);
                         if (made && inBody.mHeld)
                             scene.mHeldBodies.push_back(bodies.GetConvexBody(made.Get()));
                         return made;
                     },
                 .mHeld = {.mCreatePieceBody = [&bodies, &scene](const ConvexBodySettings& inBody) { return bodies.CreateConvexBody(scene.mWorld, scene.mSpace, inBody); },
                           .mSetPropPieces = [&bodies](BodyId inBody, const std::vector<std::vector<Vec3>>& inPieces) { return bodies.SetPropPieces(inBody, inPieces); },
                           .mSetHeldVelocity = [&bodies](BodyId inBody, const Vec3& inVelocity) { return bodies.SetHeldVelocity(inBody, inVelocity); },
                           .mIsHeld = [&bodies](BodyId inBody) { return bodies.IsHeldPropBody(inBody); }}}, dt);
    if (!fence)
    {
        std::fprintf(stderr, "crumple-racing-ode: the fence: %s\n", fence.GetError().mMessage.c_str());
        return 2;
    }
    names[fence.Get()->GetBody()] = "fence";

    Result<std::unique_ptr<RaceSession>> session = RaceSession::Create(options, damage, names);
    if (!session)
    {
        std::fprintf(stderr, "crumple-racing-ode: %s\n", session.GetError().mMessage.c_str());
        return 2;
    }
    if (Status recorded = fence.Get()->AttachRecorder(&session.Get()->GetRecorder()); !recorded)
    {
        std::fprintf(stderr, "crumple-racing-ode: %s\n", recorded.GetError().mMessage.c_str());
        return 2;
    }
    session.Get()->PaintCar(car_deformable, "before.png");

    // Drive: the rear motors spin the wheels up to the target speed; four ODE steps per 60 Hz frame.
    const int frames = static_cast<int>(std::lround(options.mDuration * 60.0));
    std::vector<BodyId> pieces;
    Status finished = Status::Ok();
    for (int frame = 0; frame < frames && finished; ++frame)
    {
        for (int i = 2; i < 4; ++i)
        {
            dJointSetHinge2Param(hinges[static_cast<std::size_t>(i)], dParamVel2, -options.mSpeed / wheel_radius);
            dJointSetHinge2Param(hinges[static_cast<std::size_t>(i)], dParamFMax2, 1500.0);
        }
        session.Get()->BeginFrame();
        for (int sub = 0; sub < 4; ++sub)
        {
            dSpaceCollide(scene.mSpace, &scene, &OdeScene::Near);
            dWorldQuickStep(scene.mWorld, dt);
            adapter->AfterStep(dt); // Crumple
            dJointGroupEmpty(scene.mContacts);
            // The fence's FEM after each engine step: the held fence body takes the struck timbers' velocity.
            finished = fence.Get()->Step(dt, pieces);
            session.Get()->NamePieces(pieces, "fence piece");
            pieces.clear();
            if (!finished)
                break;
        }
        session.Get()->EndFrame();
        if (frame % 6 == 0)
            session.Get()->PaintFrame(car_deformable, PoseOf(chassis), parked_deformable, PoseOf(parked), *fence.Get());
    }
    if (finished)
        finished = session.Get()->Finish(damage, car_deformable, parked_deformable, *fence.Get());

    adapter.reset();
    dJointGroupDestroy(scene.mContacts);
    dSpaceDestroy(scene.mSpace);
    dWorldDestroy(scene.mWorld);
    dCloseODE();
    if (!finished)
    {
        std::fprintf(stderr, "crumple-racing-ode: %s\n", finished.GetError().mMessage.c_str());
        return 2;
    }
    return 0;
}
