// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "BoxMesh.h"

#include <crumple/plugin/DeformableObject.h>

#include <array>
#include <catch2/catch.hpp>

using namespace crumple;
using namespace crumple::plugin;

namespace
{

DeformableObject MakeCar(const DamageMaterial& inMaterial, bool inInterpolate = false,
                         std::array<int, 3> inControlCount = {8, 8, 8})
{
    DeformableObjectSettings settings;
    settings.mFittedControlCount = inControlCount;
    settings.mMesh = common::MakeBoxMesh(Vec3(2.1, 0.9, 0.7), {20, 10, 8});
    settings.mMaterial = inMaterial;
    settings.mInterpolateWideImpacts = inInterpolate;
    return DeformableObject::Create(settings).Get();
}

// A collision on the car's front face (the car is body B, the wall A, normal from car to wall = +x).
Collision FrontCollision(const std::vector<std::pair<Vec3, double>>& inPointsAndImpulses)
{
    Collision collision;
    for (const auto& [point, impulse] : inPointsAndImpulses)
    {
        CollisionContact contact;
        contact.mLocalPointOnB = point;
        contact.mLocalNormalOnB = Vec3::UnitX();
        contact.mImpulse = impulse;
        collision.mContacts.push_back(contact);
    }
    return collision;
}

} // namespace

TEST_CASE("Dent depth is factor x total impulse, shaped by each contact's share", "[plugin]")
{
    DamageMaterial material;
    material.mModel = ECrushModel::ImpulseFactor;
    material.mDeformationFactor = 1.0e-5;
    material.mMinDeformation = 0.001;
    material.mMaxInstantDeformation = 0.2;
    const DeformableObject car = MakeCar(material);
    const Collision collision = FrontCollision({{Vec3(2.1, 0.0, 0.0), 6000.0}, {Vec3(2.1, 0.5, 0.0), 3000.0}});
    const std::vector<ffd::PointDisplacement> dent = car.DentFor(collision, ECollisionSide::B);
    REQUIRE(dent.size() == 2);
    // Total 9000 N s: the peak contact gets 0.09 m, the other half of it; both into the car (-x).
    CHECK(dent[0].mDisplacement.isApprox(Vec3(-0.09, 0.0, 0.0), 1.0e-12));
    CHECK(dent[1].mDisplacement.isApprox(Vec3(-0.045, 0.0, 0.0), 1.0e-12));
}

TEST_CASE("Dents below the minimum are dropped and above the maximum clamped", "[plugin]")
{
    DamageMaterial material;
    material.mDeformationFactor = 1.0e-5;
    material.mMinDeformation = 0.01;
    material.mMaxInstantDeformation = 0.05;
    const DeformableObject car = MakeCar(material);
    // 500 N s -> 5 mm: dropped.
    CHECK(car.DentFor(FrontCollision({{Vec3(2.1, 0.0, 0.0), 500.0}}), ECollisionSide::B).empty());
    // 20,000 N s -> 0.2 m: clamped to 0.05 m; its 1 % partner (2 mm) dropped; a 10 % one (about 2 cm) kept.
    const std::vector<ffd::PointDisplacement> dent = car.DentFor(
        FrontCollision({{Vec3(2.1, 0.0, 0.0), 18000.0}, {Vec3(2.1, 0.5, 0.0), 180.0}, {Vec3(2.1, -0.5, 0.0), 1800.0}}),
        ECollisionSide::B);
    REQUIRE(dent.size() == 2);
    CHECK(dent[0].mDisplacement.norm() == Approx(0.05));
    CHECK(dent[1].mDisplacement.norm() == Approx(1.0e-5 * 19980.0 * 0.1));
}

TEST_CASE("An impulse threshold leaves small impacts undented and shifts the rest (Campbell's b0)", "[plugin]")
{
    DamageMaterial material;
    material.mDeformationFactor = 1.0e-5;
    material.mMinDeformation = 0.0;
    material.mMaxInstantDeformation = 1.0;
    material.mImpulseThreshold = 4000.0; // N s
    const DeformableObject car = MakeCar(material);
    // At or below the threshold: nothing.
    CHECK(car.DentFor(FrontCollision({{Vec3(2.1, 0.0, 0.0), 4000.0}}), ECollisionSide::B).empty());
    // Above: depth = factor (J - J0), shaped by each share: (9000 - 4000) 1e-5 = 0.05 m at the peak.
    const std::vector<ffd::PointDisplacement> dent =
        car.DentFor(FrontCollision({{Vec3(2.1, 0.0, 0.0), 6000.0}, {Vec3(2.1, 0.5, 0.0), 3000.0}}), ECollisionSide::B);
    REQUIRE(dent.size() == 2);
    CHECK(dent[0].mDisplacement.isApprox(Vec3(-0.05, 0.0, 0.0), 1.0e-12));
    CHECK(dent[1].mDisplacement.isApprox(Vec3(-0.025, 0.0, 0.0), 1.0e-12));

    // Refused when negative or not finite.
    DeformableObjectSettings settings;
    settings.mMesh = common::MakeBoxMesh(Vec3(2.1, 0.9, 0.7), {4, 4, 4});
    settings.mMaterial.mImpulseThreshold = -1.0;
    CHECK(DeformableObject::Create(settings).HasError());
}

TEST_CASE("Dent depth does not depend on how many points report the same impact", "[plugin]")
{
    DamageMaterial material;
    material.mModel = ECrushModel::ImpulseFactor;
    DeformableObject four = MakeCar(material, true);
    DeformableObject sixteen = MakeCar(material, true);
    // The same face impact of 9,000 N s, as 4 corner contacts or a 4 x 4 grid, each sharing it evenly.
    std::vector<std::pair<Vec3, double>> corners, grid;
    for (double y : {-0.6, 0.6})
        for (double z : {-0.4, 0.4})
            corners.push_back({Vec3(2.1, y, z), 9000.0 / 4.0});
    for (int i = 0; i < 4; ++i)
        for (int k = 0; k < 4; ++k)
            grid.push_back({Vec3(2.1, -0.6 + 0.4 * i, -0.4 + 0.8 * k / 3.0), 9000.0 / 16.0});
    REQUIRE(four.ApplyCollision(FrontCollision(corners), ECollisionSide::B).IsValid());
    REQUIRE(sixteen.ApplyCollision(FrontCollision(grid), ECollisionSide::B).IsValid());
    const auto& rest = four.GetDeformer().GetRestMesh().mPositions;
    double max_four = 0.0, max_sixteen = 0.0;
    for (std::size_t v = 0; v < rest.size(); ++v)
    {
        max_four = std::max(max_four, (four.GetDeformer().GetPositions()[v] - rest[v]).norm());
        max_sixteen = std::max(max_sixteen, (sixteen.GetDeformer().GetPositions()[v] - rest[v]).norm());
    }
    CHECK(max_four == Approx(9000.0 * material.mDeformationFactor).epsilon(0.1));
    CHECK(max_sixteen == Approx(max_four).epsilon(0.1));
}

TEST_CASE("A wide impact makes one coherent dent", "[plugin]")
{
    // Four corner contacts of a 1.2 m x 0.8 m face: with interpolation the face centre sinks as far as
    // the corners; without it the centre lags behind. On a lattice whose spacing (0.14-0.33 m here) leaves
    // the centre out of the corners' reach: at 8^3 the quasi-interpolant prior alone already fills it.
    DamageMaterial material;
    material.mModel = ECrushModel::ImpulseFactor;
    material.mDeformationFactor = 1.0e-5;
    const auto corners = FrontCollision({{Vec3(2.1, -0.6, -0.4), 1000.0}, {Vec3(2.1, 0.6, -0.4), 1000.0},
                                         {Vec3(2.1, -0.6, 0.4), 1000.0}, {Vec3(2.1, 0.6, 0.4), 1000.0}});
    DeformableObject coherent = MakeCar(material, true, {16, 16, 16});
    DeformableObject spiky = MakeCar(material, false, {16, 16, 16});
    REQUIRE(coherent.ApplyCollision(corners, ECollisionSide::B).IsValid());
    REQUIRE(spiky.ApplyCollision(corners, ECollisionSide::B).IsValid());
    auto centre_depth = [](const DeformableObject& inObject) {
        const ffd::FfdLattice& zone = inObject.GetDeformer().GetZones()[0];
        return -zone.Displacement(zone.Locate(zone.LatticeCoordinate(Vec3(2.1, 0.0, 0.0)))).x();
    };
    CHECK(centre_depth(coherent) == Approx(0.04).epsilon(0.05));
    CHECK(centre_depth(spiky) < 0.8 * centre_depth(coherent));
}

TEST_CASE("A dent the material's maximum clamps is reported as limited", "[plugin]")
{
    DamageMaterial material;
    material.mModel = ECrushModel::ImpulseFactor;
    material.mDeformationFactor = 1.0e-5;
    material.mMaxInstantDeformation = 0.05;
    // 2,000 N s asks for 0.02 m: within the bound. 20,000 N s asks for 0.2 m: clamped to 0.05 m.
    DeformableObject soft = MakeCar(material);
    DeformableObject hard = MakeCar(material);
    const ffd::DentReport within =
        soft.ApplyCollision(FrontCollision({{Vec3(2.1, 0.0, 0.0), 2000.0}}), ECollisionSide::B).Get();
    const ffd::DentReport clamped =
        hard.ApplyCollision(FrontCollision({{Vec3(2.1, 0.0, 0.0), 15000.0}, {Vec3(2.1, 0.3, 0.0), 5000.0}}),
                            ECollisionSide::B)
            .Get();
    REQUIRE(within.mPointsApplied > 0); // both dents happened
    REQUIRE(clamped.mPointsApplied > 0);
    CHECK(within.mContactsClamped == 0);
    CHECK_FALSE(within.IsLimited());
    CHECK(clamped.mContactsClamped == 2);
    CHECK(clamped.IsLimited());
}

TEST_CASE("A mesh whose extent overflows is refused, not fitted forever", "[plugin]")
{
    DeformableObjectSettings settings;
    settings.mMesh = common::MakeBoxMesh(Vec3(2.1, 0.9, 0.7), {4, 4, 4});
    settings.mMesh.mPositions[0] = Vec3(-1.0e308, 0.0, 0.0);
    settings.mMesh.mPositions[1] = Vec3(1.0e308, 0.0, 0.0);
    CHECK(DeformableObject::Create(settings).HasError());
}
