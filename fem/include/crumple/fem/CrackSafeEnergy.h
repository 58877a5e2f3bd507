// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/fem/FemMaterialSettings.h>
#include <crumple/fem/FractureLinks.h>
#include <crumple/fem/TetMesh.h>

namespace crumple::fem
{

/// The strain energy (J) that a displacement error must stay below so that it cannot move the largest
/// principal stress of any fracture group by more than inStressFraction of the tensile strength sigma_t: the
/// stopping bound that makes an implicit step's cracks those of its converged solution.
///
/// Fracture compares each group's volume-weighted mean Cauchy stress with sigma_t (GroupPrincipalStress,
/// OpenCracks). A displacement error dx adds a stress error ds to that mean; by Weyl's inequality it moves
/// the largest principal stress by at most s = |ds|_2, the largest absolute eigenvalue of ds. Its strain
/// energy in the group is at least V w(mean ds) (Jensen: the energy density w = ds : C^-1 : ds / 2 is
/// convex), and over the stresses whose largest absolute eigenvalue is s, w is least when the other two are
/// nu s / (1 - nu) (the lateral stresses that cancel the Poisson contraction), where w = kappa s^2 / (2 E)
/// with kappa = (1 + nu)(1 - 2 nu) / (1 - nu) (0.74 at nu = 0.3; 0 for an incompressible material, whose
/// pressure costs no strain energy). So an error whose strain energy in the linearisation is below
///     E_safe = inStressFraction^2 sigma_t^2 kappa V_min / (2 E)
/// moves no group's largest principal stress by more than inStressFraction sigma_t, V_min the smallest
/// group's rest volume. Linear elasticity at the current element frames (the corotated model's); for St.
/// Venant-Kirchhoff at small strain.
/// @param[in] inMaterial             a valid material (FemMaterial::Create accepts it)
/// @param[in] inSmallestGroupVolume  V_min (m^3), > 0
/// @param[in] inStressFraction       > 0; infinity for no bound
/// @return E_safe (J); infinity when the material cannot crack (sigma_t infinite) or inStressFraction is
///         infinite
CRUMPLE_API double CrackSafeEnergy(const FemMaterialSettings& inMaterial, double inSmallestGroupVolume,
                                   double inStressFraction);

/// The rest volume (m^3) of the smallest fracture group of inMesh (the sum of its elements' rest volumes).
/// @param[in] inLinks  BuildFractureLinks(inMesh)
/// @param[in] inMesh   the mesh the links were built from
/// @return V_min, > 0 for a valid mesh; infinity when there is no group
CRUMPLE_API double SmallestGroupVolume(const FractureLinks& inLinks, const TetMesh& inMesh);

} // namespace crumple::fem
