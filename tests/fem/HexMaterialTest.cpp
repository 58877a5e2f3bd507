// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/HexMaterial.h>

#include <catch2/catch.hpp>

#include <limits>

using namespace crumple;
using namespace crumple::fem;

TEST_CASE("HexMaterial builds the isotropic elasticity matrix of steel", "[fem][hex]")
{
    const HexMaterial steel = HexMaterial::Create({}).Get();
    // E = 200 GPa, nu = 0.3: lambda = 115.3846 GPa, mu = G = 76.9231 GPa.
    const HexElasticityMatrix& d = steel.GetElasticity();
    CHECK(d(0, 0) == Approx(269.2307692307692e9).epsilon(1.0e-14));
    CHECK(d(0, 1) == Approx(115.3846153846154e9).epsilon(1.0e-14));
    CHECK(d(2, 1) == Approx(115.3846153846154e9).epsilon(1.0e-14));
    CHECK(d(3, 3) == Approx(76.92307692307692e9).epsilon(1.0e-14));
    CHECK(d(5, 5) == d(3, 3));
    CHECK(d(0, 3) == 0.0);
    CHECK(d(3, 4) == 0.0);
    CHECK(steel.GetShearModulus() == Approx(76.92307692307692e9).epsilon(1.0e-14));
    // Uniaxial stress: sigma_xx = E eps_xx when the lateral strains are -nu eps_xx.
    Eigen::Matrix<double, 6, 1> strain;
    strain << 1.0e-3, -0.3e-3, -0.3e-3, 0.0, 0.0, 0.0;
    const Eigen::Matrix<double, 6, 1> stress = d * strain;
    CHECK(stress[0] == Approx(200.0e6).epsilon(1.0e-12));
    CHECK(std::abs(stress[1]) < 1.0e-6);
}

TEST_CASE("HexMaterial refuses bad input with a clear error", "[fem][hex]")
{
    HexMaterialSettings settings;
    SECTION("negative or zero Young's modulus")
    {
        settings.mYoungsModulus = -1.0e9;
        const Result<HexMaterial> material = HexMaterial::Create(settings);
        REQUIRE(material.HasError());
        CHECK(material.GetError().mCode == EError::InvalidArgument);
        CHECK(material.GetError().mMessage.find("mYoungsModulus = -1e+09 Pa") != std::string::npos);
        settings.mYoungsModulus = 0.0;
        CHECK(HexMaterial::Create(settings).GetError().mCode == EError::InvalidArgument);
    }
    SECTION("Poisson ratio at or beyond 0.5 or -1")
    {
        for (double nu : {0.5, 0.7, -1.0, -3.0})
        {
            settings.mPoissonRatio = nu;
            const Result<HexMaterial> material = HexMaterial::Create(settings);
            REQUIRE(material.HasError());
            CHECK(material.GetError().mCode == EError::InvalidArgument);
            CHECK(material.GetError().mMessage.find("mPoissonRatio") != std::string::npos);
        }
        settings.mPoissonRatio = 0.499;
        CHECK(HexMaterial::Create(settings).IsValid());
        settings.mPoissonRatio = -0.99;
        CHECK(HexMaterial::Create(settings).IsValid());
    }
    SECTION("NaN and Inf")
    {
        settings.mYoungsModulus = std::numeric_limits<double>::quiet_NaN();
        CHECK(HexMaterial::Create(settings).GetError().mCode == EError::NonFinite);
        settings = {};
        settings.mPoissonRatio = std::numeric_limits<double>::quiet_NaN();
        CHECK(HexMaterial::Create(settings).GetError().mCode == EError::NonFinite);
        settings = {};
        settings.mYoungsModulus = std::numeric_limits<double>::infinity();
        CHECK(HexMaterial::Create(settings).GetError().mCode == EError::NonFinite);
    }
    SECTION("an out-of-range formulation")
    {
        settings.mFormulation = static_cast<EHexFormulation>(7);
        CHECK(HexMaterial::Create(settings).GetError().mCode == EError::InvalidArgument);
    }
}
