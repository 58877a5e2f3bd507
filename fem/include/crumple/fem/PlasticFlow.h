// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/fem/FemMaterialSettings.h>

#include <crumple/base/Math.h>

namespace crumple::fem
{

/// One step of von Mises plasticity for one element (O'Brien, Bargteil & Hodgins 2002; Mueller & Gross 2004
/// "Interactive Virtual Materials", section 4.4, with a radial return instead of their strain-norm yield):
/// with the elastic strain e = eps - eps_p, its deviatoric part e' and the von Mises stress
/// sigma_vm = 2 mu sqrt(3/2 e':e') of an isotropic material, the excess over the yield stress flows:
///   eps_p += min(1, mCreepRate dt) (1 - sigma_y / sigma_vm) e'   when sigma_vm > sigma_y,
/// then the equivalent plastic strain sqrt(2/3 eps_p:eps_p) is clamped to mMaxPlasticStrain. With an
/// infinite creep rate sigma_vm returns exactly to sigma_y. The flow is deviatoric: volume is kept.
/// @param[in] inTotalStrain     eps, the model's strain (ModelStrain), 3 by 3 symmetric
/// @param[in] inPlasticStrain   eps_p before the step, 3 by 3 symmetric
/// @param[in] inShearModulus    mu (Pa), > 0
/// @param[in] inMaterial        mYieldStress (Pa), mCreepRate (1/s), mMaxPlasticStrain
/// @param[in] inDeltaTime       dt (s), > 0
/// @return eps_p after the step, 3 by 3 symmetric (equal to inPlasticStrain when below yield)
CRUMPLE_API Mat3 PlasticFlow(const Mat3& inTotalStrain, const Mat3& inPlasticStrain, double inShearModulus,
                 const FemMaterialSettings& inMaterial, double inDeltaTime);

/// Equivalent (von Mises) plastic strain sqrt(2/3 eps_p:eps_p) of a deviatoric plastic strain: for uniaxial
/// plastic stretch e it is |e|.
CRUMPLE_API double EquivalentPlasticStrain(const Mat3& inPlasticStrain);

} // namespace crumple::fem
