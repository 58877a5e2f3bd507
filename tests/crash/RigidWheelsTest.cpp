// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// Wheels as rigid parts on the shipped meshes: found by name in the files, carried through the re-cut, and
// round after a crush that reaches them (they were squashed into ellipses with the body before).
#include "CarMesh.h"

#include <crumple/crash/CrashRun.h>
#include <crumple/crash/ShippedCars.h>
#include <crumple/crash/RecutCarMesh.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

using namespace crumple;
using namespace crumple::crash;

namespace
{

NamedVehicle Truck()
{
    for (const NamedVehicle& body : ShippedCars())
        if (body.mName == "Kenney truck")
            return body;
    FAIL("no Kenney truck among the shipped cars");
    return {};
}

// The truck's 64 km/h pole crash (Bullet), its wheels rigid or not.
CrashOutcome PoleCrash(bool inRigidWheels)
{
    CrashScenario scenario;
    scenario.mName = "truck pole";
    scenario.mDuration = 0.3;
    scenario.mVehicle = Truck().mVehicle;
    if (!inRigidWheels)
        scenario.mVehicle.mMeshRigidParts.clear();
    scenario.mTarget.mType = ETarget::Pole;
    scenario.mImpact.mSpeed = 64.0 / 3.6;
    scenario.mPictures = false;
    Result<CrashOutcome> outcome = RunCrash(scenario, {});
    REQUIRE(outcome);
    return std::move(outcome.Get());
}

// The truck's wheels as the crash run re-cuts them.
std::vector<std::vector<std::uint32_t>> TruckWheels()
{
    const VehicleSpec vehicle = Truck().mVehicle;
    samples::CarMeshSettings settings;
    settings.mPath = vehicle.mMesh;
    settings.mLength = vehicle.mMeshLength;
    settings.mFileToBody = samples::FileToBodyRotation(samples::EMeshAxis::PlusZ, samples::EMeshAxis::PlusY).Get();
    samples::CarBody body = samples::LoadCarBody(settings).Get();
    REQUIRE(RecutCarMesh(body.mMesh, body.mRigidParts, vehicle.mMeshMaxEdge, vehicle.mMeshFlipDeviation));
    return body.mRigidParts;
}

// The largest difference between two vertices' displacements within a part (m): zero when it translates.
double Spread(const CrashOutcome& inOutcome, const std::vector<std::uint32_t>& inPart)
{
    double spread = 0.0;
    const Vec3 first = inOutcome.mPositions[inPart.front()] - inOutcome.mRestMesh.mPositions[inPart.front()];
    for (std::uint32_t v : inPart)
        spread = std::max(spread, (inOutcome.mPositions[v] - inOutcome.mRestMesh.mPositions[v] - first).norm());
    return spread;
}

} // namespace

TEST_CASE("Wheels are found by name in the shipped meshes", "[crash]")
{
    const std::filesystem::path meshes = samples::SharedDataFolder() / "meshes";
    samples::CarMeshSettings truck;
    truck.mPath = meshes / "kenney_truck" / "vehicle-truck-red.glb";
    const samples::CarBody truck_body = samples::LoadCarBody(truck).Get();
    std::vector<std::string> names = truck_body.mRigidPartNames;
    std::sort(names.begin(), names.end());
    CHECK(names == std::vector<std::string>{"wheel-back-left", "wheel-back-right", "wheel-front-left", "wheel-front-right"});

    samples::CarMeshSettings hatchback; // all of it: the shipped crashes load its body alone ("Hatchback")
    hatchback.mPath = meshes / "gazebo_hatchback" / "hatchback.obj";
    const samples::CarBody hatchback_body = samples::LoadCarBody(hatchback).Get();
    // Three wheel meshes (front left, front right, both rear wheels in one), four wheels: the rear mesh is
    // split into its two connected pieces, each moving at its own centre.
    CHECK(hatchback_body.mRigidParts.size() == 4u);
    for (const std::vector<std::uint32_t>& part : hatchback_body.mRigidParts)
        CHECK(part.size() > 100u);

    truck.mRigidPartNames.clear();
    CHECK(samples::LoadCarBody(truck).Get().mRigidParts.empty());
}

TEST_CASE("A 64 km/h pole crash pushes the truck's front wheels back round, and squashes them without rigid parts",
          "[crash]")
{
    const std::vector<std::vector<std::uint32_t>> wheels = TruckWheels();
    REQUIRE(wheels.size() == 4u);
    const CrashOutcome rigid = PoleCrash(true);
    const CrashOutcome free = PoleCrash(false);
    REQUIRE(rigid.mPositions.size() == rigid.mRestMesh.mPositions.size());
    double moved = 0.0, squashed = 0.0;
    for (const std::vector<std::uint32_t>& wheel : wheels)
    {
        REQUIRE(wheel.back() < rigid.mPositions.size());
        INFO("wheel of " << wheel.size() << " vertices: spread " << Spread(rigid, wheel) << " m rigid, "
                         << Spread(free, wheel) << " m free");
        CHECK(Spread(rigid, wheel) <= 1.0e-9);
        moved = std::max(moved, (rigid.mPositions[wheel.front()] - rigid.mRestMesh.mPositions[wheel.front()]).norm());
        squashed = std::max(squashed, Spread(free, wheel));
    }
    CHECK(moved > 0.05);    // the crush reached a wheel and moved it
    CHECK(squashed > 0.05); // which it squashed before
}
