// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

namespace crumple::fem
{

/// How the 24 x 24 element stiffness of a trilinear hexahedron is formed. Both use 2 x 2 x 2 Gauss quadrature,
/// have exactly the 6 rigid-body zero modes and pass the constant-strain patch test on distorted meshes.
enum class EHexFormulation
{
    /// Wilson's 9 incompatible bubble modes (1 - xi^2, 1 - eta^2, 1 - zeta^2 per displacement component), with
    /// Taylor's modification (mode gradients through the centre Jacobian, scaled by det J0 / det J) so that the
    /// patch test holds on distorted elements; condensed statically into the 24 corner dofs (Wilson, Taylor,
    /// Doherty & Ghaboussi 1973; Taylor, Beresford & Wilson 1976; Abaqus C3D8I). It reproduces pure bending of
    /// rectangular elements exactly and does not shear-lock: the 40 x 4 x 4 steel cantilever of the tests comes
    /// within -0.96 % of Timoshenko beam theory, a 20 x 2 x 2 mesh within -1.3 %. Default.
    IncompatibleModes,
    /// Plain trilinear displacements, fully integrated. Shear-locks in bending (parasitic shear strain): the same
    /// cantilever comes out -4.3 % too stiff on 40 x 4 x 4 and -13 % on 20 x 2 x 2 (HexStaticSolveTest). Kept
    /// as the textbook reference.
    FullIntegration,
};

/// An isotropic linear-elastic material for hexahedral meshes. HexMaterial::Create validates it.
struct CRUMPLE_API HexMaterialSettings
{
    double mYoungsModulus = 200.0e9; ///< Young's modulus E (Pa), in (0, 1e15]; default structural steel
    double mPoissonRatio = 0.3;      ///< Poisson ratio nu (dimensionless), in the open interval (-1, 0.5)
    EHexFormulation mFormulation = EHexFormulation::IncompatibleModes; ///< Element formulation
};

} // namespace crumple::fem
