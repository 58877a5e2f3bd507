// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/fem/EElasticModel.h>

#include <crumple/base/Math.h>

namespace crumple::fem
{

/// The total strain an elasticity model measures: GreenStrain(F) = (F^T F - I) / 2 for StVenantKirchhoff,
/// sym(R^T F) - I in the element's rotated frame for CorotatedLinear. Plastic strain is subtracted from it.
/// @param[in] inModel     strain measure
/// @param[in] inF         deformation gradient, 3 by 3
/// @param[in] inRotation  polar rotation of inF (used by CorotatedLinear only), 3 by 3
/// @return symmetric strain (dimensionless), 3 by 3
CRUMPLE_API Mat3 ModelStrain(EElasticModel inModel, const Mat3& inF, const Mat3& inRotation);

} // namespace crumple::fem
