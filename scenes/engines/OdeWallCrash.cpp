// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "OdeWallCrash.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>

namespace crumple::common
{

using namespace crumple::plugin;

OdeWallCrash::OdeWallCrash(const EngineCrashSettings& inSettings)
    : mSettings(inSettings), mDamageOwner(std::move(DamageWorld::Create(inSettings.mWorld).Get())), mDamage(*mDamageOwner)
{
    dInitODE2(0); // reference counted by ODE; paired with dCloseODE in the destructor
    mWorld = dWorldCreate();
    dWorldSetGravity(mWorld, 0, 0, inSettings.mFloating ? 0.0 : -cCrashGravity);
    mSpace = dHashSpaceCreate(nullptr);
    mContacts = dJointGroupCreate(0);
    // ODE pushes a penetrating body out at ERP x depth / step: a car that sinks 0.13 m into the wall in one
    // step at 56 km/h would be thrown back at 3 m/s (a rebound of e ~ 0.13 where Crumple assumes
    // DamageWorldSettings::mRestitution). Cap that correction and bounce by Crumple's restitution instead
    // (NearCallback), so the engine's change of the car's momentum is the impulse Crumple dents with.
    dWorldSetContactMaxCorrectingVel(mWorld, cMaxCorrectingSpeed);
    // The iterative step (projected Gauss-Seidel, as Bullet's), not dWorldStep's Dantzig LCP: Dantzig bounds
    // each friction row by mu times a normal force it has not solved yet, and leaves a sliding contact with
    // less friction and less normal impulse than Coulomb's law gives. A box car into a wall turned 45 degrees
    // at 20 km/h (friction 0.5): dWorldStep took 6,329 N s along the normal where the exact sliding impulse
    // (and Bullet's, and Crumple's) is 7,158; 11-19 % short at 45 and 60 degrees. The quick step with
    // cQuickStepIterations agrees with Crumple's impulse within 2.5 % at 45 and 60 degrees, 20 and 56 km/h
    // (and at 5 km/h since the wall contacts' soft ERP is the restitution, NearCallback).
    dWorldSetQuickStepNumIterations(mWorld, cQuickStepIterations);
    if (inSettings.mAttach)
    {
        ode::OdeAdapterSettings adapter;
        adapter.mMeasureCpuTime = inSettings.mMeasureAdapterTime;
        mAdapter = std::move(ode::OdeAdapter::Create(mDamage, adapter).Get());
    }

    if (!inSettings.mFloating)
    {
        dCreatePlane(mSpace, 0, 0, 1, 0);
        // intent: the ground (the adapter's environment) is quiet, as the props' loose pieces are: pieces on
        // it make no collisions (DamageWorld::SetQuiet); the cars' contacts with it are solved as before
        if (mAdapter != nullptr)
            (void)mDamage.SetQuiet(mAdapter->GetEnvironment(), true);
    }
    if (inSettings.mTargetVehicle)
    {
        // A second car, a dynamic box on the ground.
        const TargetVehicleSettings& target = *inSettings.mTargetVehicle;
        const Vec3& th = target.mHalfExtents;
        mTarget = dBodyCreate(mWorld);
        dMass target_mass;
        dMassSetBoxTotal(&target_mass, target.mMass, 2 * th.x(), 2 * th.y(), 2 * th.z());
        dBodySetMass(mTarget, &target_mass);
        const Transform place = TargetVehicleStart(target);
        dBodySetPosition(mTarget, place.mTranslation.x(), place.mTranslation.y(), place.mTranslation.z());
        const double target_yaw = target.mYawDegrees * std::numbers::pi / 180.0;
        dMatrix3 target_rotation;
        dRFromAxisAndAngle(target_rotation, 0, 0, 1, target_yaw);
        dBodySetRotation(mTarget, target_rotation);
        dBodySetLinearVel(mTarget, target.mSpeed * std::cos(target_yaw), target.mSpeed * std::sin(target_yaw), 0);
        dBodySetAutoDisableFlag(mTarget, 0);
        dGeomSetBody(dCreateBox(mSpace, 2 * th.x(), 2 * th.y(), 2 * th.z()), mTarget);
    }
    else if (!inSettings.mDriveOnly && !inSettings.mFloating && inSettings.mPoleRadius > 0.0)
    {
        dGeomID pole = dCreateCylinder(mSpace, inSettings.mPoleRadius, 6.0); // axis along z
        dGeomSetPosition(pole, 0, 0, 3);
        RegisterImpactor(pole);
    }
    else if (!inSettings.mDriveOnly && !inSettings.mFloating && inSettings.mOverlapFraction < 1.0)
    {
        // A 2 m thick, 10 m wide wall from y = edge to edge + 10.
        dGeomID wall = dCreateBox(mSpace, 2, 10, 6);
        dGeomSetPosition(wall, 1, CrashWallLeftEdge(inSettings) + 5.0, 3);
        RegisterImpactor(wall);
    }
    else if (!inSettings.mDriveOnly && !inSettings.mFloating)
    {
        // A 2 m thick wall whose face is the plane through the origin turned by mWallAngleDegrees.
        const double angle = inSettings.mWallAngleDegrees * std::numbers::pi / 180.0;
        dGeomID wall = dCreateBox(mSpace, 2, 20, 6);
        dGeomSetPosition(wall, std::cos(angle), std::sin(angle), 3);
        dMatrix3 wall_rotation;
        dRFromAxisAndAngle(wall_rotation, 0, 0, 1, angle);
        dGeomSetRotation(wall, wall_rotation);
        RegisterImpactor(wall);
    }

    // Scenery: crates in a grid beside the road (not registered with Crumple).
    for (int i = 0; i < inSettings.mSceneryBoxes; ++i)
    {
        dBodyID crate = dBodyCreate(mWorld);
        dMass crate_mass;
        dMassSetBoxTotal(&crate_mass, 50.0, 1.0, 1.0, 1.0);
        dBodySetMass(crate, &crate_mass);
        dBodySetPosition(crate, -30.0 + 2.0 * (i % 20), 15.0 + 2.0 * (i / 20), 0.5);
        dBodySetAutoDisableFlag(crate, 0); // keep the engine busy, as moving scenery would
        dGeomSetBody(dCreateBox(mSpace, 1.0, 1.0, 1.0), crate);
    }

    const Vec3& h = inSettings.mHalfExtents;
    const double yaw = inSettings.mYawDegrees * std::numbers::pi / 180.0;
    mCar = dBodyCreate(mWorld);
    dMass mass;
    dMassSetBoxTotal(&mass, inSettings.mMass, 2 * h.x(), 2 * h.y(), 2 * h.z());
    if (inSettings.mInertia)
    {
        mass.I[0] = inSettings.mInertia->x();
        mass.I[5] = inSettings.mInertia->y();
        mass.I[10] = inSettings.mInertia->z();
    }
    dBodySetMass(mCar, &mass);
    const Vec3 origin = CrashCarStart(inSettings).mTranslation;
    dBodySetPosition(mCar, origin.x(), origin.y(), origin.z());
    dMatrix3 rotation;
    dRFromAxisAndAngle(rotation, 0, 0, 1, yaw);
    dBodySetRotation(mCar, rotation);
    dBodySetLinearVel(mCar, inSettings.mSpeed, 0, 0);
    dBodySetAutoDisableFlag(mCar, 0);
    dGeomID box = dCreateBox(mSpace, 2 * h.x(), 2 * h.y(), 2 * h.z());
    dGeomSetBody(box, mCar);

    if (mAdapter == nullptr)
        return;
    const BodyId car_body = mAdapter->AddBody(mCar).Get();
    mCarObject = mDamage.CreateDeformableObject(car_body, CrashCarObject(inSettings)).Get();
    if (mTarget != nullptr)
        mTargetObject = mDamage.CreateDeformableObject(mAdapter->AddBody(mTarget).Get(),
                                                       TargetVehicleObject(*inSettings.mTargetVehicle)).Get();
    mDamage.AddListener(&mCounter);
}

void OdeWallCrash::RegisterImpactor(dGeomID inGeom)
{
    if (mAdapter != nullptr)
        mWallBody = mAdapter->AddStaticGeom(inGeom).Get();
}

OdeWallCrash::~OdeWallCrash()
{
    mAdapter.reset();
    dJointGroupDestroy(mContacts);
    dSpaceDestroy(mSpace);
    dWorldDestroy(mWorld);
    dCloseODE();
}

void OdeWallCrash::NearCallback(void* inData, dGeomID inGeom1, dGeomID inGeom2)
{
    auto* scene = static_cast<OdeWallCrash*>(inData);
    std::array<dContact, 8> contacts{};
    const int count = dCollide(inGeom1, inGeom2, static_cast<int>(contacts.size()), &contacts[0].geom, sizeof(dContact));
    if (count <= 0)
        return;
    dBodyID b1 = dGeomGetBody(inGeom1), b2 = dGeomGetBody(inGeom2);
    for (int i = 0; i < count; ++i)
    {
        dContact& contact = contacts[static_cast<std::size_t>(i)];
        // A stiff contact: a soft CFM of 1e-5 m/N lets a 1,200 kg car at 40 km/h sink through three steps
        // (the contact force times CFM is the slack) and leaves the bounce unreached.
        // dContactApprox1: mu is a friction coefficient, as in Bullet; without it ODE reads mu as a force limit
        // in newtons (0.5 N: a frictionless ground, where the Bullet scene's car slows before the wall).
        contact.surface.mode = dContactSoftCFM | dContactSoftERP | dContactBounce | dContactApprox1;
        const bool ground = dGeomGetClass(inGeom1) == dPlaneClass || dGeomGetClass(inGeom2) == dPlaneClass;
        contact.surface.mu = ground ? scene->mSettings.mGroundFriction : scene->mSettings.mFriction;
        contact.surface.bounce = scene->mSettings.mWorld.mRestitution;
        contact.surface.bounce_vel = scene->mSettings.mWorld.mRestingSpeed;
        contact.surface.soft_cfm = 1.0e-9;
        // A held prop body is put back where it stands after every step, over a car that pushed into it: error
        // reduction would push the two apart with velocity no impulse accounts for (Crumple's impulses then
        // said a quarter of what the car lost). Its contacts resolve velocities only, as Bullet's split
        // impulse does.
        const bool held = std::find(scene->mHeldBodies.begin(), scene->mHeldBodies.end(), b1) != scene->mHeldBodies.end() ||
                          std::find(scene->mHeldBodies.begin(), scene->mHeldBodies.end(), b2) != scene->mHeldBodies.end();
        // Elsewhere ODE pushes a penetration out at soft_erp x depth / step, and takes the larger of that and
        // the bounce as the contact's parting speed: a car that sank v h into a wall in its last step would
        // be pushed out at soft_erp v where Crumple bounces it at e v. With soft_erp at most e the push-out
        // of one step's sinking never outruns the bounce (a 10 km/h hit took 6.9 % more than Crumple's
        // impulse at 0.2; the ground keeps 0.2, where no impact is counted and a car must not sink).
        const double restitution = scene->mSettings.mWorld.mRestitution;
        contact.surface.soft_erp = held ? 0.0 : ground ? 0.2 : std::clamp(restitution, cMinWallErp, 0.2);
    }
    // The one extra call a game adds to its near callback, once the surfaces are set (it reads their mu).
    if (scene->mAdapter != nullptr)
        scene->mAdapter->OnCollide(inGeom1, inGeom2, std::span<const dContact>(contacts.data(), static_cast<std::size_t>(count)));
    for (int i = 0; i < count; ++i)
        dJointAttach(dJointCreateContact(scene->mWorld, scene->mContacts, &contacts[static_cast<std::size_t>(i)]), b1, b2);
}

Result<plugin::BodyId> OdeWallCrash::MakeDebrisBody(const plugin::ConvexBodySettings& inSettings)
{
    return mAdapter->CreateConvexBody(mWorld, mSpace, inSettings);
}

Result<plugin::BodyId> OdeWallCrash::MakePropBody(const plugin::PropBodySettings& inSettings)
{
    Result<plugin::BodyId> body = mAdapter->CreatePropBody(mWorld, mSpace, inSettings);
    if (body && inSettings.mHeld)
        mHeldBodies.push_back(mAdapter->GetConvexBody(body.Get()));
    return body;
}

Status OdeWallCrash::RemoveMadeBody(plugin::BodyId inBody)
{
    const dBodyID body = mAdapter->GetConvexBody(inBody);
    if (body == nullptr)
        return MakeError(EError::OutOfRange, "OdeWallCrash::RemoveMadeBody: body " +
                                                 std::to_string(inBody.mValue) + " is none the scene made");
    if (Status removed = mAdapter->RemoveBody(body); !removed)
        return removed; // the body stays, held as it was
    // intent: the adapter destroyed the body: the near callback must not take a body made later at the same
    // address for a held one (the list's pointers are compared, never followed)
    mHeldBodies.erase(std::remove(mHeldBodies.begin(), mHeldBodies.end(), body), mHeldBodies.end());
    return Status::Ok();
}

plugin::BodyState OdeWallCrash::GetCarState() const
{
    return ode::OdeBodyState(mCar);
}

void OdeWallCrash::SetCarVelocity(const Vec3& inLinear, const Vec3& inAngular)
{
    dBodySetLinearVel(mCar, inLinear.x(), inLinear.y(), inLinear.z());
    dBodySetAngularVel(mCar, inAngular.x(), inAngular.y(), inAngular.z());
}

void OdeWallCrash::Step()
{
    dSpaceCollide(mSpace, this, &OdeWallCrash::NearCallback);
    if (mHeldBodies.empty())
    {
        // intent: the quick step shuffles its constraints with ODE's process-wide random generator; seeded the
        // same before every step, a step depends on the scene's state alone (the same crash twice in one
        // process gives the same bits, whatever ran before it)
        dRandSetSeed(0);
        dWorldQuickStep(mWorld, mSettings.mTimeStep);
    }
    else
    {
        // intent: a held prop body (a fence the car breaks) keeps the Dantzig step its coupling was measured
        // with (issue 13): under the quick step the ODE car lost 2.8-3.5 m/s in PropFenceTest's fence where
        // Crumple's impulses say 2.2 and Bullet's car loses 2.36, and no piece came loose
        dWorldStep(mWorld, mSettings.mTimeStep);
    }
    if (mAdapter != nullptr)
        mAdapter->AfterStep(mSettings.mTimeStep);
    dJointGroupEmpty(mContacts);
}

EngineCrashResult OdeWallCrash::Run()
{
    return RunEngineCrash(*this, mSettings, mAdapter != nullptr);
}

} // namespace crumple::common
