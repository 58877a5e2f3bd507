// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/props/HeldFemProp.h>

#include <string>

namespace crumple::props
{

Result<FemProp> MakeHeldFemProp(const fem::TetMesh& inBodyMesh, const fem::FemMaterialSettings& inMaterial,
                                std::span<const int> inAnchoredNodes)
{
    fem::TetSolverSettings solver;
    solver.mGravity = Vec3::Zero();
    Result<FemProp> prop = FemProp::Create(nullptr, inBodyMesh, inMaterial, solver, FemPropSettings{});
    if (!prop)
        return prop;
    for (int node : inAnchoredNodes)
        if (Status fixed = prop.Get().SetNodeFixed(node, true); !fixed)
            return MakeError(fixed.GetError().mCode, "MakeHeldFemProp: anchored node " + std::to_string(node) + ": " +
                                                         fixed.GetError().mMessage);
    return prop;
}

} // namespace crumple::props
