// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include "WallPanelMesh.h"

#include <crumple/props/FemProp.h>

#include <BrittleMaterial.h>

#include <catch2/catch.hpp>

#include <array>

namespace crumple::test
{

/// A brittle 2 m x 0.2 m x 2 m panel standing in for the WorldFixture's wall (its body frame: x in [0, 0.2],
/// y and z in [-1, 1]), anchored along its base (z = -1), without gravity: the car's hits crack it.
/// @param[in] inCells           cells along x, y, z (five tetrahedra each)
/// @param[in] inYoungsModulus   Pa (Poisson ratio 0.2)
/// @param[in] inStrengthFactor  times the shared brittle material's tensile strength
/// @param[in] inGround          a ground (then with gravity, -z), or none (then without gravity)
inline props::FemProp BrittlePanel(const std::array<int, 3>& inCells, double inYoungsModulus,
                                   double inStrengthFactor, const fem::GroundPlane& inGround = {})
{
    fem::FemMaterialSettings material = common::BrittleMaterial(fem::EFractureMode::CrackPlane);
    material.mYoungsModulus = inYoungsModulus;
    material.mPoissonRatio = 0.2;
    material.mTensileStrength *= inStrengthFactor;
    fem::TetSolverSettings settings;
    // intent: gravity only with a ground to fall on (a panel on its own stands for one held up)
    settings.mGravity = inGround.mEnabled ? Vec3(0.0, 0.0, -9.81) : Vec3::Zero();
    settings.mGround = inGround;
    props::FemProp prop = props::FemProp::Create(nullptr, WallPanelMesh(inCells), material, settings, props::FemPropSettings{}).Get();
    for (int node = 0; node < prop.GetNodeCount(); ++node)
        if (prop.GetCpuSolver()->GetMesh().GetRestPositions()[static_cast<std::size_t>(node)].z() < -0.99)
            REQUIRE(prop.SetNodeFixed(node, true).IsValid());
    return prop;
}

/// The panel weak enough (1 GPa, a tenth of the shared brittle strength, 8 x 8 cells) that the car's hard hits
/// knock pieces out of it.
inline props::FemProp WeakPanel()
{
    return BrittlePanel({1, 8, 8}, 1.0e9, 0.1);
}

/// The weak panel under gravity, standing on a ground at its footing (z = -1 m, friction 0.6): the pieces the
/// car knocks out fall onto it.
inline props::FemProp WeakPanelOnGround()
{
    return BrittlePanel({1, 8, 8}, 1.0e9, 0.1, fem::GroundPlane{true, Vec3::UnitZ(), -1.0, 0.6});
}

} // namespace crumple::test
