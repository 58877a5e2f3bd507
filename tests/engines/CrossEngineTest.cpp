// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "BulletWallCrash.h"
#include "OdeWallCrash.h"

#include <catch2/catch.hpp>

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
        CHECK(std::abs(bullet.mMaxDent - ode.mMaxDent) <= 0.2 * std::max(bullet.mMaxDent, ode.mMaxDent));
        CHECK((bullet.mDentCentroid - ode.mDentCentroid).norm() <= 0.25);
    }
}

namespace
{

// The crashes of the momentum and crush checks: frontal, 40 % offset, pole and 30-degree wall at 20-64 km/h.
std::vector<std::pair<std::string, EngineCrashSettings>> MomentumCrashes()
{
    std::vector<std::pair<std::string, EngineCrashSettings>> crashes;
    for (double km_h : {20.0, 40.0, 56.0, 64.0})
    {
        EngineCrashSettings base;
        base.mSpeed = km_h / 3.6;
        base.mDuration = 0.3;
        base.mTriangles = 2000;
        base.mFriction = 0.0; // the wall's normal impulses are then the only horizontal force on the car
        base.mGroundFriction = 0.0;
        const std::string speed = std::to_string(static_cast<int>(km_h)) + " km/h ";
        crashes.emplace_back(speed + "frontal", base);
        EngineCrashSettings offset = base;
        offset.mOverlapFraction = 0.4;
        crashes.emplace_back(speed + "40 % offset", offset);
        EngineCrashSettings angled = base;
        angled.mWallAngleDegrees = 30.0;
        crashes.emplace_back(speed + "30-degree wall", angled);
        EngineCrashSettings pole = base;
        pole.mPoleRadius = 0.127;
        crashes.emplace_back(speed + "pole", pole);
    }
    return crashes;
}

} // namespace

TEST_CASE("A collision's impulse is the engine's change of the car's momentum within 3 %, in Bullet and ODE", "[bullet][ode]")
{
    // The engines bounce as Crumple's impulses assume (the scenes set their restitution from
    // DamageWorldSettings::mRestitution and cap ODE's penetration push-out), and Crumple counts an impact once
    // however many steps the engine takes to stop the car.
    for (const auto& [name, settings] : MomentumCrashes())
    {
        const EngineCrashResult bullet = BulletWallCrash(settings).Run();
        const EngineCrashResult ode = OdeWallCrash(settings).Run();
        for (const EngineCrashResult* run : {&bullet, &ode})
        {
            const Vec3 horizontal(1.0, 1.0, 0.0);
            const Vec3 crumple = run->mCarImpulse.cwiseProduct(horizontal);
            const Vec3 engine = run->mCarMomentumChange.cwiseProduct(horizontal);
            INFO(name << (run == &bullet ? " Bullet" : " ODE") << ": Crumple " << crumple.transpose() << " N s, engine "
                      << engine.transpose() << " N s");
            CHECK((crumple - engine).norm() <= 0.03 * engine.norm());
        }
    }
}
