// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "BoxImpulseWallCrash.h"
#include "BulletWallCrash.h"
#include "OdeWallCrash.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

using namespace crumple;
using namespace crumple::common;

// Crumple is meant for engines it has no adapter for: the game joins them through DamageWorld's three calls
// (docs/adapters.md). BoxImpulseEngine (tests/common) is such an engine, written apart from Bullet and ODE:
// its own contact generation, sequential impulses and split-impulse position correction. These tests hold it
// to what the two adapted engines are held to.

namespace
{

// Three ways an engine reports its contacts: a clipped manifold (Bullet's box-box), one point per body pair
// and step (the manifold's centroid at its mean depth, as an engine that reduces its manifolds reports it),
// and gaps of up to 5 cm reported ahead of the touch (a large speculative margin, whose hit the engine
// resolves whole in the step it predicts it, as Jolt and Box2D do).
std::vector<std::pair<std::string, BoxImpulseEngineSettings>> ContactReporting()
{
    return {{"clipped manifold", {}},
            {"one point per pair", {.mOnePointPerPair = true}},
            {"5 cm speculative margin", {.mContactMargin = 0.05}}};
}

// The deepest dent of the scene's target vehicle (m); 0 without one.
template <class Scene> double TargetDent(Scene& inScene)
{
    if (!inScene.GetTargetObject().IsValid())
        return 0.0;
    const ffd::FfdDeformer& target = inScene.GetDamage().GetObject(inScene.GetTargetObject())->GetDeformer();
    double deepest = 0.0;
    for (std::size_t v = 0; v < target.GetPositions().size(); ++v)
        deepest = std::max(deepest, (target.GetPositions()[v] - target.GetRestMesh().mPositions[v]).norm());
    return deepest;
}

} // namespace

TEST_CASE("A third engine: a car resting and sliding on its ground makes no collision and no dent",
          "[engines]")
{
    for (double km_h : {0.0, 20.0, 64.0})
    {
        EngineCrashSettings drive;
        drive.mDriveOnly = true;
        drive.mSpeed = km_h / 3.6;
        drive.mTriangles = 2000;
        REQUIRE(BoxImpulseWallCrash::Supports(drive));
        BoxImpulseWallCrash scene(drive);
        const double start_height = scene.GetCarState().mCenterOfMass.z();
        double height_change = 0.0;
        int contacts = 0;
        for (int step = 0; step < 72; ++step)
        {
            scene.Step();
            height_change =
                std::max(height_change, std::abs(scene.GetCarState().mCenterOfMass.z() - start_height));
            contacts += scene.GetLastContactCount();
        }
        scene.GetDamage().Flush();
        const EngineCrashResult result =
            SummarizeCrash(scene.GetDamage(), scene.GetCarObject(), scene.GetCounter().mCollisions,
                           scene.GetCounter().mTotalImpulse);
        INFO(km_h << " km/h: " << contacts << " ground contacts, height change " << height_change << " m, "
                  << result.mCollisions << " collisions, largest dent " << result.mMaxDent << " m");
        CHECK(contacts >= 4 * 72); // the car stood on its four bottom corners all along
        CHECK(scene.GetRefusedCalls() == 0);
        CHECK(height_change <= 0.002);
        CHECK(result.mCollisions == 0);
        CHECK(result.mMaxDent == 0.0);
    }
}

// The engine's own change of the car's momentum over the collision, against the impulses Crumple solved from
// the contacts the engine reported (as CrossEngineTest checks Bullet and ODE), with and without friction.
TEST_CASE("A third engine: a collision's impulse is the engine's change of the car's momentum within 3 %",
          "[engines]")
{
    for (const auto& [reports, engine_settings] : ContactReporting())
        for (double friction : {0.0, 0.5})
            for (double km_h : {20.0, 40.0, 56.0, 64.0})
                for (const auto& [name, settings] : ImpactMatrix(km_h, friction))
                {
                    BoxImpulseWallCrash scene(settings, engine_settings);
                    const int steps = static_cast<int>(std::lround(settings.mDuration / settings.mTimeStep));
                    std::vector<Vec3> velocity{
                        scene.GetCarState().mLinearVelocity}; // velocity[k]: after k steps
                    for (int i = 0; i < steps; ++i)
                    {
                        scene.Step();
                        velocity.push_back(scene.GetCarState().mLinearVelocity);
                    }
                    scene.GetDamage().Flush();
                    double first = 1.0e30, last = -1.0e30;
                    for (const plugin::Collision& collision : scene.GetCounter().mLog)
                        for (const plugin::CollisionContact& contact : collision.mContacts)
                        {
                            first = std::min(first, contact.mTime);
                            last = std::max(last, contact.mTime);
                        }
                    REQUIRE(first <= last);
                    const auto before = static_cast<std::size_t>(std::lround(first / settings.mTimeStep) - 1);
                    const auto after =
                        std::min(static_cast<std::size_t>(std::lround(last / settings.mTimeStep)),
                                 velocity.size() - 1);
                    const plugin::BodyId car = scene.GetDamage().GetObjectBody(scene.GetCarObject());
                    const Vec3 horizontal(1.0, 1.0, 0.0);
                    const Vec3 crumple = ImpulseOnBody(scene.GetCounter().mLog, car).cwiseProduct(horizontal);
                    const Vec3 engine =
                        (settings.mMass * (velocity[after] - velocity[before])).cwiseProduct(horizontal);
                    INFO(name << ", " << reports << ", friction " << friction << ": Crumple "
                              << crumple.transpose() << " N s, engine " << engine.transpose() << " N s");
                    CHECK(scene.GetRefusedCalls() == 0);
                    CHECK(engine.norm() > 0.0);
                    CHECK((crumple - engine).norm() <= 0.03 * engine.norm());
                }
}

// What the bodies lost is what they crushed: without friction (whose sliding work is not crush) the
// collisions' crush energy (Crumple's, from the impulses it solved) is the kinetic energy the engine took
// from the car and the car it struck, for every way of reporting contacts (measured: 0.13 % at most with a
// manifold, 0.05 % with the 5 cm margin, both into a parked car; 1.7 % for one point per pair at 20 km/h
// offset).
TEST_CASE("A third engine: the crush energy is the kinetic energy the engine took from the cars, within 2 %",
          "[engines]")
{
    for (const auto& [reports, engine_settings] : ContactReporting())
        for (double km_h : {20.0, 40.0, 56.0, 64.0})
            for (const auto& [name, settings] : ImpactMatrix(km_h, 0.0))
            {
                BoxImpulseWallCrash scene(settings, engine_settings);
                const double before = scene.KineticEnergy();
                const EngineCrashResult result = scene.Run();
                const double lost = before - scene.KineticEnergy();
                double crush_energy = 0.0;
                for (const plugin::Collision& collision : scene.GetCounter().mLog)
                    crush_energy += collision.mCrushEnergyA + collision.mCrushEnergyB;
                INFO(name << ", " << reports << ": the engine took " << lost
                          << " J from the cars, the collisions crushed with " << crush_energy
                          << " J; deepest dent " << result.mMaxDent << " m");
                CHECK(scene.GetRefusedCalls() == 0);
                CHECK(lost > 0.0);
                CHECK(std::abs(crush_energy - lost) <= 0.02 * lost);
            }
}

// Issue 11's engine independence, for an engine that is not Bullet or ODE. With a manifold or a large
// speculative margin the third engine's impact is Bullet's and ODE's, and so is its crush, the struck car's
// too: within 1 % (issue 11 asks 5 %; measured 0.64 % at most, the 45-degree wall with the 5 cm margin). With
// one point per pair the engine itself is another: its offset hit pushes the car at one point, turns it
// faster and takes less energy from it (40 km/h offset: 70.0 against 72.9 kJ, 1.02 against 0.36 rad/s), so
// there the crush follows the engine's energy (the check above) and stays within issue 11's 5 % (measured 2.9
// %). Each crush deepens with speed.
// Jolt, PhysX and Bullet's default build report their states in float. Through the same glue, the third
// engine's float states are taken (no call refused: before eac59a1 most were, for float round-off in the
// rotation and the inverse inertia) and crush as its double ones do.
TEST_CASE("A third engine in single precision: its float states are taken and crush as its double ones",
          "[engines]")
{
    for (double km_h : {20.0, 64.0})
        for (const auto& [name, settings] : ImpactMatrix(km_h, 0.5))
        {
            BoxImpulseWallCrash exact(settings);
            const EngineCrashResult double_run = exact.Run();
            BoxImpulseWallCrash single(settings, {.mSinglePrecision = true});
            const EngineCrashResult float_run = single.Run();
            INFO(name << ": " << float_run.mMaxDent << " m with float states, " << double_run.mMaxDent
                      << " m with double ones");
            CHECK(single.GetRefusedCalls() == 0);
            CHECK(float_run.mCollisions == double_run.mCollisions);
            CHECK(std::abs(float_run.mMaxDent - double_run.mMaxDent) <= 1.0e-3 * double_run.mMaxDent);
        }
}

TEST_CASE("A third engine crushes as Bullet and ODE do, and deeper at higher speed", "[engines][bullet][ode]")
{
    const std::vector<std::pair<std::string, BoxImpulseEngineSettings>> reporting = ContactReporting();
    std::vector<std::vector<std::vector<double>>> crush_by_speed(
        reporting.size()); // [reporting][crash][speed]
    for (double km_h : {20.0, 40.0, 56.0, 64.0})
    {
        const auto crashes = ImpactMatrix(km_h, 0.5);
        for (std::size_t c = 0; c < crashes.size(); ++c)
        {
            const auto& [name, settings] = crashes[c];
            BulletWallCrash bullet_scene(settings);
            const EngineCrashResult bullet = bullet_scene.Run();
            const double bullet_target = TargetDent(bullet_scene);
            OdeWallCrash ode_scene(settings);
            const EngineCrashResult ode = ode_scene.Run();
            const double ode_target = TargetDent(ode_scene);
            for (std::size_t r = 0; r < reporting.size(); ++r)
            {
                BoxImpulseWallCrash scene(settings, reporting[r].second);
                const EngineCrashResult third = scene.Run();
                const double third_target = TargetDent(scene);
                const double bound = reporting[r].second.mOnePointPerPair ? 0.05 : 0.01;
                INFO(name << ", " << reporting[r].first << ": third engine " << third.mMaxDent
                          << " m, Bullet " << bullet.mMaxDent << " m, ODE " << ode.mMaxDent
                          << " m; the struck car " << third_target << " / " << bullet_target << " / "
                          << ode_target << " m; dent centroids " << third.mDentCentroid.transpose() << " / "
                          << bullet.mDentCentroid.transpose() << " / " << ode.mDentCentroid.transpose());
                CHECK(scene.GetRefusedCalls() == 0);
                // a real crush (the 20 km/h side hit dents both cars 1 cm), not empty runs agreeing
                REQUIRE(std::max(third.mMaxDent, third_target) > 0.005);
                CHECK(std::abs(third_target - bullet_target) <=
                      bound * std::max(third_target, bullet_target));
                CHECK(std::abs(third_target - ode_target) <= bound * std::max(third_target, ode_target));
                CHECK(std::abs(third.mMaxDent - bullet.mMaxDent) <=
                      bound * std::max(third.mMaxDent, bullet.mMaxDent));
                CHECK(std::abs(third.mMaxDent - ode.mMaxDent) <=
                      bound * std::max(third.mMaxDent, ode.mMaxDent));
                CHECK((third.mDentCentroid - bullet.mDentCentroid).norm() <= 0.05);
                crush_by_speed[r].resize(crashes.size());
                crush_by_speed[r][c].push_back(third.mMaxDent);
            }
        }
    }
    for (std::size_t r = 0; r < reporting.size(); ++r)
        for (const std::vector<double>& crushes : crush_by_speed[r])
        {
            INFO(reporting[r].first << ": the crush at 20, 40, 56, 64 km/h " << crushes[0] << ", "
                                    << crushes[1] << ", " << crushes[2] << ", " << crushes[3] << " m");
            CHECK(std::is_sorted(crushes.begin(), crushes.end()));
            CHECK(crushes.front() < crushes.back());
        }
}
