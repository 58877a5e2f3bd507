// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// crumple-crash reports how it re-cut a mesh body: counts that match the mesh the crash deformed, flips only
// where the scenario allows them, nothing for the procedural box.
#include <crumple/crash/CrashRun.h>
#include <crumple/crash/ShippedCars.h>

#include <catch2/catch.hpp>

#include <string>

using namespace crumple;
using namespace crumple::crash;

namespace
{

VehicleSpec Shipped(const std::string& inName)
{
    for (const NamedVehicle& body : ShippedCars())
        if (body.mName == inName)
            return body.mVehicle;
    FAIL("no " << inName << " among the shipped cars");
    return {};
}

// A short 20 km/h pole hit: enough to build the body and dent it.
CrashOutcome ShortCrash(const VehicleSpec& inVehicle)
{
    CrashScenario scenario;
    scenario.mName = "mesh preparation";
    scenario.mDuration = 0.05;
    scenario.mVehicle = inVehicle;
    scenario.mTarget.mType = ETarget::Pole;
    scenario.mImpact.mSpeed = 20.0 / 3.6;
    scenario.mPictures = false;
    Result<CrashOutcome> outcome = RunCrash(scenario, {});
    REQUIRE(outcome);
    return std::move(outcome.Get());
}

} // namespace

TEST_CASE("A mesh body's re-cut is reported with the counts of the mesh the crash deformed", "[crash]")
{
    const VehicleSpec hatchback = Shipped("Gazebo hatchback");
    const CrashOutcome recut = ShortCrash(hatchback);
    REQUIRE(recut.mMeshPreparation.has_value());
    const MeshPreparation& mesh = *recut.mMeshPreparation;
    CHECK(mesh.mTriangles == recut.mRestMesh.mTriangles.size());
    CHECK(mesh.mVertices == recut.mRestMesh.mPositions.size());
    CHECK(mesh.mTriangles > mesh.mFileTriangles);
    CHECK(mesh.mVertices > mesh.mFileVertices);
    CHECK(mesh.mMaxEdge == hatchback.mMeshMaxEdge);
    CHECK(mesh.mFlipDeviation == hatchback.mMeshFlipDeviation);
    CHECK(mesh.mNearlyFlatFlips > 0); // the premise of the second section

    SECTION("the file's triangles as they are: no re-cut, no flips")
    {
        VehicleSpec as_is = hatchback;
        as_is.mMeshMaxEdge = 0.0;
        const CrashOutcome outcome = ShortCrash(as_is);
        REQUIRE(outcome.mMeshPreparation.has_value());
        const MeshPreparation& same = *outcome.mMeshPreparation;
        CHECK(same.mFileTriangles == mesh.mFileTriangles);
        CHECK(same.mFileVertices == mesh.mFileVertices);
        CHECK(same.mTriangles == same.mFileTriangles);
        CHECK(same.mVertices == same.mFileVertices);
        CHECK(same.mTriangles == outcome.mRestMesh.mTriangles.size());
        CHECK(same.mMaxEdge == 0.0);
        CHECK(same.mFlatFlips == 0);
        CHECK(same.mNearlyFlatFlips == 0);
        CHECK(same.mCapSplitVertices == 0);
    }

    SECTION("no deviation allowed: only exactly flat pairs flip, the midpoints stay")
    {
        VehicleSpec exact = hatchback;
        exact.mMeshFlipDeviation = 0.0;
        const CrashOutcome outcome = ShortCrash(exact);
        REQUIRE(outcome.mMeshPreparation.has_value());
        const MeshPreparation& flat = *outcome.mMeshPreparation;
        CHECK(flat.mNearlyFlatFlips == 0);
        CHECK(flat.mFlipDeviation == 0.0);
        CHECK(flat.mFlatFlips == mesh.mFlatFlips);
        // intent: flips add no vertex, so the two differ only by the vertices that split caps (no flip removed
        // the caps between the splits here, so more are split)
        CHECK(flat.mCapSplitVertices > mesh.mCapSplitVertices);
        CHECK(flat.mVertices - flat.mCapSplitVertices == mesh.mVertices - mesh.mCapSplitVertices);
    }

    SECTION("the procedural box has no mesh to prepare")
    {
        CHECK_FALSE(ShortCrash(Shipped("box car")).mMeshPreparation.has_value());
    }
}
