// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <cstdint>

namespace crumple::fem
{

/// How an element turns its deformation gradient F into stress. Both use the same 6x6 isotropic material
/// matrix C (Voigt order xx, yy, zz, xy, yz, zx with engineering shear strains); they differ in the strain
/// measure.
enum class EElasticModel : std::uint8_t
{
    /// Full Green strain E = (F^T F - I) / 2 with the linear law S = C:E (second Piola-Kirchhoff stress),
    /// first Piola-Kirchhoff stress P = F S. This is what the GPU destruction paper (Morris & Anderson,
    /// section IV.A, "Calculate Green's strain tensor ... stress equals the material stiffness matrix times
    /// the strain") calls linear elasticity; with the full quadratic strain it is the geometrically nonlinear
    /// St. Venant-Kirchhoff material. Exact for rigid motions; stiffens in tension and softens, and can
    /// collapse, under strong compression (> ~40 %), so it is not the default.
    StVenantKirchhoff,
    /// Corotated linear elasticity (Mueller & Gross 2004, McAdams et al. 2011): the rotation R of the polar
    /// decomposition F = R S is removed per element, the small strain eps = sym(R^T F) - I gives
    /// sigma = C:eps, and P = R sigma. Rigid rotations give exactly zero force, no stiffness warping,
    /// stiffness bounded by the rest stiffness: the robust default.
    CorotatedLinear,
};

/// Short name of an EElasticModel, for messages.
CRUMPLE_API const char* ToString(EElasticModel inModel);

} // namespace crumple::fem
