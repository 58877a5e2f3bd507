// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// README.md's "Integration in 20 lines" block, as generated into ReadmeIntegration.cpp by
// tests/readme/CMakeLists.txt, run on a box car driven into a wall: a user who copies it gets a dent.
#include "BoxMesh.h"

#include <crumple/ffd/TriangleMesh.h>
#include <crumple/plugin/BodyState.h>
#include <crumple/plugin/ContactEvent.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

using namespace crumple;
using namespace crumple::plugin;

void ReadmeIntegration(
    const BodyState& car_state, const BodyState& static_state, const ffd::TriangleMesh& car_mesh,
    const BodyState& state_before_solver, const std::vector<ContactEvent>& contacts_of_this_step, double time,
    double dt, const std::function<void(const std::vector<Vec3>&, std::uint32_t, std::uint32_t)>& upload,
    const std::function<void(const crumple::Error&)>& report);

TEST_CASE("README's integration block dents a box car driven into a wall, refusing nothing", "[plugin]")
{
    // A 1,500 kg, 4 m box car at 10 m/s meeting a static wall at its front face (x = 2 m) with four contacts
    // in one 1/120 s step; the block's Update at 0.05 s closes the collision window and dispatches it.
    const Vec3 half(2.0, 0.9, 0.7);
    BodyState car;
    car.mMass = 1500.0;
    car.mInverseInertiaWorld = Mat3::Identity() / 2000.0;
    car.mLinearVelocity = Vec3(10.0, 0.0, 0.0);
    car.mHasShapeBounds = true;
    car.mShapeMin = -half;
    car.mShapeMax = half;
    BodyState wall;
    wall.mMotionType = EMotionType::Static;
    wall.mTransform.mTranslation = Vec3(3.0, 0.0, 0.0);
    wall.mHasShapeBounds = true;
    wall.mShapeMin = Vec3(-1.0, -5.0, -2.0);
    wall.mShapeMax = Vec3(1.0, 5.0, 2.0);
    // intent: the world the block makes numbers its bodies in creation order: the car 0, the wall 1
    std::vector<ContactEvent> contacts;
    for (double y : {-0.5, 0.5})
        for (double z : {-0.3, 0.3})
        {
            ContactEvent contact;
            contact.mBodyA = BodyId{0};
            contact.mBodyB = BodyId{1};
            contact.mPointOnA = contact.mPointOnB = Vec3(2.0, y, z);
            contact.mNormal = Vec3(-1.0, 0.0, 0.0);
            contact.mPenetrationDepth = 0.01;
            contact.mTime = 1.0 / 120.0;
            contacts.push_back(contact);
        }
    const ffd::TriangleMesh mesh = common::MakeBoxMesh(half, {16, 8, 6});

    int refusals = 0, uploads = 0;
    double front = -std::numeric_limits<double>::infinity(); // the foremost vertex uploaded last (m)
    ReadmeIntegration(
        car, wall, mesh, car, contacts, 0.05 + 1.0 / 120.0, 1.0 / 120.0,
        [&](const std::vector<Vec3>& inPositions, std::uint32_t, std::uint32_t)
        {
            ++uploads;
            front = -std::numeric_limits<double>::infinity();
            for (const Vec3& p : inPositions)
                front = std::max(front, p.x());
        },
        [&](const Error&) { ++refusals; });
    CHECK(refusals == 0);
    REQUIRE(uploads > 0);
    // intent: the front face (x = 2 m) crushed back by a dent of at least 5 cm, and not through the car
    INFO("foremost vertex after the dent " << front << " m");
    CHECK(front < half.x() - 0.05);
    CHECK(front > 0.0);
}
