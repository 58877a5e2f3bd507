// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/PlasticFlow.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace crumple;
using namespace crumple::fem;

namespace
{

constexpr double cShear = 80.0e9; // mu (Pa)

FemMaterialSettings Yielding(double inYield)
{
    FemMaterialSettings material;
    material.mYieldStress = inYield;
    material.mMaxPlasticStrain = 1.0;
    return material;
}

// Von Mises stress 2 mu sqrt(3/2 e':e') of the elastic strain eps - eps_p.
double VonMises(const Mat3& inTotal, const Mat3& inPlastic)
{
    const Mat3 elastic = inTotal - inPlastic;
    const Mat3 deviatoric = elastic - elastic.trace() / 3.0 * Mat3::Identity();
    return 2.0 * cShear * std::sqrt(1.5 * deviatoric.squaredNorm());
}

// A general symmetric strain with volume change and shear.
Mat3 SomeStrain(double inScale)
{
    Mat3 strain;
    strain << 3.0, 0.5, -0.2, 0.5, -1.0, 0.7, -0.2, 0.7, 0.4;
    return inScale * strain;
}

} // namespace

TEST_CASE("PlasticFlow leaves a strain below yield alone", "[fem]")
{
    const Mat3 strain = SomeStrain(1.0e-4);
    const double von_mises = VonMises(strain, Mat3::Zero());
    const Mat3 plastic = PlasticFlow(strain, Mat3::Zero(), cShear, Yielding(1.01 * von_mises), 0.01);
    CHECK(plastic == Mat3::Zero());
}

TEST_CASE("PlasticFlow with an infinite creep rate returns the stress exactly to the yield surface", "[fem]")
{
    // Radial return: afterwards sigma_vm = sigma_y, the flow is deviatoric (volume kept) and along the
    // deviatoric elastic strain.
    const Mat3 strain = SomeStrain(1.0e-3);
    const double yield = 0.4 * VonMises(strain, Mat3::Zero());
    const Mat3 plastic = PlasticFlow(strain, Mat3::Zero(), cShear, Yielding(yield), 0.01);
    CHECK(VonMises(strain, plastic) == Approx(yield).epsilon(1e-12));
    CHECK(std::abs(plastic.trace()) < 1e-18);
    const Mat3 deviatoric = strain - strain.trace() / 3.0 * Mat3::Identity();
    CHECK((plastic - 0.6 * deviatoric).norm() < 1e-15);
    CHECK((plastic - plastic.transpose()).norm() == 0.0);
}

TEST_CASE("PlasticFlow at a finite creep rate takes c dt of the excess per step", "[fem]")
{
    const Mat3 strain = SomeStrain(1.0e-3);
    const double yield = 0.5 * VonMises(strain, Mat3::Zero());
    FemMaterialSettings material = Yielding(yield);
    material.mCreepRate = 10.0; // 1/s
    const Mat3 plastic = PlasticFlow(strain, Mat3::Zero(), cShear, material, 0.01);
    const Mat3 deviatoric = strain - strain.trace() / 3.0 * Mat3::Identity();
    CHECK((plastic - 0.1 * 0.5 * deviatoric).norm() < 1e-15);
    // Repeated steps at constant strain approach the yield surface from above and never cross it.
    Mat3 accumulated = Mat3::Zero();
    for (int step = 0; step < 200; ++step)
    {
        accumulated = PlasticFlow(strain, accumulated, cShear, material, 0.01);
        CHECK(VonMises(strain, accumulated) >= yield * (1.0 - 1e-12));
    }
    CHECK(VonMises(strain, accumulated) == Approx(yield).epsilon(1e-6));
}

TEST_CASE("PlasticFlow clamps the equivalent plastic strain to its cap", "[fem]")
{
    // Uniaxial plastic stretch e has equivalent strain |e|.
    const Mat3 uniaxial = Vec3(1.0, -0.5, -0.5).asDiagonal();
    CHECK(EquivalentPlasticStrain(0.03 * uniaxial) == Approx(0.03).epsilon(1e-14));

    FemMaterialSettings material = Yielding(1.0e6);
    material.mMaxPlasticStrain = 0.02;
    const Mat3 plastic = PlasticFlow(0.5 * uniaxial, Mat3::Zero(), cShear, material, 0.01);
    CHECK(EquivalentPlasticStrain(plastic) == Approx(0.02).epsilon(1e-12));
    CHECK((plastic / 0.02 - uniaxial).norm() < 1e-9); // the direction of the flow is kept
}
