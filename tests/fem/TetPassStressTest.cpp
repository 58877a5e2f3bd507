// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// The Cauchy stress an implicit step's force pass hands to fracture (TetElasticForces' outCauchyStress)
// against the stress pass it replaces (TetCauchyStress), and the stress pass limited to the elements the
// force passes skip.
#include "AnchorGridLayer.h"
#include "DrawVec3.h"
#include "SmallTetBlock.h"
#include "TetElementPass.h"

#include <crumple/fem/FemMaterial.h>
#include <crumple/fem/GroupPrincipalStress.h>
#include <crumple/fem/TetElementRest.h>
#include <crumple/fem/TetGrid.h>
#include <crumple/fem/TetSolver.h>

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

TEST_CASE("Pass stress: after a step in which elements flowed, fracture judges the stress of the final state",
          "[fem]")
{
    // A soft bar that yields and is breakable (far too strong to break here: only the stresses are compared),
    // its far end pulled hard for a few implicit steps. Plastic flow after a step's last force pass changes
    // the elements' stress at the same positions: fracture must not take that pass's stress then.
    TetGridSettings grid;
    grid.mSize = Vec3(1.0, 0.1, 0.1);
    grid.mCellCount = {10, 1, 1};
    FemMaterialSettings settings;
    settings.mYoungsModulus = 1.0e7;
    settings.mYieldStress = 2.0e4;
    settings.mCreepRate = 100.0;
    settings.mTensileStrength = 1.0e12;
    TetSolverSettings solver_settings;
    solver_settings.mGravity = Vec3::Zero();
    TetSolver bar = TetSolver::Create(TetGrid(grid).Get(), settings, solver_settings).Get();
    test::AnchorGridLayer(bar, grid.mCellCount, 0);
    int flowed = 0;
    for (int step = 0; step < 4; ++step)
    {
        for (int j = 0; j <= 1; ++j)
            for (int k = 0; k <= 1; ++k)
                REQUIRE(
                    bar.ApplyImpulse(TetGridNode(grid.mCellCount, 10, j, k), Vec3(2.0, 0.0, 0.0)).IsValid());
        const TetStepResult result = bar.Step(1.0 / 60.0).Get();
        REQUIRE_FALSE(HasEvent(result.mEvents, ETetStepEvent::Diverged));
        flowed += result.mPlasticElements;

        // The group stresses of the state the step ended in, by the stress pass on its own.
        const std::vector<TetElementRest> rest = TetRestData(bar.GetMesh());
        const FemMaterial& material = bar.GetMaterial();
        const TetElementPassInput input{bar.GetElementNodes(),         rest,
                                        &material.GetMaterialMatrix(), material.GetLambda(),
                                        material.GetShearModulus(),    EElasticModel::CorotatedLinear,
                                        bar.GetPlasticStrains()};
        std::vector<Quat> rotations = bar.GetElementRotations();
        std::vector<Mat3> stress(rest.size());
        TetCauchyStress(input, bar.GetPositions(), rotations, stress);
        std::vector<PrincipalStress> expected(bar.GetGroupPrincipalStress().size());
        REQUIRE(GroupPrincipalStress(bar.GetFractureLinks(), stress, rest, expected).IsValid());
        double scale = 0.0, worst = 0.0;
        for (std::size_t group = 0; group < expected.size(); ++group)
        {
            scale = std::max(scale, std::abs(expected[group].mValue));
            worst = std::max(worst,
                             std::abs(bar.GetGroupPrincipalStress()[group].mValue - expected[group].mValue));
        }
        INFO("step " << step << ": " << result.mPlasticElements << " elements flowed, largest group stress "
                     << scale << " Pa, judged off by " << worst);
        CHECK(worst <= 1.0e-9 * scale);
    }
    CHECK(flowed > 0); // the case it guards was met
}
