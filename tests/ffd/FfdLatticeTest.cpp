// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/ffd/CubicBSplineWeights.h>
#include <crumple/ffd/FfdLattice.h>

#include "DrawVec3.h"

#include <catch2/catch.hpp>

#include <limits>
#include <random>

using namespace crumple;
using namespace crumple::ffd;

namespace
{

FfdLatticeSettings RotatedBox()
{
    FfdLatticeSettings settings;
    settings.mOrigin = Vec3(-1.0, 0.5, 0.25);
    settings.mAxes = Eigen::AngleAxisd(0.3, Vec3(1.0, 2.0, 3.0).normalized()).toRotationMatrix();
    settings.mSize = Vec3(2.0, 1.5, 1.0);
    settings.mControlCount = {7, 5, 4};
    return settings;
}

} // namespace

TEST_CASE("FfdLattice refuses bad settings with a clear error", "[ffd]")
{
    SECTION("fewer than four controls")
    {
        FfdLatticeSettings settings;
        settings.mControlCount = {4, 3, 4};
        Result<FfdLattice> lattice = FfdLattice::Create(settings);
        REQUIRE(lattice.HasError());
        CHECK(lattice.GetError().mCode == EError::InvalidArgument);
        CHECK(lattice.GetError().mMessage.find("mControlCount.y") != std::string::npos);
    }
    SECTION("degenerate volume")
    {
        FfdLatticeSettings settings;
        settings.mSize = Vec3(1.0, 0.0, 1.0);
        CHECK(FfdLattice::Create(settings).GetError().mCode == EError::DegenerateGeometry);
        settings.mSize = Vec3(1.0, -2.0, 1.0);
        CHECK(FfdLattice::Create(settings).GetError().mCode == EError::DegenerateGeometry);
    }
    SECTION("NaN and Inf")
    {
        FfdLatticeSettings settings;
        settings.mOrigin.x() = std::numeric_limits<double>::quiet_NaN();
        CHECK(FfdLattice::Create(settings).GetError().mCode == EError::NonFinite);
        settings = {};
        settings.mSize.z() = std::numeric_limits<double>::infinity();
        CHECK(FfdLattice::Create(settings).GetError().mCode == EError::NonFinite);
    }
    SECTION("an origin or a size beyond 1e7 m")
    {
        // A lattice 1e308 m across loses the precision of its coordinates: a dent at one end moved the other.
        FfdLatticeSettings settings;
        settings.mOrigin.x() = -1.7e308;
        settings.mSize.x() = 1.7e308;
        CHECK(FfdLattice::Create(settings).GetError().mCode == EError::OutOfRange);
        settings = {};
        settings.mSize.y() = 2.0e7;
        CHECK(FfdLattice::Create(settings).GetError().mCode == EError::OutOfRange);
        settings = {};
        settings.mOrigin = Vec3(-1.0e7, 0.0, 1.0e7);
        settings.mSize = Vec3(1.0e7, 1.0, 1.0);
        CHECK(FfdLattice::Create(settings).IsValid());
    }
    SECTION("axes that are not a rotation")
    {
        FfdLatticeSettings settings;
        settings.mAxes(0, 0) = -1.0; // a reflection
        CHECK(FfdLattice::Create(settings).GetError().mCode == EError::DegenerateGeometry);
        settings.mAxes = 2.0 * Mat3::Identity();
        CHECK(FfdLattice::Create(settings).GetError().mCode == EError::DegenerateGeometry);
    }
}

TEST_CASE("FfdLattice spans only where the spline is defined", "[ffd]")
{
    const FfdLattice lattice = FfdLattice::Create(RotatedBox()).Get();
    CHECK(lattice.GetCellCount() == std::array<int, 3>{4, 2, 1});
    CHECK(lattice.GetSpacing().isApprox(Vec3(0.5, 0.75, 1.0)));
    const FfdLatticeSettings& s = lattice.GetSettings();
    // The far box corner has lattice coordinate (n-3) and sits in the last cell with t = 1.
    const Vec3 far = s.mOrigin + s.mAxes * s.mSize;
    const Vec3 u = lattice.LatticeCoordinate(far);
    CHECK(u.isApprox(Vec3(4.0, 2.0, 1.0), 1.0e-12));
    const LatticeLocation location = lattice.Locate(u);
    CHECK(location.mCell == std::array<int, 3>{3, 1, 0});
    CHECK(location.mT.isApprox(Vec3::Ones(), 1.0e-12));
    CHECK(lattice.Contains(u, 1.0e-9));
    CHECK_FALSE(lattice.Contains(Vec3(-0.1, 0.0, 0.0)));
    CHECK(lattice.DistanceToBox(s.mOrigin - 0.2 * s.mAxes.col(1)) == Approx(0.2));
}

TEST_CASE("An undeformed lattice reproduces every point", "[ffd]")
{
    const FfdLattice lattice = FfdLattice::Create(RotatedBox()).Get();
    const FfdLatticeSettings& s = lattice.GetSettings();
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < 2000; ++i)
    {
        const Vec3 p =
            s.mOrigin + s.mAxes * common::DrawVec3([&] { return unit(random); }).cwiseProduct(s.mSize);
        const LatticeLocation location = lattice.Locate(lattice.LatticeCoordinate(p));
        // Displacement form: exactly zero, so rest + displacement is the rest point bit for bit.
        REQUIRE(lattice.Displacement(location) == Vec3::Zero());
        // Absolute form: sum of weights times rest control positions (independent of Displacement()).
        const auto wx = CubicBSplineWeights(location.mT.x());
        const auto wy = CubicBSplineWeights(location.mT.y());
        const auto wz = CubicBSplineWeights(location.mT.z());
        Vec3 sum = Vec3::Zero();
        for (int c = 0; c < 4; ++c)
            for (int b = 0; b < 4; ++b)
                for (int a = 0; a < 4; ++a)
                    sum += wx[static_cast<std::size_t>(a)] * wy[static_cast<std::size_t>(b)] * wz[static_cast<std::size_t>(c)] *
                           lattice.RestControlPosition(location.mCell[0] + a, location.mCell[1] + b, location.mCell[2] + c);
        REQUIRE((sum - p).norm() <= 1.0e-12 * (1.0 + p.norm()));
    }
}

TEST_CASE("A control reaches only the four cells around it per axis", "[ffd]")
{
    FfdLatticeSettings settings;
    settings.mSize = Vec3(9.0, 9.0, 9.0);
    settings.mControlCount = {12, 12, 12}; // 9 cells of 1 m
    FfdLattice lattice = FfdLattice::Create(settings).Get();
    lattice.GetControlDisplacements()[static_cast<std::size_t>(lattice.ControlIndex(6, 6, 6))] = Vec3(0.0, 0.0, 1.0);
    for (int i = 0; i < 9; ++i)
    {
        LatticeLocation location;
        location.mCell = {i, 4, 4};
        location.mT = Vec3(0.5, 0.5, 0.5);
        const bool reached = i >= 3 && i <= 6;
        CHECK((lattice.Displacement(location).z() > 0.0) == reached);
    }
}
