// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "BulletWallCrash.h"
#include "OdeWallCrash.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

using namespace crumple;
using namespace crumple::common;

TEST_CASE("The same crash in Bullet and ODE dents as deep, in the same place", "[bullet][ode]")
{
    for (double yaw : {0.0, 30.0})
    {
        EngineCrashSettings settings;
        settings.mYawDegrees = yaw;
        const EngineCrashResult bullet = BulletWallCrash(settings).Run();
        const EngineCrashResult ode = OdeWallCrash(settings).Run();
        INFO("yaw " << yaw << ": Bullet " << bullet.mMaxDent << " m at " << bullet.mDentCentroid.transpose() << ", ODE "
                    << ode.mMaxDent << " m at " << ode.mDentCentroid.transpose() << "; impulses " << bullet.mTotalImpulse
                    << " / " << ode.mTotalImpulse << " N s");
        // intent: both dent (measured 0.43 m head-on, 0.60 m at 30 degrees); depths within 1 % (the bound
        // ThirdEngineTest asks of every engine pair; measured 0.004 % and 0.05 %), the dents' centroids
        // within 2 cm (measured under 1 mm)
        REQUIRE(std::min(bullet.mMaxDent, ode.mMaxDent) > 0.2);
        CHECK(std::abs(bullet.mMaxDent - ode.mMaxDent) <= 0.01 * std::max(bullet.mMaxDent, ode.mMaxDent));
        CHECK((bullet.mDentCentroid - ode.mDentCentroid).norm() <= 0.02);
    }
}

namespace
{

// The crashes of the momentum and crush checks (ImpactMatrix) at 20-64 km/h. Glancing at 45 degrees, ODE's
// Dantzig step gave 11-19 % less than Coulomb's impulse; the scene takes its quick step.
std::vector<std::pair<std::string, EngineCrashSettings>> MomentumCrashes(double inFriction)
{
    std::vector<std::pair<std::string, EngineCrashSettings>> crashes;
    for (double km_h : {20.0, 40.0, 56.0, 64.0})
        for (auto& crash : ImpactMatrix(km_h, inFriction))
            crashes.push_back(std::move(crash));
    return crashes;
}

// Crumple's impulse on the car over its collisions, and the engine's change of the car's momentum from the
// step before the first of their contacts to the step after the last (later resting contact, such as two
// cars left pressed together, pushes them without an impact and is not part of the collision).
template <class Scene>
std::pair<Vec3, Vec3> ImpulseAndMomentumChange(const EngineCrashSettings& inSettings)
{
    Scene scene(inSettings);
    const int steps = static_cast<int>(std::lround(inSettings.mDuration / inSettings.mTimeStep));
    std::vector<Vec3> velocity{scene.GetCarState().mLinearVelocity}; // velocity[k]: after k steps
    for (int i = 0; i < steps; ++i)
    {
        scene.Step();
        velocity.push_back(scene.GetCarState().mLinearVelocity);
    }
    scene.GetDamage().Flush();
    const plugin::BodyId car = scene.GetDamage().GetObjectBody(scene.GetCarObject());
    double first = 1.0e30, last = -1.0e30;
    for (const plugin::Collision& collision : scene.GetCounter().mLog)
        if (collision.mBodyA == car || collision.mBodyB == car)
            for (const plugin::CollisionContact& contact : collision.mContacts)
            {
                first = std::min(first, contact.mTime);
                last = std::max(last, contact.mTime);
            }
    if (first > last)
        return {Vec3::Zero(), Vec3::Zero()};
    // A contact of time t was reported by step round(t / dt) (the time at its end).
    const auto before = static_cast<std::size_t>(std::lround(first / inSettings.mTimeStep) - 1);
    const auto after = static_cast<std::size_t>(std::lround(last / inSettings.mTimeStep));
    return {ImpulseOnBody(scene.GetCounter().mLog, car),
            inSettings.mMass * (velocity[std::min(after, velocity.size() - 1)] - velocity[before])};
}

// Crumple's impulse on the car against the engine's change of its momentum, horizontally, for each crash:
// within 3 % of the engine's, or within inKnownLimit's bound for a crash it names.
template <class Scene>
void CheckImpulseIsMomentumChange(const std::string& inEngine, double inFriction,
                                  const std::map<std::string, double>& inKnownLimit = {})
{
    for (const auto& [name, settings] : MomentumCrashes(inFriction))
    {
        const auto known = inKnownLimit.find(name);
        const double bound = known == inKnownLimit.end() ? 0.03 : known->second;
        const std::pair<Vec3, Vec3> run = ImpulseAndMomentumChange<Scene>(settings);
        const Vec3 horizontal(1.0, 1.0, 0.0);
        const Vec3 crumple = run.first.cwiseProduct(horizontal);
        const Vec3 engine = run.second.cwiseProduct(horizontal);
        INFO(name << " " << inEngine << ", friction " << inFriction << ": Crumple " << crumple.transpose() << " N s, engine "
                  << engine.transpose() << " N s");
        CHECK(engine.norm() > 0.0);
        CHECK((crumple - engine).norm() <= bound * engine.norm());
    }
}

} // namespace

// The engines bounce as Crumple's impulses assume (the scenes set their restitution from
// DamageWorldSettings::mRestitution and cap ODE's penetration push-out), and Crumple counts an impact once
// however many steps the engine takes to stop the car. With friction Crumple's impulse carries the engine's
// coefficient (ContactEvent::mFriction) and stops or slows the contacts' slip (FrictionalImpulses): the car's
// sideways momentum after an offset, angled or corner hit is then the engine's too.
TEST_CASE("A collision's impulse is the engine's change of the car's momentum within 3 %, in Bullet and ODE", "[bullet][ode]")
{
    CheckImpulseIsMomentumChange<BulletWallCrash>("Bullet", 0.0);
    CheckImpulseIsMomentumChange<OdeWallCrash>("ODE", 0.0);
    CheckImpulseIsMomentumChange<OdeWallCrash>("ODE", 0.5);
}

// Bullet with friction: 27 of the 28 crashes agree within 3 % since the scene gives Bullet's contacts two
// fixed friction tangents (SOLVER_USE_2_FRICTION_DIRECTIONS, ODE's pyramid; 25 of 28 with Bullet's default
// single tangent, the slip's direction when the contact appeared: a car that yaws against the wall after an
// offset or corner hit slid across it, sideways 133 N s where Crumple's impulse takes 449 N s and ODE's
// engine 448 N s at 20 km/h offset, 339 against 531 N s at 20 km/h into a corner, 641 against 1,067 N s at
// 40 km/h into a corner). The one left: the 40 km/h 40 % offset hit takes 1,451 N s sideways in Bullet
// against Crumple's 903 and ODE's 897, with the same pyramid. That is Bullet's solver stopping at its default
// 10 iterations: with 50 or more it takes 900 N s. Converged (100 and 200 iterations) Bullet takes 4.2 % more
// than Crumple at the 20 km/h 45-degree wall (6,367 against 6,111 N s along x), where ODE agrees with
// Crumple to 0.1 %; 30 iterations pass all 28, unconverged. No count passes for the right reason, so the
// scene keeps Bullet's default (measured in a scratch build of this test). That crash is held to 4 % (its
// difference is 3.5 % of the impulse: 510 of 14,658 N s), every other one to 3 %.
TEST_CASE(
    "With friction a collision's impulse is Bullet's change of the car's momentum within 3 %, one known "
    "limit within 4 %",
    "[bullet]")
{
    CheckImpulseIsMomentumChange<BulletWallCrash>("Bullet", 0.5, {{"40 km/h 40 % offset", 0.04}});
}

// A wall turned 60 degrees, with friction: the car's corner slides along the wall through the whole impact.
// Grouped as crumple-crash groups a crash pulse (0.15 s). With one friction tangent per contact (Bullet's
// default) the 20 km/h hit took 7.6 % less from the car than Crumple's Coulomb impulse says (crumple-crash's
// impulse_momentum check failed by 12 % on the Toy Car); with the scene's two fixed tangents, the pyramid of
// ODE's contacts, both engines agree with it within 3 % (Bullet 1.0 %, ODE 0.01 %).
TEST_CASE("A glancing hit on a wall turned 60 degrees: Crumple's impulse is the engine's change of momentum "
          "within 3 %, with friction",
          "[bullet][ode]")
{
    for (double km_h : {20.0, 56.0})
    {
        EngineCrashSettings glancing;
        glancing.mSpeed = km_h / 3.6;
        glancing.mDuration = 0.3;
        glancing.mTriangles = 2000;
        glancing.mFriction = 0.5;
        glancing.mWallAngleDegrees = 60.0;
        glancing.mWorld.mGrouping.mTimeWindow = 0.15;
        for (const auto& [engine, run] :
             {std::pair{"Bullet", ImpulseAndMomentumChange<BulletWallCrash>(glancing)},
              std::pair{"ODE", ImpulseAndMomentumChange<OdeWallCrash>(glancing)}})
        {
            const Vec3 horizontal(1.0, 1.0, 0.0);
            const Vec3 crumple = run.first.cwiseProduct(horizontal);
            const Vec3 change = run.second.cwiseProduct(horizontal);
            INFO(km_h << " km/h " << engine << ": Crumple " << crumple.transpose() << " N s, engine "
                      << change.transpose() << " N s");
            CHECK(change.norm() > 0.0);
            CHECK((crumple - change).norm() <= 0.03 * change.norm());
        }
    }
}

// Low speed: a car that sinks into a wall within one step leaves it at the bounce Crumple assumes, not pushed
// out faster by the engine's error reduction (ODE takes the larger of its push-out and the bounce, Bullet
// adds them below its split threshold). Before the scenes mended it (ODE's soft ERP at most the restitution,
// Bullet's split impulses for all contacts but the ground's): the 60-degree wall at 5 km/h took 6.9 % (ODE)
// and 14-15 % (Bullet) more from the car than Crumple's impulse, a 10 km/h frontal hit of the Gazebo
// hatchback in ODE 6.9 % more, a 3 km/h one in Bullet 5.0 % more.
TEST_CASE(
    "At 3-10 km/h, frontal and glancing, Crumple's impulse is the engine's change of momentum within 3 %",
    "[bullet][ode]")
{
    // (at 3 km/h the 60-degree wall is met at 0.42 m/s along its normal: resting, DamageWorldSettings::
    // mRestingSpeed, no impact)
    for (const auto& [km_h, angle] : {std::pair{3.0, 0.0}, std::pair{5.0, 0.0}, std::pair{10.0, 0.0},
                                      std::pair{5.0, 60.0}, std::pair{10.0, 60.0}})
    {
        EngineCrashSettings low;
        low.mSpeed = km_h / 3.6;
        low.mDuration = 1.0;
        low.mTriangles = 2000;
        low.mFriction = 0.5;
        low.mWallAngleDegrees = angle;
        low.mWorld.mGrouping.mTimeWindow = 0.15;
        for (const auto& [engine, run] : {std::pair{"Bullet", ImpulseAndMomentumChange<BulletWallCrash>(low)},
                                          std::pair{"ODE", ImpulseAndMomentumChange<OdeWallCrash>(low)}})
        {
            const Vec3 horizontal(1.0, 1.0, 0.0);
            const Vec3 crumple = run.first.cwiseProduct(horizontal);
            const Vec3 change = run.second.cwiseProduct(horizontal);
            INFO(km_h << " km/h, wall at " << angle << " degrees, " << engine << ": Crumple "
                      << crumple.transpose() << " N s, engine " << change.transpose() << " N s");
            CHECK(change.norm() > 0.0);
            CHECK((crumple - change).norm() <= 0.03 * change.norm());
        }
    }
}

namespace
{

// The car's largest height change (m) and angular speed (rad/s) over a drive on the bare ground.
template <class Scene> std::pair<double, double> RideOnGround(double inSpeed)
{
    EngineCrashSettings drive;
    drive.mDriveOnly = true;
    drive.mSpeed = inSpeed;
    drive.mTriangles = 2000;
    Scene scene(drive);
    const double start_height = scene.GetCarState().mCenterOfMass.z();
    double height_change = 0.0, angular_speed = 0.0;
    const int steps = static_cast<int>(std::lround(drive.mDuration / drive.mTimeStep));
    for (int step = 0; step < steps; ++step)
    {
        scene.Step();
        const plugin::BodyState car = scene.GetCarState();
        height_change = std::max(height_change, std::abs(car.mCenterOfMass.z() - start_height));
        angular_speed = std::max(angular_speed, car.mAngularVelocity.norm());
    }
    return {height_change, angular_speed};
}

} // namespace

// The crash scenes' car is a box on the ground. On a Bullet static plane a box sliding at crash speed keeps a
// one- or two-point manifold (the plane's contact points go stale as it slides 15 cm a step): it rocks from
// corner to corner and sinks, 17.7 mm and 0.205 rad/s at 20 km/h, 32.3 mm and 0.211 rad/s at 64 km/h (over
// 0.6 s). On a box ground (Bullet's box-box detector: the whole face each step) 0.002 mm and 0 rad/s, 1.2 mm
// and 0.038 rad/s; ODE's car on its plane 0.0001 mm and 4e-6 rad/s. Bounds: 2 mm, 0.05 rad/s.
TEST_CASE("A car sliding on the crash scenes' ground keeps its height and does not rock, in Bullet and ODE",
          "[bullet][ode]")
{
    for (double km_h : {20.0, 64.0})
    {
        for (const auto& [engine, ride] :
             {std::make_pair("Bullet", RideOnGround<BulletWallCrash>(km_h / 3.6)),
              std::make_pair("ODE", RideOnGround<OdeWallCrash>(km_h / 3.6))})
        {
            INFO(engine << " at " << km_h << " km/h: height change " << ride.first
                        << " m, angular speed up to " << ride.second << " rad/s");
            CHECK(ride.first <= 0.002);
            CHECK(ride.second <= 0.05);
        }
    }
}

// A game steps its engine at 30-480 Hz; the crush must not depend on which. The same crashes at five steps,
// in both engines: each crush within 1 % of the 120 Hz one (the crash tests' step) of the same engine
// (measured: 0.12 % at most; the Campbell crush takes the collision's absorbed energy, which the step does
// not change).
TEST_CASE("The crush does not depend on the engine's time step (30 to 480 Hz), in Bullet and ODE", "[bullet][ode]")
{
    std::vector<std::pair<std::string, EngineCrashSettings>> crashes;
    EngineCrashSettings base;
    base.mSpeed = 56.0 / 3.6;
    base.mDuration = 0.3;
    base.mTriangles = 2000;
    crashes.emplace_back("frontal", base);
    EngineCrashSettings offset = base;
    offset.mOverlapFraction = 0.4;
    crashes.emplace_back("40 % offset", offset);
    EngineCrashSettings pole = base;
    pole.mPoleRadius = 0.127;
    crashes.emplace_back("pole", pole);
    // (a named pair, not a structured binding: clang before 16 refuses a binding captured by a lambda)
    for (const std::pair<std::string, EngineCrashSettings>& entry : crashes)
        for (const char* engine : {"Bullet", "ODE"})
        {
            const std::string& name = entry.first;
            const EngineCrashSettings& crash = entry.second;
            const auto crush_at = [&, engine = std::string(engine)](double inTimeStep) {
                EngineCrashSettings settings = crash;
                settings.mTimeStep = inTimeStep;
                return engine == "Bullet" ? BulletWallCrash(settings).Run().mMaxDent : OdeWallCrash(settings).Run().mMaxDent;
            };
            const double reference = crush_at(1.0 / 120.0);
            REQUIRE(reference > 0.2); // a real crush, not two empty runs agreeing
            for (double hz : {30.0, 60.0, 240.0, 480.0})
            {
                const double crush = crush_at(1.0 / hz);
                INFO(name << " in " << engine << " at " << hz << " Hz: " << crush << " m, at 120 Hz " << reference << " m");
                CHECK(std::abs(crush - reference) <= 0.01 * reference);
            }
        }
}
