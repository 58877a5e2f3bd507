// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// A wooden fence as a prop body in Bullet and in ODE: the adapter makes and holds its body, the car's
// contacts with it go through the engine and the damage world to its FEM, the pieces it sheds become
// engine bodies and leave its shape, and the car drives through with the speed a fence of that mass
// leaves it (a static body would stop it dead).
#include "BulletWallCrash.h"
#include "FenceDriveThrough.h"
#include "OdeWallCrash.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>

using namespace crumple;
using namespace crumple::common;
using namespace crumple::props;

namespace
{

// inMatchVelocity: the held body is put back moving as fast as the planks the car struck (false: at rest).
template <class Scene>
FenceRun DriveThrough(double inSpeed, bool inBreakable, bool inMatchVelocity = true)
{
    const Result<FenceRun> run =
        DriveThroughFence<Scene>({.mSpeed = inSpeed, .mBreakable = inBreakable, .mMatchVelocity = inMatchVelocity});
    INFO((run ? std::string() : run.GetError().mMessage));
    REQUIRE(run);
    REQUIRE(run.Get().mFirstShapeGiven); // the first TakeChangedShape always gives the shape
    return run.Get();
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
    // at 15.43 m/s and loses 0.99 times what Crumple counts, ODE's at 15.49 m/s and 1.04 times; but the
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

TEST_CASE("Bullet and ODE: the same fence hit takes the same from the car", "[bullet][ode][props]")
{
    // The engines meet different shapes of the same fence (Bullet: the hull of each 0.25 m piece; ODE: its
    // box, which is larger) and different friction models, so the contacts differ step by step; what the
    // car loses and what the fence takes must still agree. Measured: the car's loss 2.39 (Bullet) and 2.29
    // m/s (ODE), 4 % apart; the fence's impulse 2,830 and 2,638 N s, 7 % apart. Bounds: 10 % and 15 %.
    const double speed = 64.0 / 3.6;
    const FenceRun bullet = DriveThrough<BulletWallCrash>(speed, true);
    const FenceRun ode = DriveThrough<OdeWallCrash>(speed, true);
    INFO("Bullet: " << Describe(bullet));
    INFO("ODE: " << Describe(ode));
    const double bullet_loss = bullet.mSpeedBefore - bullet.mSpeedAfter;
    const double ode_loss = ode.mSpeedBefore - ode.mSpeedAfter;
    REQUIRE(bullet_loss > 0.0);
    REQUIRE(ode_loss > 0.0);
    CHECK(std::abs(bullet_loss - ode_loss) <= 0.10 * std::max(bullet_loss, ode_loss));
    CHECK(std::abs(bullet.mFenceImpulse - ode.mFenceImpulse) <= 0.15 * std::max(bullet.mFenceImpulse, ode.mFenceImpulse));
    // Both break it; how many links differs with the contacts (the README's known limits).
    CHECK(bullet.mBrokenLinks > 0);
    CHECK(ode.mBrokenLinks > 0);
}

TEST_CASE("With the Newton test converged, the fence's cracks do not depend on the linear solver's tolerance",
          "[bullet][ode][props]")
{
    // The shipped Newton test is loose during a hit (README, known limits), and at it the conjugate gradient's
    // tolerance alone moves Bullet's fence from 1,017 to 4,536 broken links. Converged (1e-8 of the step's
    // energy scale) the answer is the solve's, not the iteration's: measured at CG 1e-6 and 1e-8, Bullet 216
    // and 215 links with the car losing 2.659 and 2.688 m/s, ODE 178 and 178 with 2.282 and 2.281 m/s. 1e-7
    // was enough while Crumple's impulses were frictionless (224 and 224); with friction in the car's
    // impulses it left Bullet at 218 and 238, and 1e-9 gives 216 and 215 again. A crack is a threshold, so a
    // link whose stress lies within the solves' difference may still flip: the bounds are 5 % of the links
    // and 2 % of the car's loss.
    const double speed = 64.0 / 3.6;
    const auto run = [&]<class Scene>(double inCgTolerance) {
        common::FenceDriveSettings settings;
        settings.mSpeed = speed;
        settings.mSolver.mImplicitTolerance = 1.0e-8;
        settings.mSolver.mCgRelativeTolerance = inCgTolerance;
        const Result<FenceRun> result = DriveThroughFence<Scene>(settings);
        INFO((result ? std::string() : result.GetError().mMessage));
        REQUIRE(result);
        return result.Get();
    };
    const auto check = [&](const char* inEngine, const FenceRun& inLoose, const FenceRun& inTight) {
        INFO(inEngine << ", CG 1e-6: " << Describe(inLoose));
        INFO(inEngine << ", CG 1e-8: " << Describe(inTight));
        REQUIRE(inLoose.mBrokenLinks > 0);
        REQUIRE(inTight.mBrokenLinks > 0);
        CHECK(std::abs(inLoose.mBrokenLinks - inTight.mBrokenLinks) <= 0.05 * std::max(inLoose.mBrokenLinks, inTight.mBrokenLinks));
        const double loose_loss = inLoose.mSpeedBefore - inLoose.mSpeedAfter;
        const double tight_loss = inTight.mSpeedBefore - inTight.mSpeedAfter;
        CHECK(std::abs(loose_loss - tight_loss) <= 0.02 * std::max(loose_loss, tight_loss));
    };
    check("Bullet", run.template operator()<BulletWallCrash>(1.0e-6), run.template operator()<BulletWallCrash>(1.0e-8));
    check("ODE", run.template operator()<OdeWallCrash>(1.0e-6), run.template operator()<OdeWallCrash>(1.0e-8));
}
