// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "DrawVec3.h"
#include "WorldFixture.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

using namespace crumple;
using namespace crumple::plugin;
using crumple::common::WorldFixture;

TEST_CASE("10,000 random impacts leave no NaN and no vertex beyond the maximum total deformation", "[plugin][stress]")
{
    WorldFixture fixture(3000, {8, 6, 6});
    const ffd::FfdDeformer& car = fixture.mWorld.GetObject(fixture.mCarObject)->GetDeformer();
    const double max_total = car.GetSettings().mZones[0].mMaxTotalDeformation;
    const Vec3 half = fixture.mHalfExtents;

    std::mt19937_64 random(2026);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::uniform_real_distribution<double> symmetric(-1.0, 1.0);
    auto random_direction = [&]() {
        Vec3 d;
        do
            d = common::DrawVec3([&] { return symmetric(random); });
        while (d.norm() < 1.0e-3 || d.norm() > 1.0);
        return Vec3(d.normalized());
    };

    int refused = 0;
    for (int impact = 0; impact < 10000; ++impact)
    {
        const double time = impact * 0.1;
        // Mass log-uniform in [1e-3, 1e6] kg, speed up to 300 m/s, random spin.
        BodyState car_state = fixture.CarState(0.0);
        car_state.mMass = std::pow(10.0, -3.0 + 9.0 * unit(random));
        car_state.mInverseInertiaWorld *= fixture.mMass / car_state.mMass;
        car_state.mLinearVelocity = 300.0 * unit(random) * random_direction();
        car_state.mAngularVelocity = 20.0 * unit(random) * random_direction();
        REQUIRE(fixture.mWorld.SetBodyState(fixture.mCar, car_state));

        // A contact set: random points on the car's surface, or degenerate sets.
        const Vec3 normal = random_direction();
        const int kind = impact % 4;
        const int count = 1 + static_cast<int>(unit(random) * 63.0);
        const Vec3 centre = car_state.mTransform.ToWorld(
            half.cwiseProduct(common::DrawVec3([&] { return symmetric(random); })));
        std::vector<ContactEvent> contacts;
        for (int i = 0; i < count; ++i)
        {
            Vec3 p;
            if (kind == 0) // scattered
                p = car_state.mTransform.ToWorld(
                    half.cwiseProduct(common::DrawVec3([&] { return symmetric(random); })));
            else if (kind == 1) // all coincident
                p = centre;
            else if (kind == 2) // collinear
                p = centre + 0.05 * i * Vec3::UnitY();
            else // nearly coincident
                p = centre + 1.0e-9 * common::DrawVec3([&] { return symmetric(random); });
            ContactEvent contact;
            contact.mBodyA = fixture.mCar;
            contact.mBodyB = fixture.mWall;
            contact.mPointOnA = contact.mPointOnB = p;
            contact.mNormal = normal;
            contact.mPenetrationDepth = 0.05 * unit(random);
            contact.mTime = time;
            contacts.push_back(contact);
        }
        if (!fixture.mWorld.SubmitContacts(contacts))
            ++refused;
        fixture.mWorld.Update(time + 0.06);

        if (impact % 500 == 499)
        {
            for (std::size_t v = 0; v < car.GetPositions().size(); ++v)
            {
                REQUIRE(car.GetPositions()[v].allFinite());
                REQUIRE(car.GetNormals()[v].allFinite());
                REQUIRE((car.GetPositions()[v] - car.GetRestMesh().mPositions[v]).norm() <= max_total * (1.0 + 1.0e-12));
            }
        }
    }
    CHECK(refused == 0);
    // The car was actually damaged (the test would be vacuous otherwise).
    double deepest = 0.0;
    for (std::size_t v = 0; v < car.GetPositions().size(); ++v)
        deepest = std::max(deepest, (car.GetPositions()[v] - car.GetRestMesh().mPositions[v]).norm());
    CHECK(deepest > 0.5 * max_total);
}
