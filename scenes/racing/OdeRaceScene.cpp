// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "OdeRaceScene.h"
#include "BoxMesh.h"
#include "RaceProps.h"
#include "RaceSession.h"

#include <crumple/ffd/BoundingBox.h>
#include <crumple/ode/OdeAdapter.h>

#include <algorithm>
#include <cmath>

namespace crumple::samples
{

using namespace crumple::plugin;

namespace
{

constexpr double cStep = 1.0 / 240.0; // four engine steps per 60 Hz frame
constexpr double cWheelRadius = 0.35;

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

} // namespace

OdeRaceScene::OdeRaceScene(const RaceSceneSettings& inSettings) : RaceScene(inSettings)
{
    dInitODE2(0); // reference counted by ODE; paired with dCloseODE in the destructor
}

OdeRaceScene::~OdeRaceScene()
{
    // The Crumple side first (the adapter's bodies are in the world), then the engine's.
    mProps.reset();
    mAdapter.reset();
    if (mContacts != nullptr)
        dJointGroupDestroy(mContacts);
    if (mSpace != nullptr)
        dSpaceDestroy(mSpace);
    if (mWorld != nullptr)
        dWorldDestroy(mWorld);
    dCloseODE();
}

void OdeRaceScene::Near(void* inData, dGeomID inGeom1, dGeomID inGeom2)
{
    auto* scene = static_cast<OdeRaceScene*>(inData);
    dBodyID b1 = dGeomGetBody(inGeom1), b2 = dGeomGetBody(inGeom2);
    if (b1 != nullptr && b2 != nullptr && dAreConnected(b1, b2) != 0)
        return; // the chassis and its own wheels
    std::array<dContact, 8> contacts{};
    const int count = dCollide(inGeom1, inGeom2, static_cast<int>(contacts.size()), &contacts[0].geom, sizeof(dContact));
    if (count <= 0)
        return;
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
    }
    // Crumple, once the surfaces are set (it reads their mu)
    if (scene->mAdapter != nullptr)
        scene->mAdapter->OnCollide(inGeom1, inGeom2, std::span<const dContact>(contacts.data(), static_cast<std::size_t>(count)));
    for (int i = 0; i < count; ++i)
        dJointAttach(dJointCreateContact(scene->mWorld, scene->mContacts, &contacts[static_cast<std::size_t>(i)]), b1, b2);
}

Result<std::unique_ptr<OdeRaceScene>> OdeRaceScene::Create(const RaceSceneSettings& inSettings)
{
    std::unique_ptr<OdeRaceScene> scene(new OdeRaceScene(inSettings));
    OdeRaceScene& s = *scene;
    const ffd::TriangleMesh car_mesh = RaceCarMesh();
    const ffd::AlignedBox bounds = ffd::BoundingBox(car_mesh.mPositions);
    const Vec3 half = 0.5 * (bounds.mMax - bounds.mMin);

    s.mWorld = dWorldCreate();
    dWorldSetGravity(s.mWorld, 0, 0, RaceCourse::Gravity().z());
    dWorldSetQuickStepNumIterations(s.mWorld, 50);
    s.mSpace = dHashSpaceCreate(nullptr);
    s.mContacts = dJointGroupCreate(0);
    if (inSettings.mAttach)
    {
        if (Status created = s.CreateDamageWorld(); !created)
            return created.GetError();
        // The sample prints Crumple's share of every frame: the adapter measures its calls' CPU time.
        ode::OdeAdapterSettings adapter_settings;
        adapter_settings.mMeasureCpuTime = true;
        Result<std::unique_ptr<ode::OdeAdapter>> adapter = ode::OdeAdapter::Create(*s.mDamage, adapter_settings);
        if (!adapter)
            return adapter.GetError();
        s.mAdapter = std::move(adapter).Get();
        s.mNames[s.mAdapter->GetEnvironment()] = "ground";
        // intent: the ground and the course's barriers are quiet (DamageWorld::SetQuiet), as the props' loose
        // pieces are: pieces rattling on them make no collisions
        if (Status quiet = s.mDamage->SetQuiet(s.mAdapter->GetEnvironment(), true); !quiet)
            return quiet.GetError();
    }

    dCreatePlane(s.mSpace, 0, 0, 1, 0);
    const Vec3 barrier_half = RaceCourse::BarrierHalfExtents();
    for (const Transform& pose : RaceCourse::Barriers())
    {
        dGeomID barrier = dCreateBox(s.mSpace, 2 * barrier_half.x(), 2 * barrier_half.y(), 2 * barrier_half.z());
        dGeomSetPosition(barrier, pose.mTranslation.x(), pose.mTranslation.y(), pose.mTranslation.z());
        dMatrix3 rotation;
        dRFromAxisAndAngle(rotation, 0, 0, 1, RaceCourse::cBarrierYaw);
        dGeomSetRotation(barrier, rotation);
        if (s.mAdapter == nullptr)
            continue;
        Result<BodyId> added = s.mAdapter->AddStaticGeom(barrier);
        if (!added)
            return added.GetError();
        if (Status quiet = s.mDamage->SetQuiet(added.Get(), true); !quiet)
            return quiet.GetError();
        s.mNames[added.Get()] = "barrier " + std::to_string(s.mNames.size());
    }

    // The car: chassis box around the body mesh, wheels of 0.35 m (inside its footprint, so the body, not a
    // wheel, meets the barriers) on hinge-2 joints (axis 1 steering, locked; axis 2 the axle, motorized at
    // the rear), the joint's suspension ERP/CFM giving the springs.
    const double mass = 1200.0;
    const double ride_height = cWheelRadius + 0.3 * half.z() + 0.3; // wheels just touching the ground
    s.mChassis = dBodyCreate(s.mWorld);
    dMass chassis_mass;
    dMassSetBoxTotal(&chassis_mass, mass, 2 * half.x(), 2 * half.y(), 1.6 * half.z());
    dBodySetMass(s.mChassis, &chassis_mass);
    dBodySetPosition(s.mChassis, 0, 0, ride_height);
    dBodySetAutoDisableFlag(s.mChassis, 0);
    dGeomSetBody(dCreateBox(s.mSpace, 2 * half.x(), 2 * half.y(), 1.6 * half.z()), s.mChassis);
    s.mWheelBase = 1.4 * half.x();
    for (int i = 0; i < 4; ++i)
    {
        const bool front = i < 2;
        const Vec3 at((front ? 0.7 : -0.7) * half.x(), (i % 2 == 0 ? 0.6 : -0.6) * half.y(), ride_height - 0.3 * half.z() - 0.3);
        dBodyID wheel = dBodyCreate(s.mWorld);
        dMass wheel_mass;
        dMassSetSphereTotal(&wheel_mass, 40.0, cWheelRadius);
        dBodySetMass(wheel, &wheel_mass);
        dBodySetPosition(wheel, at.x(), at.y(), at.z());
        dGeomSetBody(dCreateSphere(s.mSpace, cWheelRadius), wheel);
        dJointID hinge = dJointCreateHinge2(s.mWorld, nullptr);
        dJointAttach(hinge, s.mChassis, wheel);
        dJointSetHinge2Anchor(hinge, at.x(), at.y(), at.z());
        const dReal axis1[3] = {0, 0, 1}, axis2[3] = {0, 1, 0};
        dJointSetHinge2Axes(hinge, axis1, axis2);
        dJointSetHinge2Param(hinge, dParamSuspensionERP, 0.4);
        dJointSetHinge2Param(hinge, dParamSuspensionCFM, 2.0e-5);
        dJointSetHinge2Param(hinge, dParamLoStop, 0);
        dJointSetHinge2Param(hinge, dParamHiStop, 0);
        s.mHinges[static_cast<std::size_t>(i)] = hinge;
    }
    if (s.mAdapter != nullptr)
    {
        Result<BodyId> car_body = s.mAdapter->AddBody(s.mChassis);
        if (!car_body)
            return car_body.GetError();
        s.mNames[car_body.Get()] = "racing car";
        Result<const DeformableObject*> car = s.CreateCarObject(car_body.Get(), car_mesh);
        if (!car)
            return car.GetError();
        s.mCarObject = car.Get();
    }

    // The parked car.
    const Vec3 parked_half = RaceCourse::ParkedHalfExtents();
    const Transform parked_pose = RaceCourse::ParkedCar();
    s.mParked = dBodyCreate(s.mWorld);
    dMass parked_mass;
    dMassSetBoxTotal(&parked_mass, RaceCourse::cParkedMass, 2 * parked_half.x(), 2 * parked_half.y(), 2 * parked_half.z());
    dBodySetMass(s.mParked, &parked_mass);
    dBodySetPosition(s.mParked, parked_pose.mTranslation.x(), parked_pose.mTranslation.y(), parked_pose.mTranslation.z());
    dGeomSetBody(dCreateBox(s.mSpace, 2 * parked_half.x(), 2 * parked_half.y(), 2 * parked_half.z()), s.mParked);
    if (s.mAdapter == nullptr)
        return scene;
    Result<BodyId> parked_body = s.mAdapter->AddBody(s.mParked);
    if (!parked_body)
        return parked_body.GetError();
    s.mNames[parked_body.Get()] = "parked car";
    Result<const DeformableObject*> parked = s.CreateCarObject(parked_body.Get(), common::MakeBoxMesh(parked_half, {42, 18, 14}));
    if (!parked)
        return parked.GetError();
    s.mParkedObject = parked.Get();

    // The destructible props: the adapter makes and holds their bodies, RaceProps steps their FEM after each
    // engine step.
    ode::OdeAdapter& bodies = *s.mAdapter;
    Result<std::unique_ptr<RaceProps>> props = RaceProps::Create(
        *s.mDamage,
        {.mMakePropBody =
             [&bodies, &s](const PropBodySettings& inBody)
         {
             Result<BodyId> made = bodies.CreatePropBody(s.mWorld, s.mSpace, inBody);
             if (made && inBody.mHeld)
                 s.mHeldBodies.push_back(bodies.GetConvexBody(made.Get()));
             return made;
         },
         .mHeld = HeldPropCalls(bodies, [&bodies, &s](const ConvexBodySettings& inBody)
                                { return bodies.CreateConvexBody(s.mWorld, s.mSpace, inBody); })},
        cStep, s.mSettings.mPropsOffThread);
    if (Status kept = s.KeepProps(std::move(props)); !kept)
        return kept.GetError();
    return scene;
}

Status OdeRaceScene::StepFrame(const RaceNewBodies& inNewBodies)
{
    // Drive: the rear motors spin the wheels up to the target speed.
    for (int i = 2; i < 4; ++i)
    {
        dJointSetHinge2Param(mHinges[static_cast<std::size_t>(i)], dParamVel2, -mSettings.mSpeed / cWheelRadius);
        dJointSetHinge2Param(mHinges[static_cast<std::size_t>(i)], dParamFMax2, 1500.0);
    }
    // Steer: back to the course line. The front wheels' steering angle (the joint's angle 1, about the up
    // axis; it grows as the wheel turns to the right, the opposite of the course's angle) is held by its two
    // stops; ODE ignores a low stop above the high one, so the stop the angle moves towards goes first.
    const double angle = -RaceCourse::SteeringAngle(GetCarPose(), mWheelBase);
    for (int i = 0; i < 2; ++i)
    {
        dJointID hinge = mHinges[static_cast<std::size_t>(i)];
        const bool up = angle > dJointGetHinge2Param(hinge, dParamHiStop);
        dJointSetHinge2Param(hinge, up ? dParamHiStop : dParamLoStop, angle);
        dJointSetHinge2Param(hinge, up ? dParamLoStop : dParamHiStop, angle);
    }
    mFrameCrumpleMs = 0.0;
    for (int sub = 0; sub < 4; ++sub)
    {
        dSpaceCollide(mSpace, this, &OdeRaceScene::Near);
        dWorldQuickStep(mWorld, cStep);
        if (mAdapter != nullptr)
        {
            mAdapter->AfterStep(cStep); // Crumple
            mFrameCrumpleMs += 1.0e3 * mAdapter->GetLastStepStats().mSeconds;
        }
        dJointGroupEmpty(mContacts);
        // The props' FEM after each engine step: a held prop body takes the struck members' velocity.
        if (Status stepped = StepProps(cStep, inNewBodies); !stepped)
            return stepped;
    }
    return Status::Ok();
}

Transform OdeRaceScene::GetCarPose() const
{
    return PoseOf(mChassis);
}

Transform OdeRaceScene::GetParkedPose() const
{
    return PoseOf(mParked);
}

} // namespace crumple::samples
