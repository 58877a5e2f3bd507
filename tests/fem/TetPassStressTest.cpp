// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// The Cauchy stress an implicit step's force pass hands to fracture (TetElasticForces' outCauchyStress)
// against the stress pass it replaces (TetCauchyStress), and the stress pass limited to the elements the
// force passes skip.
#include "DrawVec3.h"
#include "SmallTetBlock.h"
#include "TetElementPass.h"

#include <crumple/fem/FemMaterial.h>
#include <crumple/fem/TetElementRest.h>

#include <catch2/catch.hpp>

#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

using namespace crumple;
using namespace crumple::fem;

TEST_CASE("Pass stress: the force pass's Cauchy stress is the stress pass's at the same positions, skipped "
          "elements left to it",
          "[fem]")
{
    const TetMesh mesh = test::SmallTetBlock();
    const std::vector<TetElementRest> rest = TetRestData(mesh);
    const FemMaterial material = FemMaterial::Create({}).Get();
    const std::size_t tets = rest.size();

    // A strongly and unevenly deformed state, with plastic strains, and every third element skipped.
    std::mt19937 random(9u);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::vector<Vec3> positions = mesh.GetRestPositions();
    for (Vec3& position : positions)
        position += 0.05 * common::DrawVec3([&] { return unit(random); });
    std::vector<Mat3> plastic(tets);
    for (Mat3& strain : plastic)
    {
        const Mat3 draw = Mat3::NullaryExpr([&] { return unit(random); });
        strain = 1.0e-3 * (draw + draw.transpose());
    }
    std::vector<std::uint8_t> active(tets, 1);
    for (std::size_t tet = 0; tet < tets; tet += 3)
        active[tet] = 0;
    TetElementPassInput input{mesh.GetTets(),
                              rest,
                              &material.GetMaterialMatrix(),
                              material.GetLambda(),
                              material.GetShearModulus(),
                              EElasticModel::CorotatedLinear,
                              plastic};
    input.mElementActive = active;

    // The force pass writes the evaluated elements' stress and leaves the skipped ones' as they were.
    const Mat3 untouched = Mat3::Constant(-7.0);
    std::vector<Quat> pass_rotations(tets, Quat::Identity());
    std::vector<Vec3> forces(positions.size());
    std::vector<Mat3> pass_stress(tets, untouched);
    TetElasticForces(input, positions, {}, 0.0, pass_rotations, {}, forces, nullptr, pass_stress);
    // The stress pass from the rotations the force pass ended on, as Fracture() ran it after the step.
    std::vector<Quat> stress_rotations = pass_rotations;
    std::vector<Mat3> full(tets);
    TetCauchyStress(input, positions, stress_rotations, full);
    double scale = 0.0;
    for (const Mat3& stress : full)
        scale = std::max(scale, stress.norm());
    REQUIRE(scale > 1.0e6); // a real stress state (Pa): the comparison below is not vacuous
    for (std::size_t tet = 0; tet < tets; ++tet)
    {
        INFO("element " << tet);
        if (active[tet] != 0)
            CHECK((pass_stress[tet] - full[tet]).norm() <= 1.0e-12 * scale);
        else
            CHECK(pass_stress[tet] == untouched);
    }

    // Limited to the skipped elements, the stress pass fills exactly those, bit for bit as the full one.
    std::vector<Quat> skipped_rotations = pass_rotations;
    TetCauchyStress(input, positions, skipped_rotations, pass_stress, true);
    for (std::size_t tet = 0; tet < tets; ++tet)
    {
        INFO("element " << tet);
        if (active[tet] == 0)
            CHECK(std::memcmp(pass_stress[tet].data(), full[tet].data(), sizeof(Mat3)) == 0);
        else
            CHECK((pass_stress[tet] - full[tet]).norm() <= 1.0e-12 * scale);
    }
}
