// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// A wooden fence as a prop body in Bullet and in ODE: the adapter makes and holds its body, the car's
// contacts with it go through the engine and the damage world to its FEM, the pieces it sheds become
// engine bodies and leave its shape, and the car drives through with the speed a fence of that mass
// leaves it (a static body would stop it dead).
#include "BulletWallCrash.h"
#include "OdeWallCrash.h"

#include <crumple/fem/PropMaterialPreset.h>
#include <crumple/fem/TetFence.h>
#include <crumple/props/PropBody.h>
#include <crumple/props/PropWorld.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>

using namespace crumple;
using namespace crumple::common;
using namespace crumple::props;

namespace
{

constexpr double cCellSize = 0.025;  // the fence's cubes: two across each plank, so a bending plank shows tension
                                     // (fracture reads a cube's mean stress: one cube across a bent member reads none)
constexpr double cShapeSize = 0.25;  // its collision pieces: a few dozen cubes each, so the engines see dozens of pieces
constexpr double cMinBodyMass = 0.05; // kg: lighter splinters leave without a body
constexpr double cShapeTolerance = 0.01; // m: the engine's shape follows the FEM to a centimetre

// A 4 m wooden fence across the car's path: 5 cm planks, posts at y = -1.95, 0 and 1.95, two rails 0.1 m tall
// at 0.4 and 0.8 m, its face at x = 0 (the fence runs along +x in its own frame: turned a quarter about z).
fem::TetFenceSettings FenceSettings()
{
    fem::TetFenceSettings fence;
    fence.mLength = 4.0;
    fence.mHeight = 1.2;
    fence.mThickness = 0.05;
    fence.mCellSize = cCellSize;
    return fence;
}

Transform FencePose()
{
    Transform pose;
    pose.mRotation = Eigen::AngleAxisd(0.5 * M_PI, Vec3::UnitZ()).toRotationMatrix(); // fence x -> world y
    pose.mTranslation = Vec3(0.05, -2.0, 0.01); // fence y in [0, 0.05] -> world x in [0, 0.05]; just off the ground
    return pose;
}

struct FenceRun
{
    double mSpeedBefore = 0.0, mSpeedAfter = 0.0; ///< The car's speed along x (m/s)
    double mCarX = 0.0;
    double mCarZ = 0.0;                          ///< The car's centre at the end (m)
    double mFenceMoved = 0.0;                    ///< How far the held fence body ended from its pose (m)
    double mFenceImpulse = 0.0;                  ///< Crumple's impulse on the fence body, along +x (N s)
    double mFenceMass = 0.0;                     ///< kg
    int mBrokenLinks = 0;
    int mBodiesMade = 0;
    std::uint64_t mRevision = 0;
    std::size_t mPiecesBefore = 0, mPiecesAfter = 0;
    bool mPiecesAccepted = true;
    int mShapeChanges = 0;
    int mLoose = 0;              ///< Pieces handed over, with or without a body
    double mCarImpulse = 0.0;    ///< Crumple's impulses on the car over the run, along x (N s)
};

// inMatchVelocity: the held body is put back moving as fast as the planks the car struck (false: at rest).
template <class Scene>
FenceRun DriveThrough(double inSpeed, bool inBreakable, bool inMatchVelocity = true)
{
    EngineCrashSettings settings;
    settings.mDriveOnly = true;
    settings.mSpeed = inSpeed;
    settings.mDuration = 0.6;
    settings.mGap = 0.3;
    settings.mTriangles = 2000;
    Scene scene(settings);
    std::unique_ptr<PropWorld> props = PropWorld::Create(scene.GetDamage()).Get();

    const fem::TetFence fence = fem::MakeTetFence(FenceSettings()).Get();
    fem::PropMaterialPreset wood = fem::MakePropMaterialPreset(fem::EPropMaterial::Wood).Get();
    if (!inBreakable)
        wood.mMaterial.mTensileStrength = std::numeric_limits<double>::infinity();
    const PropBody made = MakePropBody(fence.mMesh, wood.mMaterial.mDensity, FencePose(), true, cShapeSize).Get();
    const Result<plugin::BodyId> created = scene.MakePropBody(made.mBody);
    REQUIRE(created);
    const plugin::BodyId fence_body = created.Get();
    fem::TetSolverSettings solver;
    solver.mGravity = Vec3::Zero(); // the held body stands for what holds the fence up
    FemProp prop = FemProp::Create(nullptr, made.mMesh, wood.mMaterial, solver, FemPropSettings{}).Get();
    for (int node : fence.mGroundNodes)
        REQUIRE(prop.SetNodeFixed(node, true));
    const PropId fence_prop = props->AddProp(fence_body, std::move(prop)).Get();
    REQUIRE(props->TakeChangedShape(fence_prop, cShapeSize, cShapeTolerance).Get()); // the first call gives the shape

    FenceRun run;
    run.mFenceMass = made.mBody.mMass;
    run.mPiecesBefore = made.mBody.mPieces.size();
    run.mSpeedBefore = scene.GetCarState().mLinearVelocity.x();
    const int steps = static_cast<int>(std::lround(settings.mDuration / settings.mTimeStep));
    for (int i = 0; i < steps; ++i)
    {
        scene.Step();
        REQUIRE(props->Step(settings.mTimeStep));
        if (inMatchVelocity)
            REQUIRE(scene.GetAdapter().SetHeldVelocity(fence_body, props->GetContactVelocity(fence_prop)));
        const std::vector<LooseFragment> loose = props->TakeLooseFragments(cMinBodyMass).Get(); // a local: Get() of a temporary dangles
        for (const LooseFragment& piece : loose)
        {
            ++run.mLoose;
            if (piece.mDropped)
                continue;
            Result<plugin::BodyId> body = scene.MakeDebrisBody(piece.mRigidBody.mBody);
            REQUIRE(body);
            ++run.mBodiesMade;
        }
        const std::optional<std::vector<std::vector<Vec3>>> shape = props->TakeChangedShape(fence_prop, cShapeSize, cShapeTolerance).Get();
        if (shape)
        {
            run.mPiecesAfter = shape->size();
            ++run.mShapeChanges;
            run.mPiecesAccepted = run.mPiecesAccepted && scene.GetAdapter().SetPropPieces(fence_body, *shape).IsValid();
        }
    }
    scene.GetDamage().Flush();
    const plugin::BodyState car = scene.GetCarState();
    run.mSpeedAfter = car.mLinearVelocity.x();
    run.mCarX = car.mCenterOfMass.x();
    run.mCarZ = car.mCenterOfMass.z();
    run.mFenceMoved = (scene.GetDamage().GetBodyState(fence_body)->mCenterOfMass - made.mBody.mPosition).norm();
    run.mFenceImpulse = ImpulseOnBody(scene.GetCounter().mLog, fence_body).x();
    run.mCarImpulse = ImpulseOnBody(scene.GetCounter().mLog, scene.GetDamage().GetObjectBody(scene.GetCarObject())).x();
    run.mBrokenLinks = props->GetProp(fence_prop)->GetCpuSolver()->GetBrokenLinkCount();
    run.mRevision = props->GetShapeRevision(fence_prop);
    return run;
}

std::string Describe(const FenceRun& inRun)
{
    return "speed " + std::to_string(inRun.mSpeedBefore) + " -> " + std::to_string(inRun.mSpeedAfter) + " m/s, car at x = " +
           std::to_string(inRun.mCarX) + " m, z = " + std::to_string(inRun.mCarZ) + " m; fence " + std::to_string(inRun.mFenceMass) + " kg took " +
           std::to_string(inRun.mFenceImpulse) + " N s, its body moved " + std::to_string(inRun.mFenceMoved) +
           " m; links broken " + std::to_string(inRun.mBrokenLinks) + ", pieces loose " + std::to_string(inRun.mLoose) +
           " (bodies " + std::to_string(inRun.mBodiesMade) + "), shape pieces " + std::to_string(inRun.mPiecesBefore) +
           " -> " + std::to_string(inRun.mPiecesAfter) + " over " + std::to_string(inRun.mShapeChanges) +
           " changes; Crumple's impulse on the car " + std::to_string(inRun.mCarImpulse) + " N s, its momentum change " +
           std::to_string(1200.0 * (inRun.mSpeedAfter - inRun.mSpeedBefore)) + " N s";
}

template <class Scene>
void CheckFence(const char* inEngine)
{
    const double speed = 64.0 / 3.6;
    const FenceRun wood = DriveThrough<Scene>(speed, true);
    const FenceRun unbreakable = DriveThrough<Scene>(speed, false);
    INFO(inEngine << ", wood: " << Describe(wood));
    INFO(inEngine << ", unbreakable: " << Describe(unbreakable));
    for (const FenceRun* run : {&wood, &unbreakable})
    {
        // The held body stays where it stands, takes impulses, and its shape follows its FEM.
        CHECK(run->mFenceMoved < 1.0e-6);
        CHECK(run->mFenceImpulse > 0.0);
        CHECK(run->mShapeChanges > 0);
        CHECK(run->mPiecesAccepted);
        CHECK(run->mSpeedAfter < run->mSpeedBefore);
    }
    // Wood cracks and sheds pieces that become engine bodies and leave its shape; the same fence that
    // cannot crack does neither.
    CHECK(wood.mBrokenLinks > 0);
    CHECK(wood.mLoose > 0);
    CHECK(wood.mBodiesMade > 0);
    CHECK(unbreakable.mBrokenLinks == 0);
    CHECK(unbreakable.mLoose == 0);
    // Put back at rest after every step, the fence met the car afresh at every step and took far more from it
    // (Bullet 13,090 against 2,830 N s, ODE 3,860 against 2,640): planks already moving at the car's speed
    // take no new impulse.
    const FenceRun at_rest = DriveThrough<Scene>(speed, true, false);
    INFO(inEngine << ", wood put back at rest: " << Describe(at_rest));
    CHECK(wood.mFenceImpulse < at_rest.mFenceImpulse);
    CHECK(wood.mSpeedAfter > at_rest.mSpeedAfter);
    // Not checked (README, known limits): how much of the car's speed each takes, and whether the engine
    // takes from the car what Crumple's impulses say. With the held body moving as fast as the planks the car
    // struck, along the strike (SetHeldVelocity from the next step on, GetContactVelocity), Bullet's car ends
    // at 15.39 m/s and loses 1.01 times what Crumple counts, ODE's at 15.49 m/s and 1.04 times; but the
    // held body still has the whole prop's mass in each contact, and how close the engine comes depends on
    // the scene's friction (Crumple's impulse is frictionless).
}

} // namespace

TEST_CASE("Bullet: a car breaks through a held wooden fence, whose shape follows its FEM", "[bullet][props]")
{
    CheckFence<BulletWallCrash>("Bullet");
}

TEST_CASE("ODE: a car breaks through a held wooden fence, whose shape follows its FEM", "[ode][props]")
{
    CheckFence<OdeWallCrash>("ODE");
}
