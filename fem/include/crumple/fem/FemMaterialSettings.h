// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/fem/EElasticModel.h>
#include <crumple/fem/EFractureMode.h>

#include <limits>

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
struct CRUMPLE_API FemMaterialSettings
{
    /// Young's modulus E (Pa), in (0, cMaxYoungsModulus] (steel 2e11, aluminium 7e10, wood ~1e10, rubber ~1e6)
    double mYoungsModulus = 1.0e9;
    /// Poisson's ratio nu, in (-1, cMaxPoissonRatio]; 0.5 is incompressible and makes the Lame parameter
    /// lambda infinite, so it is refused
    double mPoissonRatio = 0.3;
    double mDensity = 1000.0;       ///< Mass density rho (kg/m^3), in [cMinDensity, cMaxDensity] (steel 7850)
    double mMassDamping = 0.0;      ///< Rayleigh mass-proportional damping alpha (1/s), in [0, cMaxMassDamping]; 0 is undamped
    double mStiffnessDamping = 0.0; ///< Rayleigh stiffness-proportional damping beta (s), in [0, cMaxStiffnessDamping]; 0 is undamped
    EElasticModel mModel = EElasticModel::CorotatedLinear; ///< Strain measure and stress law

    /// Plasticity (von Mises, associative, perfectly plastic up to a cap), applied to each element after
    /// every symplectic sub-step or implicit piece, with that (sub-)step's dt: with the elastic strain e = eps - eps_p and sigma = C:e, when the von Mises stress
    /// sigma_vm = sqrt(3/2 s:s) (s the deviatoric part of sigma) exceeds mYieldStress, the plastic strain
    /// takes min(1, mCreepRate dt) of the deviatoric elastic strain beyond the yield surface (radial
    /// return: with an infinite creep rate sigma_vm comes back exactly to the yield stress), then the
    /// equivalent plastic strain sqrt(2/3 eps_p:eps_p) is clamped to mMaxPlasticStrain. Plastic flow is
    /// deviatoric, so it keeps the volume. The element's rest shape is that of eps_p: a barrier bent past
    /// yield stays bent. Infinity switches plasticity off (and costs nothing).
    double mYieldStress = std::numeric_limits<double>::infinity(); ///< sigma_y (Pa), > 0 (mild steel 2.5e8)
    double mCreepRate = std::numeric_limits<double>::infinity();   ///< Plastic flow rate (1/s), > 0
    double mMaxPlasticStrain = 0.5; ///< Cap of the equivalent plastic strain (dimensionless), >= 0

    /// Fracture (Rankine): after every symplectic sub-step or implicit piece the volume-weighted mean stress of each element group
    /// (cube) is decomposed into principal stresses; where the largest exceeds mTensileStrength the group
    /// detaches from neighbours as mFractureMode says. Infinity means unbreakable (and costs nothing).
    double mTensileStrength = std::numeric_limits<double>::infinity(); ///< sigma_t (Pa), > 0 (glass ~5e7)
    EFractureMode mFractureMode = EFractureMode::CrackPlane;           ///< Which faces a crack opens

    /// Largest accepted Poisson's ratio: above it lambda / mu > 99 and linear tetrahedra lock in volume
    static constexpr double cMaxPoissonRatio = 0.495;
    /// Bounds far beyond any solid (diamond's E is 1.2e12 Pa, osmium's density 22,600 kg/m^3), inside which the
    /// derived quantities (lambda + 2 mu, inverse nodal masses, the stable step's damping terms) stay finite
    static constexpr double cMaxYoungsModulus = 1.0e15;   ///< Pa
    static constexpr double cMinDensity = 1.0e-6;         ///< kg/m^3
    static constexpr double cMaxDensity = 1.0e8;          ///< kg/m^3
    static constexpr double cMaxMassDamping = 1.0e9;      ///< 1/s
    static constexpr double cMaxStiffnessDamping = 1.0e3; ///< s
};

} // namespace crumple::fem
