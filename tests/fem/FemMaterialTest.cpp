// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/FemMaterial.h>
#include <crumple/fem/MaterialStress.h>

#include <catch2/catch.hpp>

#include <limits>
#include <string>

using namespace crumple;
using namespace crumple::fem;

namespace
{

FemMaterialSettings Steel()
{
    FemMaterialSettings steel;
    steel.mYoungsModulus = 200.0e9;
    steel.mPoissonRatio = 0.3;
    steel.mDensity = 7850.0;
    return steel;
}

} // namespace

TEST_CASE("FemMaterial derives the Lame parameters and the 6x6 isotropic matrix", "[fem]")
{
    Result<FemMaterial> result = FemMaterial::Create(Steel());
    REQUIRE(result.IsValid());
    const FemMaterial& steel = result.Get();
    const double lambda = 200.0e9 * 0.3 / (1.3 * 0.4); // 115.38 GPa
    const double mu = 200.0e9 / 2.6;                   // 76.92 GPa
    CHECK(steel.GetLambda() == Approx(lambda).epsilon(1e-14));
    CHECK(steel.GetShearModulus() == Approx(mu).epsilon(1e-14));
    CHECK(steel.GetWaveSpeed() == Approx(5856.36).epsilon(1e-5)); // sqrt((lambda + 2 mu) / rho), m/s

    const Matrix6& c = steel.GetMaterialMatrix();
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            CHECK(c(i, j) == Approx(i == j ? lambda + 2.0 * mu : lambda).epsilon(1e-14));
    for (int i = 3; i < 6; ++i)
        CHECK(c(i, i) == Approx(mu).epsilon(1e-14));
    CHECK(c.block<3, 3>(0, 3).norm() == 0.0);
    CHECK((c - c.transpose()).norm() == 0.0);
}

TEST_CASE("MaterialStress gives uniaxial stress E eps and shear stress G gamma", "[fem]")
{
    const FemMaterial steel = FemMaterial::Create(Steel()).Get();

    // Uniaxial stress: exx = e with the Poisson contraction eyy = ezz = -nu e gives sxx = E e and nothing
    // else.
    const double e = 1.0e-3;
    const Mat3 uniaxial = Vec3(e, -0.3 * e, -0.3 * e).asDiagonal();
    const Mat3 sigma = MaterialStress(steel.GetMaterialMatrix(), uniaxial);
    CHECK(sigma(0, 0) == Approx(200.0e9 * e).epsilon(1e-13));
    CHECK(std::abs(sigma(1, 1)) < 1e-4);
    CHECK(std::abs(sigma(2, 2)) < 1e-4);

    // Simple shear: tensor strain exy = gamma / 2 gives sxy = G gamma.
    Mat3 shear = Mat3::Zero();
    shear(0, 1) = shear(1, 0) = 0.5 * e;
    const Mat3 tau = MaterialStress(steel.GetMaterialMatrix(), shear);
    CHECK(tau(0, 1) == Approx(steel.GetShearModulus() * e).epsilon(1e-14));
    CHECK(tau(1, 0) == tau(0, 1));
    CHECK(tau.diagonal().norm() == 0.0);
}

TEST_CASE("FemMaterial refuses invalid settings and names the field", "[fem]")
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    struct Case
    {
        const char* mName;
        FemMaterialSettings mSettings;
        EError mCode;
        const char* mNeedle;
    };
    std::vector<Case> cases;
    auto add = [&](const char* inName, auto inChange, EError inCode, const char* inNeedle)
    {
        FemMaterialSettings settings = Steel();
        inChange(settings);
        cases.push_back({inName, settings, inCode, inNeedle});
    };
    add(
        "NaN E", [&](FemMaterialSettings& s) { s.mYoungsModulus = nan; }, EError::NonFinite,
        "mYoungsModulus = nan");
    add(
        "negative E", [](FemMaterialSettings& s) { s.mYoungsModulus = -1.0e9; }, EError::InvalidArgument,
        "mYoungsModulus = -1e+09 Pa: must be > 0");
    add(
        "zero E", [](FemMaterialSettings& s) { s.mYoungsModulus = 0.0; }, EError::InvalidArgument,
        "mYoungsModulus");
    add(
        "nu = 0.5", [](FemMaterialSettings& s) { s.mPoissonRatio = 0.5; }, EError::InvalidArgument,
        "mPoissonRatio = 0.5: must lie in (-1, 0.495]");
    add(
        "nu > 0.5", [](FemMaterialSettings& s) { s.mPoissonRatio = 0.7; }, EError::InvalidArgument,
        "mPoissonRatio");
    add(
        "nu = -1", [](FemMaterialSettings& s) { s.mPoissonRatio = -1.0; }, EError::InvalidArgument,
        "mPoissonRatio");
    add(
        "NaN nu", [&](FemMaterialSettings& s) { s.mPoissonRatio = nan; }, EError::NonFinite, "mPoissonRatio");
    add(
        "negative density", [](FemMaterialSettings& s) { s.mDensity = -7850.0; }, EError::InvalidArgument,
        "mDensity = -7850 kg/m^3: must be > 0");
    add(
        "zero density", [](FemMaterialSettings& s) { s.mDensity = 0.0; }, EError::InvalidArgument,
        "mDensity");
    add(
        "infinite density",
        [](FemMaterialSettings& s) { s.mDensity = std::numeric_limits<double>::infinity(); },
        EError::NonFinite, "mDensity");
    add(
        "negative mass damping", [](FemMaterialSettings& s) { s.mMassDamping = -0.1; },
        EError::InvalidArgument, "mMassDamping");
    add(
        "negative stiffness damping", [](FemMaterialSettings& s) { s.mStiffnessDamping = -1.0e-5; },
        EError::InvalidArgument, "mStiffnessDamping");
    add(
        "unknown model", [](FemMaterialSettings& s) { s.mModel = static_cast<EElasticModel>(7); },
        EError::InvalidArgument, "mModel");

    for (const Case& c : cases)
    {
        INFO(c.mName);
        Result<FemMaterial> material = FemMaterial::Create(c.mSettings);
        REQUIRE(material.HasError());
        INFO(material.GetError().mMessage);
        CHECK(material.GetError().mCode == c.mCode);
        CHECK(material.GetError().mMessage.find(c.mNeedle) != std::string::npos);
    }
}
