// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// The crush profile crumple-crash reports (CRASH3's C1..C6 and their average) is measured on the face the
// crash struck: known answers on a box car whose faces are moved by hand.
#include "BoxMesh.h"

#include <crumple/crash/CrashRun.h>

#include <catch2/catch.hpp>

#include <vector>

using namespace crumple;
using namespace crumple::crash;

namespace
{

const Vec3 cHalf(2.2, 0.825, 0.7);

// The box car with every vertex that inSelect picks moved by inMove (m, body frame).
std::vector<Vec3> Moved(const ffd::TriangleMesh& inRest, bool (*inSelect)(const Vec3&), const Vec3& inMove)
{
    std::vector<Vec3> positions = inRest.mPositions;
    for (Vec3& p : positions)
        if (inSelect(p))
            p += inMove;
    return positions;
}

void CheckUniform(const CrushProfile& inProfile, ECarFace inFace, double inDepth, double inWidth)
{
    INFO(CarFaceName(inProfile.mFace)
         << " profile over " << inProfile.mDamageWidth << " m, average " << inProfile.Average());
    CHECK(inProfile.mFace == inFace);
    CHECK(inProfile.mDamageWidth == Approx(inWidth).margin(1.0e-9));
    for (double c : inProfile.mC)
        CHECK(c == Approx(inDepth).margin(1.0e-12));
    CHECK(inProfile.Average() == Approx(inDepth).margin(1.0e-12));
}

} // namespace

TEST_CASE("The crush profile is measured on the face the crash struck", "[crash]")
{
    const ffd::TriangleMesh rest = common::MakeBoxMesh(cHalf, common::BoxSegmentsForTriangles(cHalf, 8000));
    // The front pushed back 0.25 m over the whole width.
    const std::vector<Vec3> front = Moved(
        rest, [](const Vec3& p) { return p.x() >= 1.6; }, Vec3(-0.25, 0.0, 0.0));
    CheckUniform(StruckCrushProfile(rest, front), ECarFace::Front, 0.25, 2.0 * cHalf.y());
    // A reverse into a wall: the rear pushed forward 0.2 m. Before, the report measured the front: all zero.
    const std::vector<Vec3> rear = Moved(
        rest, [](const Vec3& p) { return p.x() <= -1.6; }, Vec3(0.2, 0.0, 0.0));
    CheckUniform(StruckCrushProfile(rest, rear), ECarFace::Rear, 0.2, 2.0 * cHalf.y());
    CHECK(FaceCrushProfile(rest, rear, ECarFace::Front).Average() == 0.0);
    // A side hit: the left side between x = -1 and 1 pushed in 0.15 m.
    const std::vector<Vec3> left = Moved(
        rest, [](const Vec3& p) { return p.y() >= 0.5 && std::abs(p.x()) <= 1.0; }, Vec3(0.0, -0.15, 0.0));
    const CrushProfile side = StruckCrushProfile(rest, left);
    CHECK(side.mFace == ECarFace::Left);
    CHECK(side.mDamageWidth <= 2.0 + 1.0e-9);
    CHECK(side.mDamageWidth >= 1.8);
    CHECK(side.Average() == Approx(0.15).margin(1.0e-12));
    // The right side, mirrored.
    const std::vector<Vec3> right = Moved(
        rest, [](const Vec3& p) { return p.y() <= -0.5 && std::abs(p.x()) <= 1.0; }, Vec3(0.0, 0.15, 0.0));
    CHECK(StruckCrushProfile(rest, right).mFace == ECarFace::Right);
    // Nothing moved: the front's empty profile.
    const CrushProfile none = StruckCrushProfile(rest, rest.mPositions);
    CHECK(none.mFace == ECarFace::Front);
    CHECK(none.mDamageWidth == 0.0);
    CHECK(none.Average() == 0.0);
}
