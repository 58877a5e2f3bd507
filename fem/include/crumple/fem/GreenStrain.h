// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Math.h>

namespace crumple::fem
{

/// Green(-Lagrange) strain E = (F^T F - I) / 2 (the paper's "Green's strain tensor", section IV.A).
/// Symmetric, exactly zero for any rigid motion, quadratic in the displacement gradient.
/// @param[in] inF  deformation gradient, 3 by 3
/// @return E (dimensionless), 3 by 3 symmetric
CRUMPLE_API Mat3 GreenStrain(const Mat3& inF);

} // namespace crumple::fem
