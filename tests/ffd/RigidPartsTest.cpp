// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// Rigid parts (FfdDeformerSettings::mRigidParts): a wheel beside a car body's front keeps its shape when a
// crush reaches it, and moves exactly as the lattice moves the centre of its bounding box.
#include "BoxMesh.h"

#include <crumple/ffd/FfdDeformer.h>
#include <crumple/plugin/DeformableObjectSettings.h>

#include <catch2/catch.hpp>

#include <cstring>

using namespace crumple;
using namespace crumple::ffd;

namespace
{

// A 4 m body and a separate 0.6 m "wheel" box under its front corner, one mesh; the wheel's vertices last.
struct BodyAndWheel
{
    TriangleMesh mMesh;
    std::vector<std::uint32_t> mWheel;
    Vec3 mWheelCentre;
};

BodyAndWheel MakeBodyAndWheel()
{
    BodyAndWheel made;
    made.mMesh = common::MakeBoxMesh(Vec3(2.0, 0.9, 0.5), {40, 18, 10});
    made.mWheelCentre = Vec3(1.35, 0.7, -0.45);
    TriangleMesh wheel = common::MakeBoxMesh(Vec3(0.3, 0.1, 0.3), {6, 2, 6});
    const auto base = static_cast<std::uint32_t>(made.mMesh.mPositions.size());
    for (const Vec3& p : wheel.mPositions)
    {
        made.mWheel.push_back(static_cast<std::uint32_t>(made.mMesh.mPositions.size()));
        made.mMesh.mPositions.push_back(p + made.mWheelCentre);
    }
    for (const auto& t : wheel.mTriangles)
        made.mMesh.mTriangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    return made;
}

FfdDeformer MakeDeformer(const BodyAndWheel& inMade, bool inRigidWheel)
{
    FfdDeformerSettings settings;
    settings.mZones.push_back(plugin::FitZoneToMesh(inMade.mMesh, {10, 6, 6}, 1.0));
    if (inRigidWheel)
        settings.mRigidParts.push_back(inMade.mWheel);
    return FfdDeformer::Create(inMade.mMesh, settings).Get();
}

// A deep push on the front face, over its lower half (where the wheel sits behind it).
std::vector<PointDisplacement> FrontCrush()
{
    std::vector<PointDisplacement> points;
    for (double y : {-0.6, -0.2, 0.2, 0.6})
        for (double z : {-0.4, -0.1})
            points.push_back({Vec3(2.0, y, z), Vec3(-0.45, 0.0, 0.0)});
    return points;
}

// The largest change of a distance between two of inVertices (m): zero for a rigid translation.
double Distortion(const FfdDeformer& inDeformer, const std::vector<std::uint32_t>& inVertices)
{
    const std::vector<Vec3>& rest = inDeformer.GetRestMesh().mPositions;
    const std::vector<Vec3>& now = inDeformer.GetPositions();
    double largest = 0.0;
    for (std::uint32_t a : inVertices)
        for (std::uint32_t b : inVertices)
            largest = std::max(largest, std::abs((now[a] - now[b]).norm() - (rest[a] - rest[b]).norm()));
    return largest;
}

} // namespace

TEST_CASE("A rigid part moves as the lattice moves its centre and keeps its shape, a free one is squashed", "[ffd]")
{
    const BodyAndWheel made = MakeBodyAndWheel();
    FfdDeformer free = MakeDeformer(made, false);
    FfdDeformer rigid = MakeDeformer(made, true);
    REQUIRE(free.ApplyDent(FrontCrush(), 1.0));
    REQUIRE(rigid.ApplyDent(FrontCrush(), 1.0));

    // The body dents the same either way (the part changes nothing of the solve).
    const std::vector<Vec3>& free_positions = free.GetPositions();
    const std::vector<Vec3>& rigid_positions = rigid.GetPositions();
    REQUIRE(std::memcmp(free_positions.data(), rigid_positions.data(), made.mWheel.front() * sizeof(Vec3)) == 0);

    // Free, the crush's field squashes the wheel; rigid, every vertex moves by the same vector, bitwise,
    // the lattice's displacement at the centre of the wheel's rest box.
    INFO("free wheel distorted by " << Distortion(free, made.mWheel) << " m");
    CHECK(Distortion(free, made.mWheel) > 0.01);
    const FfdLattice& zone = rigid.GetZones()[0];
    const Vec3 expected = zone.Displacement(zone.Locate(zone.LatticeCoordinate(made.mWheelCentre)));
    CHECK(expected.norm() > 0.01); // the crush reached it
    for (std::uint32_t v : made.mWheel)
    {
        const Vec3 moved = rigid_positions[v] - rigid.GetRestMesh().mPositions[v];
        CHECK((moved - expected).cwiseAbs().maxCoeff() <= 1.0e-15 * (1.0 + rigid.GetRestMesh().mPositions[v].norm()));
    }
    CHECK(Distortion(rigid, made.mWheel) <= 1.0e-12);

    // Incremental updates and a full recompute agree bit for bit with the part.
    const std::vector<Vec3> incremental = rigid.GetPositions();
    rigid.RecomputeAll();
    CHECK(std::memcmp(incremental.data(), rigid.GetPositions().data(), incremental.size() * sizeof(Vec3)) == 0);
}

TEST_CASE("Rigid parts that are empty, overlap or name no vertex are refused", "[ffd]")
{
    const BodyAndWheel made = MakeBodyAndWheel();
    FfdDeformerSettings settings;
    settings.mZones.push_back(plugin::FitZoneToMesh(made.mMesh, {10, 6, 6}, 1.0));
    const auto vertices = static_cast<std::uint32_t>(made.mMesh.mPositions.size());
    struct Bad
    {
        std::vector<std::vector<std::uint32_t>> mParts;
        EError mCode;
        const char* mSays;
    } bad[] = {{{{}}, EError::InvalidArgument, "mRigidParts[0] is empty"},
               {{{0, 1}, {2, vertices}}, EError::OutOfRange, "mRigidParts[1] names vertex"},
               {{{0, 1}, {3, 1}}, EError::InvalidArgument, "mRigidParts[1]: vertex 1"},
               {{{4, 4}}, EError::InvalidArgument, "mRigidParts[0]: vertex 4"}};
    for (const Bad& b : bad)
    {
        settings.mRigidParts = b.mParts;
        const Result<FfdDeformer> made_deformer = FfdDeformer::Create(made.mMesh, settings);
        REQUIRE(made_deformer.HasError());
        INFO(made_deformer.GetError().mMessage);
        CHECK(made_deformer.GetError().mCode == b.mCode);
        CHECK(made_deformer.GetError().mMessage.find(b.mSays) != std::string::npos);
    }
}
