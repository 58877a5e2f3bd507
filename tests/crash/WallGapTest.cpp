// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// The wall gap (crumple-crash's wall_gap_m): how far the front a flat wall struck ended behind the wall's
// final plane. Known answers on fronts moved by hand, then a crash: a flat front stays flat.
#include <crumple/crash/CrashRun.h>
#include <crumple/crash/WallGap.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

using namespace crumple;
using namespace crumple::crash;

namespace
{

// A body's front face at x = 1 (normal +x) over |y|, |z| < 0.5, its vertices 5 cm apart and off the 10 cm
// squares' edges, and its two sides (normal -y, +y) from x = 0 to 1 at y = -0.5 and 0.5; the wall's normal
// into the wall is +x.
struct Front
{
    ffd::TriangleMesh mRest;
    std::vector<Vec3> mNormals;
    std::vector<Vec3> mPositions;

    Front()
    {
        for (int j = 0; j < 20; ++j)
            for (int k = 0; k < 20; ++k)
                Add(Vec3(1.0, -0.475 + 0.05 * j, -0.475 + 0.05 * k), Vec3::UnitX());
        for (double side : {-0.5, 0.5})
            for (int i = 0; i <= 20; ++i)
                for (int k = 0; k < 20; ++k)
                    Add(Vec3(0.05 * i, side, -0.475 + 0.05 * k), Vec3(0.0, side > 0.0 ? 1.0 : -1.0, 0.0));
        mPositions = mRest.mPositions;
    }
    void Add(const Vec3& inPoint, const Vec3& inNormal)
    {
        mRest.mPositions.push_back(inPoint);
        mNormals.push_back(inNormal);
    }
    // Crushed to the plane x = inPlane (inBehind further where y < 0): the face moves onto it, and what lay
    // ahead of it on the sides is packed behind it to a quarter of its length, as a crush packs it.
    void Crush(double inPlane, double inBehind = 0.0)
    {
        for (std::size_t v = 0; v < mPositions.size(); ++v)
        {
            const Vec3& rest = mRest.mPositions[v];
            const double plane = inPlane - (rest.y() < 0.0 ? inBehind : 0.0);
            if (mNormals[v].x() > 0.5)
                mPositions[v].x() = plane;
            else if (rest.x() > plane)
                mPositions[v].x() = plane - 0.25 * (rest.x() - plane);
        }
    }
    WallGap Gap() const { return MeasureWallGap(mRest, mNormals, mPositions, Vec3::UnitX()); }
};

} // namespace

TEST_CASE("Wall gap: a front crushed flat onto the wall has none, whatever its sides do", "[crash]")
{
    Front front;
    front.Crush(0.7);
    const WallGap gap = front.Gap();
    CHECK(gap.mSquares == 100);
    CHECK(gap.mMean == 0.0);
    CHECK(gap.mLargest == 0.0);
}

TEST_CASE(
    "Wall gap: half the front pushed 10 cm past the wall's plane gives a mean of 5 cm and a largest of 10",
    "[crash]")
{
    Front front;
    front.Crush(0.7, 0.1);
    const WallGap gap = front.Gap();
    CHECK(gap.mSquares == 100);
    CHECK(gap.mMean == Approx(0.05).epsilon(1.0e-12));
    CHECK(gap.mLargest == Approx(0.1).epsilon(1.0e-12));
}

TEST_CASE("Wall gap: only moves over 1 cm count, and only what lay ahead of the wall's final plane",
          "[crash]")
{
    Front untouched;
    const WallGap none = untouched.Gap();
    CHECK(none.mSquares == 0);
    CHECK(none.mMean == 0.0);
    // Moved 5 mm: not the wall's. Its plane is then the foremost vertex that moved more than 1 cm.
    Front shallow;
    shallow.Crush(0.995);
    CHECK(shallow.Gap().mSquares == 0);
    // Arrays of different lengths: nothing measured, nothing read past an end.
    Front short_normals;
    short_normals.Crush(0.7);
    short_normals.mNormals.pop_back();
    const WallGap mismatched = short_normals.Gap();
    CHECK(mismatched.mSquares == 0);
    CHECK(std::isnan(mismatched.mMean));
    CHECK(std::isnan(mismatched.mLargest));
    // A part of the face that the wall did not reach (it stayed at x = 1, behind no plane) is not in it, and
    // the side packed behind a plane 0.3 m back is not either: the face's other half, pushed onto it,
    // conforms.
    Front half;
    half.Crush(0.7);
    for (std::size_t v = 0; v < half.mPositions.size(); ++v)
        if (half.mNormals[v].x() > 0.5 && half.mRest.mPositions[v].y() < 0.0)
            half.mPositions[v] = half.mRest.mPositions[v];
    const WallGap offset = half.Gap();
    CHECK(offset.mSquares == 50);
    CHECK(offset.mLargest == 0.0);
}

TEST_CASE("Wall gap: an offset wall's gap counts only the part it covers, and takes its plane there",
          "[crash]")
{
    // The face's y < 0 half pushed 0.1 m further than the rest: a whole wall sees a gap of 0.1 m there. A
    // wall that covers y >= 0 only does not, nor does its plane come from the other half.
    Front front;
    front.Crush(0.7, 0.1);
    const WallReach covers_positive_y{Vec3::UnitY(), 0.0};
    const WallGap covered =
        MeasureWallGap(front.mRest, front.mNormals, front.mPositions, Vec3::UnitX(), &covers_positive_y);
    CHECK(covered.mSquares == 50);
    CHECK(covered.mLargest == 0.0);
    // The other half alone: its own plane 0.1 m further back, on which it ends flat.
    const WallReach covers_negative_y{-Vec3::UnitY(), 0.0};
    const WallGap other =
        MeasureWallGap(front.mRest, front.mNormals, front.mPositions, Vec3::UnitX(), &covers_negative_y);
    CHECK(other.mSquares == 50);
    CHECK(other.mLargest == Approx(0.0).margin(1.0e-15));
}

// A flat-fronted car into a flat wall: the struck face must end on the wall's plane, to the lattice's
// resolution (full wall: largest 0.8 mm at 20 km/h and 1.8-1.9 mm at 56 km/h in both engines; 40 % offset:
// 1 mm at 56 km/h; bound 5 mm).
TEST_CASE(
    "Wall gap: the box car's flat front crushed by a full or an offset wall ends flat, in Bullet and ODE",
    "[crash]")
{
    for (EEngine engine : {EEngine::Bullet, EEngine::Ode})
        for (double km_h : {20.0, 56.0})
            for (ETarget target : {ETarget::RigidWall, ETarget::OffsetWall})
            {
                CrashScenario scenario;
                scenario.mName = "box car into a wall";
                scenario.mEngine = engine;
                scenario.mDuration = 0.3;
                scenario.mVehicle.mBoxSize = Vec3(4.4, 1.65, 1.4);
                scenario.mVehicle.mMass = 1575.0;
                scenario.mImpact.mSpeed = km_h / 3.6;
                scenario.mTarget.mType = target;
                const Result<CrashOutcome> outcome = RunCrash(scenario, {});
                REQUIRE(outcome);
                REQUIRE(outcome.Get().mWallGap);
                const WallGap& gap = *outcome.Get().mWallGap;
                INFO(km_h << " km/h, " << (target == ETarget::RigidWall ? "full" : "offset") << " wall, "
                          << (engine == EEngine::Bullet ? "Bullet" : "ODE") << ": mean " << gap.mMean
                          << " m, largest " << gap.mLargest << " m over " << gap.mSquares << " squares");
                CHECK(gap.mSquares > (target == ETarget::RigidWall ? 200 : 50));
                CHECK(gap.mLargest < 0.005);
                Expectation mean;
                mean.mQuantity = EQuantity::WallGap;
                CHECK(outcome.Get().Measure(mean) == gap.mMean);
            }
}
