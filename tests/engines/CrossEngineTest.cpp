// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "BulletWallCrash.h"
#include "OdeWallCrash.h"

#include <catch2/catch.hpp>

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
