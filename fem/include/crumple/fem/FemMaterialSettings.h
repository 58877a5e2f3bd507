// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/fem/EElasticModel.h>

namespace crumple::fem
{

/// Describes an isotropic elastic material for the FEM solvers. Validated by FemMaterial::Create().
///
/// Damping is Rayleigh damping, C_d = mMassDamping M + mStiffnessDamping K, off by default:
///  - the mass term slows every node towards rest (modal damping ratio zeta = alpha / (2 omega), strongest
///    on the slow modes). It also drags rigid motion like air: a falling free body reaches g / alpha.
///  - the stiffness term resists the strain rate (Kelvin-Voigt viscosity, zeta = beta omega / 2, strongest
///    on the fast modes) and leaves rigid motion alone.
/// The symplectic integrator applies the mass term implicitly (v /= 1 + alpha dt, unconditionally stable) and
/// the stiffness term as a viscous stress beta C:strain_rate inside the element pass, which shortens the
/// stable sub-step (StableTimeStep() accounts for it: zeta_max = beta omega_max / 2 of 1 costs a factor 2.4
/// in sub-steps). The implicit integrator puts both in its system matrix; it is also numerically dissipative
/// by itself (a mode of frequency omega loses amplitude by 1 / sqrt(1 + (omega h)^2) per step), so it comes
/// to rest without either, while symplectic Euler needs some damping to ever fall asleep.
struct FemMaterialSettings
{
    /// Young's modulus E (Pa), > 0 (steel 2e11, aluminium 7e10, wood ~1e10, rubber ~1e6)
    double mYoungsModulus = 1.0e9;
    /// Poisson's ratio nu, in (-1, cMaxPoissonRatio]; 0.5 is incompressible and makes the Lame parameter
    /// lambda infinite, so it is refused
    double mPoissonRatio = 0.3;
    double mDensity = 1000.0;       ///< Mass density rho (kg/m^3), > 0 (steel 7850)
    double mMassDamping = 0.0;      ///< Rayleigh mass-proportional damping alpha (1/s), >= 0; 0 is undamped
    double mStiffnessDamping = 0.0; ///< Rayleigh stiffness-proportional damping beta (s), >= 0; 0 is undamped
    EElasticModel mModel = EElasticModel::CorotatedLinear; ///< Strain measure and stress law

    /// Largest accepted Poisson's ratio: above it lambda / mu > 99 and linear tetrahedra lock in volume
    static constexpr double cMaxPoissonRatio = 0.495;
};

} // namespace crumple::fem
