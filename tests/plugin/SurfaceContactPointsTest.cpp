// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/plugin/SurfaceContactPoints.h>

#include <catch2/catch.hpp>

using namespace crumple;
using namespace crumple::plugin;

TEST_CASE("A single reported point is split onto both surfaces by the depth", "[plugin]")
{
    // A sphere of radius 1 at z = 0.9 sinks 0.1 m into the ground z = 0; ODE reports the midpoint.
    ContactEvent contact;
    contact.mPointOnA = contact.mPointOnB = Vec3(0.0, 0.0, -0.05);
    contact.mNormal = Vec3::UnitZ(); // from the ground (B) to the sphere (A)
    contact.mPenetrationDepth = 0.1;
    const SurfacePoints surface = SurfaceContactPoints(contact);
    CHECK(surface.mOnA.isApprox(Vec3(0.0, 0.0, -0.1)));   // the sphere's lowest point
    CHECK(surface.mOnB.isApprox(Vec3(0.0, 0.0, 0.0), 1e-15)); // the ground surface
    CHECK((surface.mOnA - surface.mOnB).isApprox(-contact.mPenetrationDepth * contact.mNormal));
}

TEST_CASE("Two distinct points are already on the surfaces", "[plugin]")
{
    ContactEvent contact;
    contact.mPointOnA = Vec3(1.0, 2.0, -0.02);
    contact.mPointOnB = Vec3(1.0, 2.0, 0.0);
    contact.mNormal = Vec3::UnitZ();
    contact.mPenetrationDepth = 0.02;
    const SurfacePoints surface = SurfaceContactPoints(contact);
    CHECK(surface.mOnA == contact.mPointOnA);
    CHECK(surface.mOnB == contact.mPointOnB);
}
