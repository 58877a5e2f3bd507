// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/HexElementStiffness.h>

#include <catch2/catch.hpp>

#include <Eigen/Eigenvalues>

#include <limits>

using namespace crumple;
using namespace crumple::fem;

namespace
{

// A box a x b x c at the origin, in HexMesh corner order.
HexCornerMatrix BoxCorners(double inA, double inB, double inC)
{
    HexCornerMatrix corners;
    corners << 0, 0, 0, inA, 0, 0, inA, inB, 0, 0, inB, 0, 0, 0, inC, inA, 0, inC, inA, inB, inC, 0, inB, inC;
    return corners;
}

// A visibly non-rectangular brick: a unit cube with every corner moved, non-planar faces included.
HexCornerMatrix DistortedCorners()
{
    HexCornerMatrix corners = BoxCorners(1.0, 1.0, 1.0);
    HexCornerMatrix offsets;
    offsets << 0.10, -0.05, 0.02, 0.20, 0.08, -0.10, -0.12, 0.15, 0.05, 0.04, -0.10, 0.12, //
        -0.08, 0.06, -0.15, 0.15, -0.12, 0.10, 0.05, 0.20, -0.05, -0.10, 0.02, 0.18;
    return corners + offsets;
}

HexMaterial Material(EHexFormulation inFormulation)
{
    HexMaterialSettings settings;
    settings.mFormulation = inFormulation;
    return HexMaterial::Create(settings).Get();
}

// The 6 rigid motions (3 translations, 3 infinitesimal rotations) of the corners, as columns.
Eigen::Matrix<double, 24, 6> RigidModes(const HexCornerMatrix& inCorners)
{
    Eigen::Matrix<double, 24, 6> modes = Eigen::Matrix<double, 24, 6>::Zero();
    for (int c = 0; c < 8; ++c)
        for (int axis = 0; axis < 3; ++axis)
        {
            modes(3 * c + axis, axis) = 1.0;
            const Vec3 rotated = Vec3::Unit(axis).cross(Vec3(inCorners.row(c).transpose()));
            modes.block<3, 1>(3 * c, 3 + axis) = rotated;
        }
    return modes;
}

} // namespace

TEST_CASE("Hex element stiffness is symmetric, PSD, with exactly the 6 rigid modes as null space", "[fem][hex]")
{
    const EHexFormulation formulation =
        GENERATE(EHexFormulation::IncompatibleModes, EHexFormulation::FullIntegration);
    const bool distorted = GENERATE(false, true);
    const HexCornerMatrix corners = distorted ? DistortedCorners() : BoxCorners(0.5, 0.3, 0.2);
    CAPTURE(static_cast<int>(formulation), distorted);

    const Result<HexElementStiffnessMatrix> stiffness = HexElementStiffness(corners, Material(formulation));
    REQUIRE(stiffness.IsValid());
    const HexElementStiffnessMatrix& k = stiffness.Get();
    CHECK(k == k.transpose());

    const Eigen::SelfAdjointEigenSolver<HexElementStiffnessMatrix> eigen(k);
    const Eigen::Matrix<double, 24, 1>& lambda = eigen.eigenvalues(); // ascending
    const double largest = lambda[23];
    INFO("eigenvalues / largest: " << (lambda / largest).transpose());
    CHECK(largest > 1.0e9);
    for (int i = 0; i < 6; ++i)
        CHECK(std::abs(lambda[i]) < 1.0e-12 * largest);
    // The 7th is a genuine deformation mode, 10 orders of magnitude above rounding.
    CHECK(lambda[6] > 1.0e-3 * largest);

    // The rigid motions are exactly those zero modes: K r = 0.
    const Eigen::Matrix<double, 24, 6> rigid = RigidModes(corners);
    CHECK((k * rigid).norm() < 1.0e-12 * largest * rigid.norm());
}

TEST_CASE("Hex element stiffness stores the exact energy of a uniform strain", "[fem][hex]")
{
    const EHexFormulation formulation =
        GENERATE(EHexFormulation::IncompatibleModes, EHexFormulation::FullIntegration);
    const HexMaterial material = Material(formulation);
    // u = G x with a constant displacement gradient G: strain energy = V/2 eps^T D eps (any brick shape).
    Mat3 gradient;
    gradient << 1.0e-3, 0.4e-3, -0.2e-3, 0.1e-3, -0.5e-3, 0.3e-3, 0.2e-3, 0.6e-3, 0.8e-3;
    Eigen::Matrix<double, 6, 1> strain;
    strain << gradient(0, 0), gradient(1, 1), gradient(2, 2), gradient(0, 1) + gradient(1, 0),
        gradient(1, 2) + gradient(2, 1), gradient(2, 0) + gradient(0, 2);
    const double energy_density = 0.5 * strain.dot(material.GetElasticity() * strain); // J/m^3

    const HexCornerMatrix box = BoxCorners(0.5, 0.3, 0.2);
    Eigen::Matrix<double, 24, 1> u;
    for (int c = 0; c < 8; ++c)
        u.segment<3>(3 * c) = gradient * box.row(c).transpose();
    const HexElementStiffnessMatrix k = HexElementStiffness(box, material).Get();
    CHECK(0.5 * u.dot(k * u) == Approx(energy_density * 0.5 * 0.3 * 0.2).epsilon(1.0e-12));
}

TEST_CASE("Hex element stiffness scales with E and refuses broken elements", "[fem][hex]")
{
    const HexMaterial steel = Material(EHexFormulation::IncompatibleModes);
    HexMaterialSettings soft_settings;
    soft_settings.mYoungsModulus = 1.0e6;
    const HexMaterial soft = HexMaterial::Create(soft_settings).Get();
    const HexElementStiffnessMatrix k_steel = HexElementStiffness(DistortedCorners(), steel).Get();
    const HexElementStiffnessMatrix k_soft = HexElementStiffness(DistortedCorners(), soft).Get();
    CHECK((k_steel * (1.0e6 / 200.0e9) - k_soft).norm() < 1.0e-12 * k_soft.norm());

    SECTION("inverted")
    {
        HexCornerMatrix corners = BoxCorners(1.0, 1.0, 1.0);
        corners.col(2) *= -1.0; // mirrored: negative Jacobian
        const Result<HexElementStiffnessMatrix> k = HexElementStiffness(corners, steel);
        REQUIRE(k.HasError());
        CHECK(k.GetError().mCode == EError::DegenerateGeometry);
        CHECK(k.GetError().mMessage.find("inverted") != std::string::npos);
    }
    SECTION("flat")
    {
        HexCornerMatrix corners = BoxCorners(1.0, 1.0, 1.0e-9);
        CHECK(HexElementStiffness(corners, steel).GetError().mCode == EError::DegenerateGeometry);
    }
    SECTION("NaN")
    {
        HexCornerMatrix corners = BoxCorners(1.0, 1.0, 1.0);
        corners(5, 1) = std::numeric_limits<double>::quiet_NaN();
        CHECK(HexElementStiffness(corners, steel).GetError().mCode == EError::NonFinite);
    }
}
