// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/ffd/FoldGuard.h>

#include "DrawVec3.h"
#include "SameBytes.h"

#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include <cmath>
#include <cstring>
#include <random>

using namespace crumple;
using crumple::common::SameBytes;
using namespace crumple::ffd;

namespace
{

constexpr double cMinSpacing = 0.2;

// 8 x 5 x 5 controls, 0.4 m spacing along every axis.
FfdLattice MakeLattice(const Mat3& inAxes = Mat3::Identity())
{
    FfdLatticeSettings settings;
    settings.mOrigin = Vec3(-1.0, -0.4, -0.4);
    settings.mAxes = inAxes;
    settings.mControlCount = {8, 5, 5};
    settings.mSize = Vec3(5 * 0.4, 2 * 0.4, 2 * 0.4);
    return FfdLattice::Create(settings).Get();
}

Mat3 Rotated()
{
    return (Eigen::AngleAxisd(0.5, Vec3::UnitZ()) * Eigen::AngleAxisd(-0.3, Vec3(1.0, 1.0, 0.0).normalized()))
        .toRotationMatrix();
}

// Smallest gap between neighbouring controls of any lattice line, in the lattice frame, over the spacing.
double MinRelativeGap(const FfdLattice& inLattice, const std::vector<Vec3>& inDisplacements)
{
    const auto& n = inLattice.GetSettings().mControlCount;
    const Mat3& axes = inLattice.GetSettings().mAxes;
    double smallest = std::numeric_limits<double>::infinity();
    for (int c = 0; c < n[2]; ++c)
        for (int b = 0; b < n[1]; ++b)
            for (int a = 0; a < n[0]; ++a)
            {
                const std::array<int, 3> here{{a, b, c}};
                const Vec3 x = axes.transpose() *
                               (inLattice.RestControlPosition(a, b, c) +
                                inDisplacements[static_cast<std::size_t>(inLattice.ControlIndex(a, b, c))]);
                for (int axis = 0; axis < 3; ++axis)
                {
                    std::array<int, 3> next = here;
                    if (++next[static_cast<std::size_t>(axis)] >= n[static_cast<std::size_t>(axis)])
                        continue;
                    const int k = inLattice.ControlIndex(next[0], next[1], next[2]);
                    const Vec3 y = axes.transpose() * (inLattice.RestControlPosition(next[0], next[1], next[2]) +
                                                       inDisplacements[static_cast<std::size_t>(k)]);
                    smallest = std::min(smallest, (y[axis] - x[axis]) / inLattice.GetSpacing()[axis]);
                }
            }
    return smallest;
}

} // namespace

TEST_CASE("FoldGuard changes nothing when no pair violates", "[ffd]")
{
    for (const Mat3& axes : {Mat3(Mat3::Identity()), Rotated()})
    {
        const FfdLattice lattice = MakeLattice(axes);
        const auto count = static_cast<std::size_t>(lattice.GetControlCount());
        std::mt19937 random(7);
        std::uniform_real_distribution<double> small(-0.05, 0.05); // gaps stay above 0.5 h
        std::vector<Vec3> before(count, Vec3::Zero());
        for (Vec3& d : before)
            d = common::DrawVec3([&] { return small(random); });
        std::vector<Vec3> after = before;
        std::vector<int> changed;
        for (int control = 3; control < static_cast<int>(count); control += 7)
        {
            after[static_cast<std::size_t>(control)] += common::DrawVec3([&] { return small(random); });
            changed.push_back(control);
        }
        REQUIRE(MinRelativeGap(lattice, after) > cMinSpacing);
        const std::vector<Vec3> wanted = after;
        CHECK(FoldGuard(lattice, before, after, changed, cMinSpacing).empty());
        CHECK(SameBytes(after, wanted));
    }
}

TEST_CASE("A control pushed past its neighbours along +x pushes them along (rear impact)", "[ffd]")
{
    const FfdLattice lattice = MakeLattice();
    const double h = lattice.GetSpacing().x();
    const std::vector<Vec3> before(static_cast<std::size_t>(lattice.GetControlCount()), Vec3::Zero());
    std::vector<Vec3> after = before;
    const int pusher = lattice.ControlIndex(2, 2, 1);
    after[static_cast<std::size_t>(pusher)] = Vec3(2.5 * h, 0.0, 0.0); // past controls 3 and 4 of its line
    const std::vector<int> changed{pusher};
    REQUIRE(MinRelativeGap(lattice, after) < 0.0); // folded as proposed

    const std::vector<int> moved = FoldGuard(lattice, before, after, changed, cMinSpacing);

    // The pusher sits at 3.5 h (lattice x, rest of control j at (j - 1) h): control 3 must reach 3.7 h,
    // 4 must reach 3.9 h and 5 must reach 4.1 h; control 6 (rest 5 h) is already clear.
    CHECK(moved == std::vector<int>{lattice.ControlIndex(3, 2, 1), lattice.ControlIndex(4, 2, 1),
                                    lattice.ControlIndex(5, 2, 1)});
    CHECK(after[static_cast<std::size_t>(pusher)] == Vec3(2.5 * h, 0.0, 0.0)); // keeps its wanted position
    CHECK(after[static_cast<std::size_t>(lattice.ControlIndex(3, 2, 1))].x() == Approx(1.7 * h).epsilon(1e-8));
    CHECK(after[static_cast<std::size_t>(lattice.ControlIndex(4, 2, 1))].x() == Approx(0.9 * h).epsilon(1e-8));
    CHECK(after[static_cast<std::size_t>(lattice.ControlIndex(5, 2, 1))].x() == Approx(0.1 * h).epsilon(1e-7));
    for (int control : moved)
    {
        // Only along the axis, only forward.
        CHECK(after[static_cast<std::size_t>(control)].y() == 0.0);
        CHECK(after[static_cast<std::size_t>(control)].z() == 0.0);
        CHECK(after[static_cast<std::size_t>(control)].x() > 0.0);
    }
    CHECK(after[static_cast<std::size_t>(lattice.ControlIndex(1, 2, 1))] == Vec3::Zero()); // behind: untouched
    CHECK(MinRelativeGap(lattice, after) >= cMinSpacing);
}

TEST_CASE("A push toward -x cascades toward lower indices (front impact), also in a rotated lattice", "[ffd]")
{
    for (const Mat3& axes : {Mat3(Mat3::Identity()), Rotated()})
    {
        const FfdLattice lattice = MakeLattice(axes);
        const double h = lattice.GetSpacing().x();
        const Vec3 direction = axes.col(0);
        const std::vector<Vec3> before(static_cast<std::size_t>(lattice.GetControlCount()), Vec3::Zero());
        std::vector<Vec3> after = before;
        const int pusher = lattice.ControlIndex(6, 1, 3);
        const Vec3 wanted = -2.5 * h * direction + Vec3(0.01, -0.02, 0.03); // mostly along -x, a bit sideways
        after[static_cast<std::size_t>(pusher)] = wanted;
        const std::vector<int> changed{pusher};

        const std::vector<int> moved = FoldGuard(lattice, before, after, changed, cMinSpacing);

        CHECK(moved == std::vector<int>{lattice.ControlIndex(3, 1, 3), lattice.ControlIndex(4, 1, 3),
                                        lattice.ControlIndex(5, 1, 3)});
        CHECK(after[static_cast<std::size_t>(pusher)] == wanted);
        for (int control : moved)
        {
            // Moved backwards along the lattice's x axis only: no component across it.
            const Vec3& d = after[static_cast<std::size_t>(control)];
            CHECK(d.dot(direction) < 0.0);
            CHECK((d - d.dot(direction) * direction).norm() < 1.0e-14);
        }
        CHECK(after[static_cast<std::size_t>(lattice.ControlIndex(7, 1, 3))] == Vec3::Zero());
        CHECK(after[static_cast<std::size_t>(lattice.ControlIndex(2, 1, 3))] == Vec3::Zero());
        CHECK(MinRelativeGap(lattice, after) >= cMinSpacing);
    }
}

TEST_CASE("FoldGuard handles pushes along y and z, and earlier dents", "[ffd]")
{
    const FfdLattice lattice = MakeLattice(Rotated());
    const auto count = static_cast<std::size_t>(lattice.GetControlCount());
    const Mat3& axes = lattice.GetSettings().mAxes;
    const double h = 0.4;

    // An earlier dent, already ordered: the whole plane x = 4 moved by -0.3 h.
    std::vector<Vec3> before(count, Vec3::Zero());
    for (int c = 0; c < 5; ++c)
        for (int b = 0; b < 5; ++b)
            before[static_cast<std::size_t>(lattice.ControlIndex(4, b, c))] = -0.3 * h * axes.col(0);
    REQUIRE(MinRelativeGap(lattice, before) >= cMinSpacing);

    // This dent: one control down z by 1.5 h, another up y by 1.2 h, one more back along x by 0.8 h.
    std::vector<Vec3> after = before;
    const std::vector<int> changed{lattice.ControlIndex(1, 1, 3), lattice.ControlIndex(4, 2, 2),
                                   lattice.ControlIndex(6, 3, 1)};
    after[static_cast<std::size_t>(changed[0])] += -1.5 * h * axes.col(2);
    after[static_cast<std::size_t>(changed[1])] += -0.8 * h * axes.col(0);
    after[static_cast<std::size_t>(changed[2])] += 1.2 * h * axes.col(1);
    const std::vector<Vec3> wanted = after;

    const std::vector<int> moved = FoldGuard(lattice, before, after, changed, cMinSpacing);

    CHECK(!moved.empty());
    for (int control : changed)
        CHECK(after[static_cast<std::size_t>(control)] == wanted[static_cast<std::size_t>(control)]);
    CHECK(MinRelativeGap(lattice, after) >= cMinSpacing);
    // z push: the control below on that line yields downward.
    CHECK(axes.col(2).dot(after[static_cast<std::size_t>(lattice.ControlIndex(1, 1, 2))]) < 0.0);
    // y push: the control above on that line yields upward.
    CHECK(axes.col(1).dot(after[static_cast<std::size_t>(lattice.ControlIndex(6, 4, 1))]) > 0.0);
    // x push from the dented plane: control 3 yields backward, control 5 (rest ahead) does not move.
    CHECK(axes.col(0).dot(after[static_cast<std::size_t>(lattice.ControlIndex(3, 2, 2))]) < 0.0);
    CHECK(after[static_cast<std::size_t>(lattice.ControlIndex(5, 2, 2))] == Vec3::Zero());
    // Deterministic: the same input gives the same bytes.
    std::vector<Vec3> again = wanted;
    CHECK(FoldGuard(lattice, before, again, changed, cMinSpacing) == moved);
    CHECK(SameBytes(again, after));
}

TEST_CASE("Controls that move into each other meet around their midpoint", "[ffd]")
{
    const FfdLattice lattice = MakeLattice();
    const double h = lattice.GetSpacing().x();
    const std::vector<Vec3> before(static_cast<std::size_t>(lattice.GetControlCount()), Vec3::Zero());
    std::vector<Vec3> after = before;
    const int left = lattice.ControlIndex(3, 2, 2);
    const int right = lattice.ControlIndex(4, 2, 2);
    after[static_cast<std::size_t>(left)] = Vec3(0.6 * h, 0.0, 0.0);   // to 2.6 h
    after[static_cast<std::size_t>(right)] = Vec3(-0.6 * h, 0.0, 0.0); // to 2.4 h
    const std::vector<int> changed{left, right};

    const std::vector<int> moved = FoldGuard(lattice, before, after, changed, cMinSpacing);

    // Midpoint 2.5 h, gap 0.2 h: 2.4 h and 2.6 h, the neighbours (at h and 4 h) stay clear.
    CHECK(moved == std::vector<int>{left, right});
    CHECK(after[static_cast<std::size_t>(left)].x() == Approx(0.4 * h).epsilon(1e-8));
    CHECK(after[static_cast<std::size_t>(right)].x() == Approx(-0.4 * h).epsilon(1e-8));
    CHECK(MinRelativeGap(lattice, after) >= cMinSpacing);
}

TEST_CASE("Controls meet around their midpoint when one of them had moved in an earlier dent", "[ffd]")
{
    // The right control moved forward by 0.3 h in an earlier dent; this dent moves it back to 0.05 h (down
    // the line, toward the left one) while the left one moves up by h: both moved into each other in this
    // dent, so they meet at the midpoint of where this dent wanted them (measured from the state before it,
    // not from rest: from rest the right one would seem to have moved up and be pushed along instead).
    const FfdLattice lattice = MakeLattice();
    const double h = lattice.GetSpacing().x();
    const int left = lattice.ControlIndex(3, 2, 2);
    const int right = lattice.ControlIndex(4, 2, 2);
    std::vector<Vec3> before(static_cast<std::size_t>(lattice.GetControlCount()), Vec3::Zero());
    before[static_cast<std::size_t>(right)] = Vec3(0.3 * h, 0.0, 0.0);
    std::vector<Vec3> after = before;
    after[static_cast<std::size_t>(left)] = Vec3(1.0 * h, 0.0, 0.0);
    after[static_cast<std::size_t>(right)] = Vec3(0.05 * h, 0.0, 0.0);
    const std::vector<int> changed{left, right};

    const std::vector<int> moved = FoldGuard(lattice, before, after, changed, cMinSpacing);

    // Midpoint of the wanted displacements 0.525 h, gap 0.2 h: 0.925 h and 0.125 h.
    CHECK(moved == std::vector<int>{left, right});
    CHECK(after[static_cast<std::size_t>(left)].x() == Approx(0.925 * h).epsilon(1e-8));
    CHECK(after[static_cast<std::size_t>(right)].x() == Approx(0.125 * h).epsilon(1e-8));
    CHECK(MinRelativeGap(lattice, after) >= cMinSpacing);
}

TEST_CASE("FoldGuard with a zero minimum spacing does nothing", "[ffd]")
{
    const FfdLattice lattice = MakeLattice();
    const std::vector<Vec3> before(static_cast<std::size_t>(lattice.GetControlCount()), Vec3::Zero());
    std::vector<Vec3> after = before;
    const int pusher = lattice.ControlIndex(2, 2, 1);
    after[static_cast<std::size_t>(pusher)] = Vec3(1.0, 0.0, 0.0);
    const std::vector<Vec3> wanted = after;
    const std::vector<int> changed{pusher};
    CHECK(FoldGuard(lattice, before, after, changed, 0.0).empty());
    CHECK(SameBytes(after, wanted));
}
