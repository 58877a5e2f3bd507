// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// The crack-safe energy: its closed form, the bound it rests on (no stress error whose largest absolute
// principal value is s stores less than kappa s^2 / (2 E) per volume, and one stores exactly that), and the
// smallest group's volume it is taken over.
#include <crumple/fem/CrackSafeEnergy.h>
#include <crumple/fem/IsotropicMaterialMatrix.h>
#include <crumple/fem/PropMaterialPreset.h>
#include <crumple/fem/TetGrid.h>

#include <Eigen/Eigenvalues>
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>

using namespace crumple;
using namespace crumple::fem;

namespace
{

// Strain energy per volume of a stress tensor, sigma : C^-1 : sigma / 2 in Voigt form (J/m^3).
double EnergyDensity(const Mat3& inStress, const Matrix6& inCompliance)
{
    Vector6 voigt;
    voigt << inStress(0, 0), inStress(1, 1), inStress(2, 2), inStress(0, 1), inStress(1, 2), inStress(2, 0);
    return 0.5 * voigt.dot(inCompliance * voigt);
}

double LargestAbsoluteEigenvalue(const Mat3& inStress)
{
    return Eigen::SelfAdjointEigenSolver<Mat3>(inStress).eigenvalues().cwiseAbs().maxCoeff();
}

} // namespace

TEST_CASE("CrackSafeEnergy: the closed form, and no bound where nothing can crack", "[fem]")
{
    FemMaterialSettings wood =
        MakePropMaterialPreset(EPropMaterial::Wood).Get().mMaterial; // 10 GPa, 0.3, 40 MPa
    const double volume = 0.025 * 0.025 * 0.025;
    // kappa = 1.3 x 0.4 / 0.7; half the strength: (20 MPa)^2 kappa V / (2 x 10 GPa)
    const double kappa = 1.3 * 0.4 / 0.7;
    CHECK(CrackSafeEnergy(wood, volume, 0.5) ==
          Approx(20.0e6 * 20.0e6 * kappa * volume / 2.0e10).epsilon(1e-14));
    // Quadratic in the fraction, linear in the volume.
    CHECK(CrackSafeEnergy(wood, volume, 0.25) ==
          Approx(0.25 * CrackSafeEnergy(wood, volume, 0.5)).epsilon(1e-14));
    CHECK(CrackSafeEnergy(wood, 2.0 * volume, 0.5) ==
          Approx(2.0 * CrackSafeEnergy(wood, volume, 0.5)).epsilon(1e-14));
    CHECK(std::isinf(CrackSafeEnergy(wood, volume, std::numeric_limits<double>::infinity())));
    wood.mTensileStrength = std::numeric_limits<double>::infinity();
    CHECK(std::isinf(CrackSafeEnergy(wood, volume, 0.5)));
}

TEST_CASE("CrackSafeEnergy: a stress error that moves a principal stress by s stores at least kappa s^2 / 2E",
          "[fem]")
{
    // The derivation's claim, checked on random stress tensors for several Poisson ratios, and the minimiser
    // it names (lateral stresses nu s / (1 - nu)) attaining it.
    std::mt19937_64 random(20261205);
    std::uniform_real_distribution<double> entry(-1.0, 1.0);
    for (double nu : {0.0, 0.2, 0.3, 0.45, 0.495})
    {
        const double young = 10.0e9;
        const Matrix6 compliance = IsotropicMaterialMatrix(young, nu).inverse();
        const double kappa = (1.0 + nu) * (1.0 - 2.0 * nu) / (1.0 - nu);
        double tightest = std::numeric_limits<double>::infinity();
        for (int trial = 0; trial < 20000; ++trial)
        {
            Mat3 stress;
            for (int i = 0; i < 3; ++i)
                for (int j = i; j < 3; ++j)
                    stress(i, j) = stress(j, i) = 1.0e7 * entry(random);
            const double s = LargestAbsoluteEigenvalue(stress);
            const double ratio = EnergyDensity(stress, compliance) / (kappa * s * s / (2.0 * young));
            tightest = std::min(tightest, ratio);
        }
        INFO("nu " << nu << ": least energy over the bound in 20,000 random stresses " << tightest);
        CHECK(tightest >= 1.0 - 1e-12);
        const double s = 3.0e7;
        const Mat3 minimiser = Vec3(s, nu * s / (1.0 - nu), nu * s / (1.0 - nu)).asDiagonal();
        CHECK(EnergyDensity(minimiser, compliance) == Approx(kappa * s * s / (2.0 * young)).epsilon(1e-12));
    }
}

TEST_CASE("SmallestGroupVolume: the smallest group's rest volume", "[fem]")
{
    // Cubes of 0.1 x 0.2 x 0.25 m: each group is one cube whatever the tetrahedra it is cut into.
    TetGridSettings grid;
    grid.mSize = Vec3(0.4, 0.4, 0.5);
    grid.mCellCount = {4, 2, 2};
    const TetMesh cubes = TetGrid(grid).Get();
    CHECK(SmallestGroupVolume(BuildFractureLinks(cubes), cubes) == Approx(0.1 * 0.2 * 0.25).epsilon(1e-12));
    // One tetrahedron per group: the smallest tetrahedron.
    const TetMesh single = TetMesh::Create(cubes.GetRestPositions(), cubes.GetTets()).Get();
    double smallest = std::numeric_limits<double>::infinity();
    for (int tet = 0; tet < single.GetTetCount(); ++tet)
        smallest = std::min(smallest, single.GetRestVolume(tet));
    CHECK(SmallestGroupVolume(BuildFractureLinks(single), single) == Approx(smallest).epsilon(1e-12));
}
