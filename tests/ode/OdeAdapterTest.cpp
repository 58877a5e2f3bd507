// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "HeldWall.h"
#include "OdeWallCrash.h"
#include "TurnedBlock.h"

#include <crumple/ode/OdeAdapter.h>

#include <catch2/catch.hpp>
#include "ScratchDirectory.h"

#include <crumple/base/FileBytes.h>
#include <crumple/plugin/DamageRecorder.h>
#include <crumple/plugin/ReplayDamage.h>

#include <filesystem>
#include <ode/ode.h>

#include <array>
#include <cmath>
#include <limits>

using namespace crumple;
using namespace crumple::plugin;
using namespace crumple::common;

namespace
{

// A sphere falling on a plane, with joint feedback on every contact joint to read ODE's own impulse.
struct DropScene
{
    DropScene()
    {
        dInitODE2(0);
        mWorld = dWorldCreate();
        dWorldSetGravity(mWorld, 0, 0, -9.81);
        mSpace = dHashSpaceCreate(nullptr);
        mJoints = dJointGroupCreate(0);
        dCreatePlane(mSpace, 0, 0, 1, 0);
        mSphere = dBodyCreate(mWorld);
        dMass mass;
        dMassSetSphereTotal(&mass, cMass, cRadius);
        dBodySetMass(mSphere, &mass);
        dBodySetPosition(mSphere, 0, 0, cRadius + cDrop);
        dGeomSetBody(dCreateSphere(mSpace, cRadius), mSphere);
    }
    ~DropScene()
    {
        dJointGroupDestroy(mJoints);
        dSpaceDestroy(mSpace);
        dWorldDestroy(mWorld);
        dCloseODE();
    }
    static void Near(void* inData, dGeomID inA, dGeomID inB)
    {
        auto* scene = static_cast<DropScene*>(inData);
        std::array<dContact, 4> contacts{};
        const int n = dCollide(inA, inB, 4, &contacts[0].geom, sizeof(dContact));
        std::array<dContactGeom, 4> geoms{};
        for (int i = 0; i < n; ++i)
            geoms[static_cast<std::size_t>(i)] = contacts[static_cast<std::size_t>(i)].geom;
        if (n > 0 && scene->mAdapter != nullptr)
            scene->mAdapter->OnCollide(inA, inB, std::span(geoms.data(), static_cast<std::size_t>(n)));
        for (int i = 0; i < n; ++i)
        {
            contacts[static_cast<std::size_t>(i)].surface.mode = 0;
            contacts[static_cast<std::size_t>(i)].surface.mu = 0.5;
            dJointID joint = dJointCreateContact(scene->mWorld, scene->mJoints, &contacts[static_cast<std::size_t>(i)]);
            dJointAttach(joint, dGeomGetBody(inA), dGeomGetBody(inB));
            scene->mFeedback.emplace_back();
            dJointSetFeedback(joint, &scene->mFeedback.back());
        }
    }
    // One step; returns the impulse ODE's contact joints applied to the sphere along +z (N s).
    double Step(double inTimeStep)
    {
        mFeedback.clear();
        mFeedback.reserve(64);
        dSpaceCollide(mSpace, this, &Near);
        dWorldStep(mWorld, inTimeStep);
        if (mAdapter != nullptr)
            mAdapter->AfterStep(inTimeStep);
        double impulse = 0.0;
        for (const dJointFeedback& f : mFeedback)
            impulse += std::abs(static_cast<double>(f.f1[2])) * inTimeStep; // force on the sphere over the step
        dJointGroupEmpty(mJoints);
        return impulse;
    }

    static constexpr double cMass = 2.0, cRadius = 0.5, cDrop = 1.25;
    dWorldID mWorld;
    dSpaceID mSpace;
    dJointGroupID mJoints;
    dBodyID mSphere;
    std::vector<dJointFeedback> mFeedback;
    ode::OdeAdapter* mAdapter = nullptr;
};

} // namespace

TEST_CASE("ODE: a sphere dropped on a plane gets (1+e) m v, and agrees with ODE's contact joints", "[ode]")
{
    DropScene scene;
    DamageWorldSettings settings;
    settings.mRestitution = 0.0; // ODE contacts without dContactBounce are plastic
    std::unique_ptr<DamageWorld> damage_owner = std::move(DamageWorld::Create(settings).Get());
    DamageWorld& damage = *damage_owner;
    std::unique_ptr<ode::OdeAdapter> adapter = std::move(ode::OdeAdapter::Create(damage).Get());
    scene.mAdapter = adapter.get();
    REQUIRE(adapter->AddBody(scene.mSphere));
    CHECK(adapter->AddBody(scene.mSphere).HasError());
    CrashCounter counter;
    damage.AddListener(&counter);

    const double dt = 1.0 / 240.0;
    double peak_ode = 0.0;
    for (int i = 0; i < 240; ++i)
        peak_ode = std::max(peak_ode, scene.Step(dt));
    damage.Flush();

    REQUIRE(counter.mCollisions >= 1);
    const Collision& impact = counter.mLog.front();
    const double v_fall = std::sqrt(2.0 * 9.81 * DropScene::cDrop);
    CHECK(impact.mBodyA == adapter->GetEnvironment()); // the plane has no body: the static environment
    CHECK(impact.TotalImpulse() == Approx(DropScene::cMass * v_fall).epsilon(0.02));
    // ODE's joints also cancel the impact step's gravity (m g dt) and its error reduction pushes the sphere
    // out of the plane at ERP x depth / dt: allow both, measured from the reported depth, and 1 %.
    double depth = 0.0;
    for (const CollisionContact& c : impact.mContacts)
        depth = std::max(depth, c.mPenetrationDepth);
    const double erp_push = DropScene::cMass * static_cast<double>(dWorldGetERP(scene.mWorld)) * depth / dt;
    INFO("ODE applied " << peak_ode << " N s, Crumple " << impact.TotalImpulse() << " N s, depth " << depth << " m");
    CHECK(std::abs(peak_ode - impact.TotalImpulse()) <= DropScene::cMass * 9.81 * dt + erp_push + 0.01 * impact.TotalImpulse());
}

TEST_CASE("ODE: a body the game removes from the damage world itself leaves the other bodies' damage on",
          "[ode]")
{
    // The drop scene with a second sphere beside the first; the game removes the second's damage body
    // (DamageWorld::RemoveBody, not the adapter's) before both land: its contacts with the plane named a dead
    // body, and the world refused each step's whole batch, the first sphere's landing with it.
    DropScene scene;
    DamageWorldSettings settings;
    settings.mRestitution = 0.0;
    std::unique_ptr<DamageWorld> damage_owner = std::move(DamageWorld::Create(settings).Get());
    DamageWorld& damage = *damage_owner;
    std::unique_ptr<ode::OdeAdapter> adapter = std::move(ode::OdeAdapter::Create(damage).Get());
    scene.mAdapter = adapter.get();
    dBodyID other = dBodyCreate(scene.mWorld);
    dMass mass;
    dMassSetSphereTotal(&mass, DropScene::cMass, DropScene::cRadius);
    dBodySetMass(other, &mass);
    dBodySetPosition(other, 3.0, 0.0, DropScene::cRadius + DropScene::cDrop);
    dGeomSetBody(dCreateSphere(scene.mSpace, DropScene::cRadius), other);
    const BodyId sphere_body = adapter->AddBody(scene.mSphere).Get();
    const BodyId other_body = adapter->AddBody(other).Get();
    REQUIRE(damage.RemoveBody(other_body));
    CrashCounter counter;
    damage.AddListener(&counter);
    int refused = 0;
    for (int i = 0; i < 240; ++i)
    {
        scene.Step(1.0 / 240.0);
        refused += adapter->GetLastStepStats().mContactsRefused;
    }
    damage.Flush();
    CHECK(refused == 0);
    REQUIRE(counter.mCollisions >= 1);
    CHECK(counter.mLog.front().mBodyB == sphere_body);
    const double v_fall = std::sqrt(2.0 * 9.81 * DropScene::cDrop);
    CHECK(counter.mLog.front().TotalImpulse() == Approx(DropScene::cMass * v_fall).epsilon(0.02));
    damage.RemoveListener(&counter);
}

TEST_CASE("ODE: the box car crash dents the front, head-on and at 30 degrees", "[ode]")
{
    for (double yaw : {0.0, 30.0})
    {
        EngineCrashSettings settings;
        settings.mYawDegrees = yaw;
        OdeWallCrash crash(settings);
        const EngineCrashResult result = crash.Run();
        INFO("yaw " << yaw << ": max dent " << result.mMaxDent << " m at " << result.mDentCentroid.transpose());
        CHECK(result.mCollisions >= 1);
        CHECK(result.mMaxDent > 0.1);
        CHECK(result.mDentCentroid.x() > 1.0);
        if (yaw > 0.0)
            CHECK(result.mDentCentroid.y() < -0.2);
    }
}

TEST_CASE("ODE: a car driving on flat ground gets no damage", "[ode]")
{
    EngineCrashSettings settings;
    settings.mDriveOnly = true;
    settings.mSpeed = 25.0;
    settings.mDuration = 1.0;
    settings.mMeasureAdapterTime = true;
    OdeWallCrash drive(settings);
    const EngineCrashResult result = drive.Run();
    CHECK(result.mMaxDent == 0.0);
    CHECK(drive.GetAdapter().GetLastStepStats().mContactsReported > 0);
    CHECK(drive.GetAdapter().GetLastStepStats().mBodiesSnapshotted == 1);
    // The adapter's own share of the step, on the game's thread: some, and far less than a step's 1/60 s.
    const double seconds = drive.GetAdapter().GetLastStepStats().mSeconds;
    CHECK(seconds > 0.0);
    CHECK(seconds < 1.0 / 60.0);
    // Unless asked for, the time is not measured (the clock is a system call): the same drive reports none.
    settings.mMeasureAdapterTime = false;
    OdeWallCrash unmeasured(settings);
    unmeasured.Run();
    CHECK(unmeasured.GetAdapter().GetLastStepStats().mContactsReported > 0);
    CHECK(unmeasured.GetAdapter().GetLastStepStats().mSeconds == 0.0);
}

TEST_CASE("ODE: the same crash twice gives bitwise identical meshes", "[ode][determinism]")
{
    EngineCrashSettings settings;
    settings.mYawDegrees = 30.0;
    const EngineCrashResult first = OdeWallCrash(settings).Run();
    const EngineCrashResult second = OdeWallCrash(settings).Run();
    // intent: a crash that dents (0.60 m at 30 degrees), so equal meshes are not two rest meshes
    REQUIRE(first.mMaxDent > 0.2);
    REQUIRE_FALSE(first.mDamage.empty());
    CHECK(first.mPositions == second.mPositions);
    CHECK(first.mDamage == second.mDamage);
}

TEST_CASE("ODE: a recorded crash replays headless to bitwise identical meshes", "[ode][replay]")
{
    const std::filesystem::path path = ScratchDirectory() / "ode-crash.crumple";
    EngineCrashSettings settings;
    settings.mYawDegrees = 30.0;
    OdeWallCrash crash(settings);
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

TEST_CASE("ODE: a convex body the adapter makes has the settings' mass, inertia, pose and velocities, and goes with RemoveBody",
          "[ode]")
{
    dInitODE2(0);
    dWorldID world = dWorldCreate();
    dSpaceID space = dHashSpaceCreate(nullptr);
    {
        std::unique_ptr<DamageWorld> damage_owner = std::move(DamageWorld::Create().Get());
        DamageWorld& damage = *damage_owner;
        std::unique_ptr<ode::OdeAdapter> adapter = std::move(ode::OdeAdapter::Create(damage).Get());

        // A 0.6 x 0.1 x 0.2 m, 12 kg block turned about an oblique axis, moving and spinning; its hull 0.02 m
        // above the centre of mass (the box geom sits where the points are).
        const ConvexBodySettings settings = TurnedBlock(0.02);
        const BodyId id = adapter->CreateConvexBody(world, space, settings).Get();
        dBodyID body = adapter->GetConvexBody(id);
        REQUIRE(body != nullptr);
        CHECK(adapter->FindBody(body) == id);
        CHECK(dSpaceGetNumGeoms(space) == 1);

        dMass mass;
        dBodyGetMass(body, &mass);
        CHECK(std::abs(mass.mass - settings.mMass) <= 1.0e-12 * settings.mMass);
        CHECK(std::abs(mass.c[0]) + std::abs(mass.c[1]) + std::abs(mass.c[2]) == 0.0);
        const Mat3 local = settings.mOrientation.transpose() * settings.WorldInertia() * settings.mOrientation;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                CHECK(std::abs(mass.I[4 * i + j] - local(i, j)) <= 1.0e-12 * local.norm());
        const dReal* position = dBodyGetPosition(body);
        const dReal* rotation = dBodyGetRotation(body);
        CHECK((Vec3(position[0], position[1], position[2]) - settings.mPosition).norm() <= 1.0e-12);
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                CHECK(std::abs(rotation[4 * i + j] - settings.mOrientation(i, j)) <= 1.0e-9);
        const dReal* v = dBodyGetLinearVel(body);
        const dReal* w = dBodyGetAngularVel(body);
        CHECK((Vec3(v[0], v[1], v[2]) - settings.mLinearVelocity).norm() <= 1.0e-12);
        CHECK((Vec3(w[0], w[1], w[2]) - settings.mAngularVelocity).norm() <= 1.0e-12);
        // The box geom bounds the points along the body axes, centred on them (0.02 m above the centre of mass).
        dGeomID geom = dSpaceGetGeom(space, 0);
        dVector3 lengths;
        dGeomBoxGetLengths(geom, lengths);
        CHECK(std::abs(lengths[0] - 0.6) <= 1.0e-12);
        CHECK(std::abs(lengths[2] - 0.2) <= 1.0e-12);
        const dReal* offset = dGeomGetOffsetPosition(geom);
        CHECK(std::abs(offset[2] - 0.02) <= 1.0e-12);
        REQUIRE(damage.GetBodyState(id) != nullptr);
        CHECK(std::abs(damage.GetBodyState(id)->mMass - settings.mMass) <= 1.0e-12 * settings.mMass);

        // Bad settings are refused and add nothing; RemoveBody destroys body and geom.
        ConvexBodySettings heavy = settings;
        heavy.mMass = std::numeric_limits<double>::quiet_NaN();
        CHECK_FALSE(adapter->CreateConvexBody(world, space, heavy));
        CHECK_FALSE(adapter->CreateConvexBody(nullptr, space, settings));
        CHECK(dSpaceGetNumGeoms(space) == 1);
        REQUIRE(adapter->RemoveBody(body));
        CHECK(adapter->GetConvexBody(id) == nullptr);
        CHECK(damage.GetBodyState(id) == nullptr);
        CHECK(dSpaceGetNumGeoms(space) == 0);
        // One left for the adapter's destructor.
        REQUIRE(adapter->CreateConvexBody(world, space, settings));
        adapter.reset();
        CHECK(dSpaceGetNumGeoms(space) == 0);
    }
    dSpaceDestroy(space);
    dWorldDestroy(world);
    dCloseODE();
}

TEST_CASE("ODE: a held prop body stays at its pose without gravity, and its pieces can be replaced", "[ode][props]")
{
    dInitODE2(0);
    dWorldID world = dWorldCreate();
    dWorldSetGravity(world, 0.0, 0.0, -9.81);
    dSpaceID space = dHashSpaceCreate(nullptr);
    {
        std::unique_ptr<DamageWorld> damage_owner = std::move(DamageWorld::Create().Get());
        DamageWorld& damage = *damage_owner;
        std::unique_ptr<ode::OdeAdapter> adapter = std::move(ode::OdeAdapter::Create(damage).Get());
        const PropBodySettings settings = TurnedSlab();
        const BodyId id = adapter->CreatePropBody(world, space, settings).Get();
        dBodyID body = adapter->GetConvexBody(id);
        REQUIRE(body != nullptr);
        CHECK(dSpaceGetNumGeoms(space) == 2);
        CHECK(dBodyGetGravityMode(body) == 0);

        // Pushed, it is back at its pose, at rest, after every step.
        for (int step = 0; step < 20; ++step)
        {
            dBodySetLinearVel(body, 3.0, -1.0, 2.0);
            dBodySetAngularVel(body, 0.0, 4.0, 0.0);
            dWorldStep(world, 1.0 / 60.0);
            adapter->AfterStep(1.0 / 60.0);
            const dReal* position = dBodyGetPosition(body);
            CHECK((Vec3(position[0], position[1], position[2]) - settings.mPosition).norm() <= 1.0e-12);
            const dReal* v = dBodyGetLinearVel(body);
            const dReal* w = dBodyGetAngularVel(body);
            CHECK(Vec3(v[0], v[1], v[2]).norm() + Vec3(w[0], w[1], w[2]).norm() == 0.0);
        }

        // Given the velocity of the material a car struck, it is back at its pose moving so; refused, changing
        // nothing, for a body that is not held or a velocity that is not finite.
        const Vec3 struck(4.0, 0.5, 0.0);
        REQUIRE(adapter->SetHeldVelocity(id, struck));
        for (int step = 0; step < 3; ++step)
        {
            dWorldStep(world, 1.0 / 60.0);
            adapter->AfterStep(1.0 / 60.0);
            const dReal* position = dBodyGetPosition(body);
            CHECK((Vec3(position[0], position[1], position[2]) - settings.mPosition).norm() <= 1.0e-12);
            const dReal* v = dBodyGetLinearVel(body);
            CHECK((Vec3(v[0], v[1], v[2]) - struck).norm() == 0.0);
        }
        CHECK(adapter->SetHeldVelocity(id, Vec3(std::nan(""), 0.0, 0.0)).GetError().mCode == EError::NonFinite);
        CHECK(adapter->SetHeldVelocity(id, Vec3(2.0e6, 0.0, 0.0)).GetError().mCode == EError::OutOfRange);
        CHECK(adapter->SetHeldVelocity(BodyId{}, struck).GetError().mCode == EError::OutOfRange);
        REQUIRE(adapter->SetHeldVelocity(id, Vec3::Zero()));

        // New pieces replace the geoms; bad ones, and bodies that are not prop bodies, are refused.
        PropBodySettings one = settings;
        one.mPieces.pop_back();
        REQUIRE(adapter->SetPropPieces(id, one.mPieces));
        CHECK(dSpaceGetNumGeoms(space) == 1);
        CHECK(adapter->SetPropPieces(id, {}).HasError());
        CHECK(dSpaceGetNumGeoms(space) == 1);
        const BodyId debris = adapter->CreateConvexBody(world, space, TurnedBlock()).Get();
        CHECK(adapter->SetPropPieces(debris, one.mPieces).GetError().mCode == EError::OutOfRange);
        CHECK(adapter->CreatePropBody(nullptr, space, settings).HasError());
        CHECK(dSpaceGetNumGeoms(space) == 2);

        // A free prop body falls; the adapter's destructor destroys what it made.
        const BodyId free = adapter->CreatePropBody(world, space, TurnedSlab(false)).Get();
        CHECK(adapter->IsHeldPropBody(id)); // what props::HeldPropEngine::mIsHeld asks
        CHECK_FALSE(adapter->IsHeldPropBody(free));
        CHECK_FALSE(adapter->IsHeldPropBody(BodyId{}));
        for (int step = 0; step < 10; ++step)
        {
            dWorldStep(world, 1.0 / 60.0);
            adapter->AfterStep(1.0 / 60.0);
        }
        CHECK(dBodyGetLinearVel(adapter->GetConvexBody(free))[2] < -1.0);
        adapter.reset();
        CHECK(dSpaceGetNumGeoms(space) == 0);
    }
    dSpaceDestroy(space);
    dWorldDestroy(world);
    dCloseODE();
}

namespace
{

// A ball touching a held wall (1 mm in) at height inY, frictionless and without bounce: the impulse it takes
// in one dWorldStep of 1/120 s, and the mass the damage world saw the wall with. inContactMass: SetHeldMass's
// argument (0: none given).
struct WallBallScene
{
    static void Near(void* inData, dGeomID inA, dGeomID inB)
    {
        auto* scene = static_cast<WallBallScene*>(inData);
        std::array<dContact, 8> contacts{};
        const int n = dCollide(inA, inB, 8, &contacts[0].geom, sizeof(dContact));
        for (int i = 0; i < n; ++i)
            contacts[static_cast<std::size_t>(i)].surface.mode = dContactApprox1_1;
        scene->mAdapter->OnCollide(inA, inB,
                                   std::span<const dContact>(contacts.data(), static_cast<std::size_t>(n)));
        for (int i = 0; i < n; ++i)
            dJointAttach(
                dJointCreateContact(scene->mWorld, scene->mJoints, &contacts[static_cast<std::size_t>(i)]),
                dGeomGetBody(inA), dGeomGetBody(inB));
    }
    dWorldID mWorld = nullptr;
    dJointGroupID mJoints = nullptr;
    ode::OdeAdapter* mAdapter = nullptr;
};

double BallImpulseInOneStep(double inY, double inContactMass, double& outWallMassSeen)
{
    dInitODE2(0);
    WallBallScene scene;
    scene.mWorld = dWorldCreate();
    dSpaceID space = dHashSpaceCreate(nullptr);
    scene.mJoints = dJointGroupCreate(0);
    double impulse = 0.0;
    {
        std::unique_ptr<DamageWorld> damage = std::move(DamageWorld::Create().Get());
        std::unique_ptr<ode::OdeAdapter> adapter = std::move(ode::OdeAdapter::Create(*damage).Get());
        scene.mAdapter = adapter.get();
        const BodyId wall = adapter->CreatePropBody(scene.mWorld, space, HeldWall()).Get();
        ConvexBodySettings ball_settings = WallBall(inY);
        ball_settings.mPosition.x() = -0.05 - 0.1 + 0.001;
        const BodyId ball = adapter->CreateConvexBody(scene.mWorld, space, ball_settings).Get();
        if (inContactMass > 0.0)
            REQUIRE(adapter->SetHeldMass(wall, inContactMass));
        dSpaceCollide(space, &scene, &WallBallScene::Near);
        dWorldStep(scene.mWorld, 1.0 / 120.0);
        adapter->AfterStep(1.0 / 120.0);
        dJointGroupEmpty(scene.mJoints);
        outWallMassSeen = damage->GetBodyState(wall)->mMass;
        impulse = WallBallImpulse(dBodyGetLinearVel(adapter->GetConvexBody(ball))[0]);
    }
    dJointGroupDestroy(scene.mJoints);
    dSpaceDestroy(space);
    dWorldDestroy(scene.mWorld);
    dCloseODE();
    return impulse;
}

} // namespace

TEST_CASE("ODE: a held prop body given a contact mass meets a blow anywhere as a point mass of it",
          "[ode][props]")
{
    constexpr double cContactMass = 10.0; // kg
    double seen = 0.0;
    // As made (50 kg, turning), a blow 1.5 m from the centre meets 1 / (1/m + r^2 / I_z) = 18.6 kg; impulses
    // go as the reduced masses (ODE's push out of the 1 mm adds the same to every approach).
    const double own_inertia_z = HeldWall().mPrincipalInertia.z();
    const double off_centre_mass = 1.0 / (1.0 / 50.0 + 1.5 * 1.5 / own_inertia_z);
    const double own_centre = BallImpulseInOneStep(0.0, 0.0, seen);
    CHECK(seen == Approx(50.0).epsilon(1e-9));
    const double own_off_centre = BallImpulseInOneStep(1.5, 0.0, seen);
    CHECK(own_off_centre / own_centre ==
          Approx(WallBallReducedMass(off_centre_mass) / WallBallReducedMass(50.0)).epsilon(0.01));
    // Given 10 kg: the same 10 kg at the centre and off it (within the 1 % ODE's finite inertia leaves), in
    // the engine and in the damage world.
    const double given_centre = BallImpulseInOneStep(0.0, cContactMass, seen);
    CHECK(seen == Approx(cContactMass).epsilon(1e-9));
    const double given_off_centre = BallImpulseInOneStep(1.5, cContactMass, seen);
    CHECK(seen == Approx(cContactMass).epsilon(1e-9));
    CHECK(given_centre / own_centre ==
          Approx(WallBallReducedMass(cContactMass) / WallBallReducedMass(50.0)).epsilon(0.01));
    CHECK(given_off_centre == Approx(given_centre).epsilon(0.01));

    // 0 gives the body its own mass and inertia back; bad masses and bodies that are not held are refused,
    // changing nothing.
    dInitODE2(0);
    dWorldID world = dWorldCreate();
    dSpaceID space = dHashSpaceCreate(nullptr);
    {
        std::unique_ptr<DamageWorld> damage = std::move(DamageWorld::Create().Get());
        std::unique_ptr<ode::OdeAdapter> adapter = std::move(ode::OdeAdapter::Create(*damage).Get());
        const BodyId wall = adapter->CreatePropBody(world, space, HeldWall()).Get();
        dBodyID body = adapter->GetConvexBody(wall);
        const auto mass_of = [body]
        {
            dMass mass;
            dBodyGetMass(body, &mass);
            return mass;
        };
        REQUIRE(adapter->SetHeldMass(wall, cContactMass));
        CHECK(mass_of().mass == cContactMass);
        // 100 R^2 per kilogram, R^2 the body's own (I_x + I_y + I_z) / m
        const double radius_squared = HeldWall().mPrincipalInertia.sum() / 50.0;
        CHECK(mass_of().I[0] == Approx(cContactMass * 100.0 * radius_squared).epsilon(1e-12));
        CHECK(adapter->SetHeldMass(wall, -1.0).GetError().mCode == EError::OutOfRange);
        CHECK(adapter->SetHeldMass(wall, 2.0e12).GetError().mCode == EError::OutOfRange);
        CHECK(adapter->SetHeldMass(wall, std::nan("")).GetError().mCode == EError::NonFinite);
        const BodyId free_body = adapter->CreateConvexBody(world, space, WallBall(0.0)).Get();
        CHECK(adapter->SetHeldMass(free_body, 1.0).GetError().mCode == EError::OutOfRange);
        CHECK(adapter->SetHeldMass(BodyId{}, 1.0).GetError().mCode == EError::OutOfRange);
        CHECK(mass_of().mass == cContactMass);
        REQUIRE(adapter->SetHeldMass(wall, 0.0));
        CHECK(mass_of().mass == 50.0);
        CHECK(mass_of().I[0] == HeldWall().mPrincipalInertia.x());
        CHECK(mass_of().I[5] == HeldWall().mPrincipalInertia.y());
        CHECK(mass_of().I[10] == HeldWall().mPrincipalInertia.z());
    }
    dSpaceDestroy(space);
    dWorldDestroy(world);
    dCloseODE();
}

TEST_CASE("ODE: a body state carries its geoms' bounds in its frame, a plane's out to the state's range", "[ode]")
{
    dInitODE();
    dWorldID world = dWorldCreate();
    dSpaceID space = dHashSpaceCreate(nullptr);
    // A body turned about z with a 2 x 4 x 6 m box offset 1 m along its own x: exact bounds in the body frame.
    dBodyID body = dBodyCreate(world);
    dMatrix3 turn;
    dRFromAxisAndAngle(turn, 0, 0, 1, 0.7);
    dBodySetRotation(body, turn);
    dBodySetPosition(body, 5, -3, 2);
    dMass mass;
    dMassSetBoxTotal(&mass, 10, 2, 4, 6);
    dBodySetMass(body, &mass);
    dGeomID box = dCreateBox(space, 2, 4, 6);
    dGeomSetBody(box, body);
    dGeomSetOffsetPosition(box, 1, 0, 0);
    const BodyState state = ode::OdeBodyState(body);
    REQUIRE(state.mHasShapeBounds);
    CHECK(state.mShapeMin.isApprox(Vec3(0, -2, -3), 1.0e-9));
    CHECK(state.mShapeMax.isApprox(Vec3(2, 2, 3), 1.0e-9));
    CHECK(ValidateBodyState(state));
    // A static box geom: its bounds in its own frame; a plane: the state's range.
    dGeomID wall = dCreateBox(space, 2, 10, 6);
    dGeomSetPosition(wall, 1, 2, 3);
    dGeomSetRotation(wall, turn);
    const BodyState wall_state = ode::OdeStaticGeomState(wall);
    REQUIRE(wall_state.mHasShapeBounds);
    CHECK(wall_state.mShapeMin.isApprox(Vec3(-1, -5, -3), 1.0e-9));
    CHECK(wall_state.mShapeMax.isApprox(Vec3(1, 5, 3), 1.0e-9));
    const BodyState plane_state = ode::OdeStaticGeomState(dCreatePlane(space, 0, 0, 1, 0));
    REQUIRE(plane_state.mHasShapeBounds);
    CHECK(plane_state.mShapeMax.x() == cMaxBodyPosition);
    CHECK(ValidateBodyState(plane_state));
    dSpaceDestroy(space);
    dWorldDestroy(world);
    dCloseODE();
}
