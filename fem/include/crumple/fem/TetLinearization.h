// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Math.h>

namespace crumple::fem
{

/// The linearisation of one element's first Piola-Kirchhoff stress around the current state:
/// dP = mFrame C:sym(mFrame^T dF) + dF mStress. Corotated: mFrame = R, mStress = 0 (the rotated rest
/// stiffness R K0 R^T). St. Venant-Kirchhoff: mFrame = F and mStress the second Piola-Kirchhoff stress
/// clamped to positive semi-definite, so the stiffness stays symmetric positive semi-definite for conjugate
/// gradient.
struct CRUMPLE_API TetLinearization
{
    Mat3 mFrame = Mat3::Identity(); ///< R or F, 3 by 3
    Mat3 mStress = Mat3::Zero();    ///< Geometric-stiffness stress (Pa), 3 by 3 symmetric PSD
};

} // namespace crumple::fem
