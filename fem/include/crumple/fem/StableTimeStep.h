// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/fem/FemMaterial.h>
#include <crumple/fem/TetElementRest.h>

#include <span>

namespace crumple::fem
{

/// The largest symplectic-Euler sub-step (s) that this function can prove stable at rest, times a safety
/// factor.
///
/// Symplectic Euler is stable for dt < 2 / omega_max, omega_max^2 the largest eigenvalue of M^-1 K (lumped
/// M). By the element eigenvalue inequality (Irons), omega_max^2 <= max over elements of omega_e^2, and for a
/// linear tetrahedron with lumped mass rho V0 / 4 per corner
///   omega_e^2 <= 4 (3 lambda + 2 mu) g_e / rho,  g_e = lambda_max(sum_a grad N_a grad N_a^T) = 1 / h_e^2,
/// since u^T K_e u = V0 (lambda tr(A)^2 + 2 mu |sym A|^2) <= V0 (3 lambda + 2 mu) |A|^2 for A = grad u. This
/// is a CFL condition dt <= h_min / c with the element length h_e (half a cube edge for the 5-tet corner
/// elements) and the wave speed c = sqrt((3 lambda + 2 mu) / rho) (= sqrt(E/rho) x 1.36 at nu = 0.3).
/// With stiffness damping beta the limit shrinks to (2 / omega)(sqrt(1 + zeta^2) - zeta), zeta = beta omega
/// / 2. The result is inSafetyFactor times that limit; the default 0.5 keeps omega_max dt <= 1 (energy
/// fluctuation of symplectic Euler below a factor 2 in the stiffest mode). The bound holds at rest and for
/// the corotated model at any deformation; St. Venant-Kirchhoff stiffens under stretch and can exceed it
/// beyond ~30 % strain.
/// @param[in] inRest          #T element rest data
/// @param[in] inMaterial      the material
/// @param[in] inSafetyFactor  in (0, 1]
/// @return stable sub-step (s), > 0 (infinite for no elements)
CRUMPLE_API double StableTimeStep(std::span<const TetElementRest> inRest, const FemMaterial& inMaterial,
                      double inSafetyFactor);

} // namespace crumple::fem
