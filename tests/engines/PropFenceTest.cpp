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

#include <algorithm>
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
    // Wood cracks; the same fence that cannot crack does not, and sheds nothing. Pieces that come loose and
    // become engine bodies are tested on a brittle facing (PropEngineTest.cpp): since the fence's fracture is
    // that of its converged solve (TetSolverSettings::mCrackStressTolerance), no piece of this fence comes
    // loose at 64 km/h at the scene's 120 Hz (the car passes it bent, one piece: the README's known limits).
    // Before, the Newton test stopped early in the hit and the links its error cracked (Bullet 1,228, ODE
    // 834) cut pieces loose.
    CHECK(wood.mBrokenLinks > 0);
    // Through it: the car keeps most of its speed (Bullet 15.29 of 17.78 m/s, ODE 15.49; a fence that held
    // the car back, as one put back at rest after every step did at 240 Hz, took 6.5-10 m/s) and ends past
    // the fence's face (x = 0-0.05 m) by more than its half length (Bullet's car ends at x = 6.95 m)
    CHECK(wood.mSpeedAfter > 0.7 * wood.mSpeedBefore);
    CHECK(wood.mCarX > 2.0);
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

// A restarted level: the fence is removed one step into the drive, before the car meets it (RemoveProp, the
// adapter's RemoveBody), and the same fence added again in its place meets the car as the first would have.
template <class Scene> void CheckRestartedFence(const char* inEngine)
{
    const double speed = 64.0 / 3.6;
    const FenceRun first = DriveThrough<Scene>(speed, true);
    const Result<FenceRun> restarted = DriveThroughFence<Scene>({.mSpeed = speed, .mRestartFenceAtStep = 1});
    INFO((restarted ? std::string() : restarted.GetError().mMessage));
    REQUIRE(restarted);
    const FenceRun& run = restarted.Get();
    INFO(inEngine << ", first fence: " << Describe(first));
    INFO(inEngine << ", fresh fence: " << Describe(run));
    CHECK(run.mRemovedBodies == 1); // the fence's body: no piece had come loose yet
    CHECK(run.mRemovedGone);
    CHECK(run.mPiecesAccepted);
    CHECK(run.mFenceMoved < 1.0e-6);
    CHECK(run.mBrokenLinks > 0);
    CHECK(run.mFenceImpulse > 0.0);
    CHECK(run.mBrokenLinks == first.mBrokenLinks);
    CHECK(run.mSpeedAfter == first.mSpeedAfter);
    CHECK(run.mFenceImpulse == first.mFenceImpulse);
}

} // namespace

TEST_CASE(
    "Bullet: a restarted level's fence is removed with its body, and a fresh one breaks as the first would "
    "have",
    "[bullet][props]")
{
    CheckRestartedFence<BulletWallCrash>("Bullet");
}

TEST_CASE(
    "ODE: a restarted level's fence is removed with its body, and a fresh one breaks as the first would have",
    "[ode][props]")
{
    CheckRestartedFence<OdeWallCrash>("ODE");
}

TEST_CASE("Bullet: a car breaks through a held wooden fence, whose shape follows its FEM", "[bullet][props]")
{
    CheckFence<BulletWallCrash>("Bullet");
}

TEST_CASE("ODE: a car breaks through a held wooden fence, whose shape follows its FEM", "[ode][props]")
{
    CheckFence<OdeWallCrash>("ODE");
}

TEST_CASE("Bullet and ODE: the same fence hit breaks the same links", "[bullet][ode][props]")
{
    // The engines meet different shapes of the same fence (Bullet: the hull of each 0.25 m piece; ODE: its
    // box) and report different contacts, but the links the FEM breaks are those of its converged solve
    // (mCrackStressTolerance), not of where its Newton test stopped. Measured (Bullet / ODE / in both / in
    // either): 64 km/h 220 / 179 / 178 / 221, 40 km/h 128 / 117 / 117 / 128: ODE's links are Bullet's but
    // one, and Bullet breaks a few more where its car touches the rails one step longer (the README's known
    // limits); 81 % and 91 % of the links that break in either break in both. With the Newton test alone
    // 381 of 1,681 and 148 of 1,477 (23 % and 10 %). Bounds: 70 % of the links in either break in both, and
    // 95 % of the fewer engine's links are the other's too.
    for (double speed : {64.0 / 3.6, 40.0 / 3.6})
    {
        const FenceRun bullet = DriveThrough<BulletWallCrash>(speed, true);
        const FenceRun ode = DriveThrough<OdeWallCrash>(speed, true);
        INFO("Bullet: " << Describe(bullet));
        INFO("ODE: " << Describe(ode));
        REQUIRE(bullet.mBroken.size() == ode.mBroken.size());
        int both = 0, either = 0;
        for (std::size_t link = 0; link < bullet.mBroken.size(); ++link)
        {
            both += bullet.mBroken[link] != 0 && ode.mBroken[link] != 0 ? 1 : 0;
            either += bullet.mBroken[link] != 0 || ode.mBroken[link] != 0 ? 1 : 0;
        }
        INFO("links broken in both " << both << ", in either " << either);
        REQUIRE(bullet.mBrokenLinks > 0);
        REQUIRE(ode.mBrokenLinks > 0);
        CHECK(both >= 0.70 * either);
        CHECK(both >= 0.95 * std::min(bullet.mBrokenLinks, ode.mBrokenLinks));
    }
}

TEST_CASE("Known limit: Bullet and ODE take the same speed from the car at the held fence",
          "[bullet][ode][props][!mayfail]")
{
    // Reported, not required, until the held prop's coupling is mended (README, known limits). The engines'
    // agreement sits at the 10 % bound and moves with any change of the friction solves' bits: the car lost
    // 2.547 m/s in Bullet and 2.285 in ODE (10.3 % apart) at 6bd527b, 2.479 and 2.284 (7.9 %) once the solve
    // let a contact go where its states could not all hold (773c7ed), 2.565 and 2.284 (11.0 %) once a
    // subspace step's Newton iterations were bounded, and 2.531 and 2.284 (9.8 %) once a stalled solve
    // stopped: on either side of the bound by chance, so it neither fails nor passes the suite. At the
    // scene's 120 Hz the car moves 15 cm a step into a 5 cm fence: the held body's shape never gets ahead of
    // it (the contacts reach 0.79 m deep), the car passes the fence bent but whole, and the engines lose the
    // rails' contact one step apart. At 240 Hz the held body stops the car instead (6.5 and 10.3 m/s lost).
    // This passed (2.39 and 2.29 m/s) while the Newton test's error cracked the fence apart, and failed with
    // that error and Bullet's ground as a box (3.13 and 2.29).
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
}

TEST_CASE("With the Newton test converged, the fence's cracks do not depend on the linear solver's tolerance",
          "[bullet][ode][props]")
{
    // With the Newton test relative to the step's energy alone (no crack stress bound, as before it existed)
    // the conjugate gradient's tolerance moved Bullet's fence from 1,017 to 4,536 broken links. Converged
    // (1e-8 of the step's energy scale) the answer is the solve's, not the iteration's: measured at CG 1e-6
    // and 1e-8, Bullet 216 and 215 links with the car losing 2.659 and 2.688 m/s, ODE 178 and 178 with 2.282
    // and 2.281 m/s. 1e-7 was enough while Crumple's impulses were frictionless (224 and 224); with friction
    // in the car's impulses it left Bullet at 218 and 238, and 1e-9 gives 216 and 215 again. A crack is a
    // threshold, so a link whose stress lies within the solves' difference may still flip: the bounds are 5 %
    // of the links and 2 % of the car's loss.
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
