// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// White-box: the AVX tensor-product sum FfdLattice::Displacement takes on processors that have AVX gives the
// scalar sum's bits (so a dent, a replay and a golden hash are the same on every x86-64 machine), and the
// scalar sum is the B-spline sum itself.
#include "TensorProductSum.h"
#include "DrawVec3.h"

#include <SkipTest.h>

#include <crumple/ffd/CubicBSplineWeights.h>
#include <crumple/ffd/FfdLattice.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

using namespace crumple;
using namespace crumple::ffd;

namespace
{

bool SameBytes(const Vec3& inA, const Vec3& inB)
{
    return std::memcmp(inA.data(), inB.data(), sizeof(Vec3)) == 0;
}

// Control values of every kind a lattice can hold: ordinary, exact and negative zeros, subnormal, large.
double AnyValue(std::mt19937_64& ioRandom)
{
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    switch (ioRandom() % 8)
    {
    case 0: return 0.0;
    case 1: return -0.0;
    case 2: return unit(ioRandom) * 1.0e-310;
    case 3: return unit(ioRandom) * 1.0e6;
    default: return unit(ioRandom) * 0.3;
    }
}

// The local parameter: inside the cell, or exactly on its faces.
double AnyT(std::mt19937_64& ioRandom)
{
    switch (ioRandom() % 6)
    {
    case 0: return 0.0;
    case 1: return 1.0;
    default: return std::uniform_real_distribution<double>(0.0, 1.0)(ioRandom);
    }
}

} // namespace

TEST_CASE("The scalar tensor-product sum is the triple sum of the B-spline weights times the controls", "[ffd]")
{
    std::mt19937_64 random(11);
    std::uniform_real_distribution<double> value(-0.5, 0.5);
    const int nx = 6, ny = 5, nz = 4;
    std::vector<Vec3> controls(static_cast<std::size_t>(nx * ny * nz));
    for (Vec3& control : controls)
        control = common::DrawVec3([&] { return value(random); });
    for (int trial = 0; trial < 200; ++trial)
    {
        const int i = static_cast<int>(random() % (nx - 3)), j = static_cast<int>(random() % (ny - 3)), k = static_cast<int>(random() % (nz - 3));
        const CellWeights w{CubicBSplineWeights(AnyT(random)), CubicBSplineWeights(AnyT(random)), CubicBSplineWeights(AnyT(random))};
        Vec3 reference = Vec3::Zero();
        for (int c = 0; c < 4; ++c)
            for (int b = 0; b < 4; ++b)
                for (int a = 0; a < 4; ++a)
                    reference += w.mX[static_cast<std::size_t>(a)] * w.mY[static_cast<std::size_t>(b)] *
                                 w.mZ[static_cast<std::size_t>(c)] *
                                 controls[static_cast<std::size_t>(i + a + nx * (j + b + ny * (k + c)))];
        const Vec3 sum = TensorProductSum(&controls[static_cast<std::size_t>(i + nx * (j + ny * k))], nx, nx * ny, w);
        CHECK((sum - reference).cwiseAbs().maxCoeff() <= 1.0e-15);
    }
}

TEST_CASE("The wide tensor-product sum gives the scalar sum's bits", "[ffd]")
{
    if (!HasWideTensorProductSum())
        common::SkipTest("this processor (or build) has no AVX: FfdLattice::Displacement takes the scalar sum alone");
    std::mt19937_64 random(5);
    const int nx = 7, ny = 6, nz = 5;
    std::vector<Vec3> controls(static_cast<std::size_t>(nx * ny * nz));
    int compared = 0, differing = 0;
    for (int fill = 0; fill < 20; ++fill)
    {
        for (Vec3& control : controls)
            control = common::DrawVec3([&] { return AnyValue(random); });
        // intent: every cell but the last (its last control ends the array: the wide sum reads one past it)
        for (int k = 0; k < nz - 3; ++k)
            for (int j = 0; j < ny - 3; ++j)
                for (int i = 0; i < nx - 3; ++i)
                {
                    if (i == nx - 4 && j == ny - 4 && k == nz - 4)
                        continue;
                    const CellWeights w{CubicBSplineWeights(AnyT(random)), CubicBSplineWeights(AnyT(random)),
                                        CubicBSplineWeights(AnyT(random))};
                    const Vec3* first = &controls[static_cast<std::size_t>(i + nx * (j + ny * k))];
                    const Vec3 scalar = TensorProductSum(first, nx, nx * ny, w);
                    const Vec3 wide = WideTensorProductSum(first, nx, nx * ny, w);
                    ++compared;
                    differing += SameBytes(scalar, wide) ? 0 : 1;
                }
    }
    CHECK(compared == 20 * (4 * 3 * 2 - 1));
    CHECK(differing == 0);
}

TEST_CASE("The wide sum over a cell's packed controls gives the scalar sum's bits, the last cell included", "[ffd]")
{
    if (!HasWideTensorProductSum())
        common::SkipTest("this processor (or build) has no AVX: FfdDeformer sums each vertex with the scalar sum");
    std::mt19937_64 random(6);
    const int nx = 7, ny = 6, nz = 5;
    std::vector<Vec3> controls(static_cast<std::size_t>(nx * ny * nz));
    int compared = 0, differing = 0;
    PackedCellControls packed;
    for (int fill = 0; fill < 20; ++fill)
    {
        for (Vec3& control : controls)
            control = common::DrawVec3([&] { return AnyValue(random); });
        for (int k = 0; k < nz - 3; ++k)
            for (int j = 0; j < ny - 3; ++j)
                for (int i = 0; i < nx - 3; ++i)
                {
                    const Vec3* first = &controls[static_cast<std::size_t>(i + nx * (j + ny * k))];
                    PackCellControls(first, nx, nx * ny, packed);
                    for (int point = 0; point < 4; ++point)
                    {
                        const CellWeights w{CubicBSplineWeights(AnyT(random)), CubicBSplineWeights(AnyT(random)),
                                            CubicBSplineWeights(AnyT(random))};
                        ++compared;
                        differing += SameBytes(TensorProductSum(first, nx, nx * ny, w), WidePackedTensorProductSum(packed, w)) ? 0 : 1;
                    }
                }
    }
    CHECK(compared == 20 * 4 * 3 * 2 * 4);
    CHECK(differing == 0);
}

TEST_CASE("Displacement is the same field in the lattice's last cell (scalar sum) as in the others (wide sum)", "[ffd]")
{
    // A field linear in the control index is reproduced exactly up to round-off by the cubic B-spline: the
    // last cell (always summed by the scalar path) and its neighbours (the wide path, with AVX) must meet it
    // and agree across their shared face.
    FfdLatticeSettings settings;
    settings.mControlCount = {6, 5, 7};
    settings.mSize = Vec3(3.0, 2.0, 4.0);
    settings.mOrigin = Vec3(-1.5, -1.0, -2.0);
    FfdLattice lattice = FfdLattice::Create(settings).Get();
    std::vector<Vec3>& controls = lattice.GetControlDisplacements();
    for (int c = 0; c < 7; ++c)
        for (int b = 0; b < 5; ++b)
            for (int a = 0; a < 6; ++a)
                controls[static_cast<std::size_t>(lattice.ControlIndex(a, b, c))] = Vec3(0.01 * a, -0.02 * b, 0.03 * c);
    const std::array<int, 3>& cells = lattice.GetCellCount();
    std::mt19937_64 random(3);
    for (int trial = 0; trial < 500; ++trial)
    {
        const Vec3 u(std::uniform_real_distribution<double>(0.0, cells[0])(random),
                     std::uniform_real_distribution<double>(0.0, cells[1])(random),
                     std::uniform_real_distribution<double>(0.0, cells[2])(random));
        // Controls a sit at lattice coordinate a - 1: the field is 0.01 (u + 1), ...
        const Vec3 expected(0.01 * (u.x() + 1.0), -0.02 * (u.y() + 1.0), 0.03 * (u.z() + 1.0));
        CHECK((lattice.Displacement(lattice.Locate(u)) - expected).cwiseAbs().maxCoeff() <= 1.0e-15);
    }
    // The last cell's corner face against its neighbour's, at the same point u = cells - (1, 1, 0) + ...
    const Vec3 on_face(cells[0] - 1.0, cells[1] - 0.5, cells[2] - 0.5);
    LatticeLocation last = lattice.Locate(on_face);
    LatticeLocation neighbour = last;
    neighbour.mCell[0] -= 1;
    neighbour.mT.x() = 1.0;
    REQUIRE(last.mCell == std::array<int, 3>{cells[0] - 1, cells[1] - 1, cells[2] - 1});
    CHECK((lattice.Displacement(last) - lattice.Displacement(neighbour)).cwiseAbs().maxCoeff() <= 1.0e-15);
}
