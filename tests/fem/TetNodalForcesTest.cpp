// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/DeformationGradient.h>
#include <crumple/fem/EdgeMatrix.h>
#include <crumple/fem/FemMaterial.h>
#include <crumple/fem/FirstPiolaStress.h>
#include <crumple/fem/GreenStrain.h>
#include <crumple/fem/PolarRotation.h>
#include <crumple/fem/StrainEnergyDensity.h>
#include <crumple/fem/TetNodalForces.h>
#include <crumple/fem/TetVolume.h>

#include "DrawVec3.h"

#include <catch2/catch.hpp>

#include <array>
#include <random>

using namespace crumple;
using namespace crumple::fem;

namespace
{

// Elastic energy V0 psi(F) of one element with corners at inX.
double ElementEnergy(EElasticModel inModel, const Matrix6& inC, const std::array<Vec3, 4>& inX,
                     const Mat3& inDmInverse, double inVolume)
{
    const Mat3 f = DeformationGradient(inX[0], inX[1], inX[2], inX[3], inDmInverse);
    const Mat3 r = PolarRotation(f, Quat::Identity()).toRotationMatrix();
    return inVolume * StrainEnergyDensity(inModel, f, r, inC);
}

} // namespace

TEST_CASE("DeformationGradient reproduces an affine map and GreenStrain vanishes on rotations", "[fem]")
{
    const std::array<Vec3, 4> rest = {Vec3(0.1, 0.0, 0.0), Vec3(1.0, 0.2, 0.0), Vec3(0.0, 0.9, 0.1),
                                      Vec3(0.2, 0.1, 1.1)};
    const Mat3 dm_inverse = EdgeMatrix(rest[0], rest[1], rest[2], rest[3]).inverse();
    Mat3 a;
    a << 1.1, 0.2, -0.1, 0.05, 0.9, 0.3, -0.2, 0.1, 1.3;
    const Vec3 b(3.0, -1.0, 2.0);
    const Mat3 f =
        DeformationGradient(a * rest[0] + b, a * rest[1] + b, a * rest[2] + b, a * rest[3] + b, dm_inverse);
    CHECK((f - a).norm() < 1e-14);

    const Mat3 rotation = Eigen::AngleAxisd(2.0, Vec3(1, 1, 0).normalized()).toRotationMatrix();
    CHECK(GreenStrain(rotation).norm() < 1e-15);
    const Mat3 stretch = Vec3(1.1, 1.0, 1.0).asDiagonal();
    CHECK(GreenStrain(stretch)(0, 0) == Approx(0.105).epsilon(1e-14)); // (1.1^2 - 1) / 2
}

TEST_CASE("TetNodalForces are minus the energy gradient, balanced and torque free", "[fem]")
{
    FemMaterialSettings settings;
    settings.mYoungsModulus = 1.0e7;
    settings.mPoissonRatio = 0.35;
    const Matrix6 c = FemMaterial::Create(settings).Get().GetMaterialMatrix();
    const std::array<Vec3, 4> rest = {Vec3(0, 0, 0), Vec3(0.1, 0, 0), Vec3(0, 0.1, 0), Vec3(0, 0, 0.1)};
    const Mat3 dm_inverse = EdgeMatrix(rest[0], rest[1], rest[2], rest[3]).inverse();
    const double volume = TetVolume(rest[0], rest[1], rest[2], rest[3]);

    std::mt19937 random(11);
    std::uniform_real_distribution<double> jitter(-0.02, 0.02);
    for (EElasticModel model : {EElasticModel::StVenantKirchhoff, EElasticModel::CorotatedLinear})
        for (int trial = 0; trial < 10; ++trial)
        {
            // A rotated, randomly deformed element.
            const Mat3 rotation =
                Eigen::AngleAxisd(0.3 * trial, Vec3(1, 2, 3).normalized()).toRotationMatrix();
            std::array<Vec3, 4> x;
            for (int corner = 0; corner < 4; ++corner)
                x[corner] = rotation * (rest[corner] + common::DrawVec3([&] { return jitter(random); }));
            const Mat3 f = DeformationGradient(x[0], x[1], x[2], x[3], dm_inverse);
            const Mat3 r = PolarRotation(f, Quat::Identity()).toRotationMatrix();
            const std::array<Vec3, 4> forces =
                TetNodalForces(FirstPiolaStress(model, f, r, c), dm_inverse, volume);

            // Balanced (sum zero) and torque free (sum x_i x f_i zero), relative to the force scale.
            double scale = 0.0;
            Vec3 sum = Vec3::Zero(), torque = Vec3::Zero();
            for (int corner = 0; corner < 4; ++corner)
            {
                scale = std::max(scale, forces[corner].norm());
                sum += forces[corner];
                torque += x[corner].cross(forces[corner]);
            }
            CHECK(sum.norm() < 1e-12 * scale);
            CHECK(torque.norm() < 1e-12 * scale * 0.1);

            // f = -dW/dx by central differences.
            const double h = 1.0e-7;
            double worst = 0.0;
            for (int corner = 0; corner < 4; ++corner)
                for (int axis = 0; axis < 3; ++axis)
                {
                    std::array<Vec3, 4> plus = x, minus = x;
                    plus[corner][axis] += h;
                    minus[corner][axis] -= h;
                    const double derivative = (ElementEnergy(model, c, plus, dm_inverse, volume) -
                                               ElementEnergy(model, c, minus, dm_inverse, volume)) /
                                              (2.0 * h);
                    worst = std::max(worst, std::abs(-derivative - forces[corner][axis]));
                }
            INFO(ToString(model) << " trial " << trial);
            CHECK(worst < 1e-6 * scale);
        }
}
