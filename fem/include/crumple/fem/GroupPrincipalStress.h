// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>
#include <crumple/base/Result.h>

#include <crumple/fem/FractureLinks.h>
#include <crumple/fem/TetElementRest.h>

#include <span>

namespace crumple::fem
{

/// The largest principal stress of an element group and its direction.
struct CRUMPLE_API PrincipalStress
{
    double mValue = 0.0;               ///< Largest eigenvalue of the stress tensor (Pa), > 0 is tension
    Vec3 mDirection = Vec3::UnitX();   ///< Unit eigenvector (sign arbitrary), world axes
};

/// Largest principal stress of each group's rest-volume-weighted mean stress, by Eigen's closed-form
/// symmetric 3x3 eigen solver (Mueller et al. 2004 and the GPU destruction paper, section IV.B, take the
/// largest tensile eigenvalue as the fracture measure).
/// @param[in]  inLinks          links of the rest mesh (groups and their elements)
/// @param[in]  inElementStress  #T Cauchy stresses (Pa), symmetric 3 by 3
/// @param[in]  inRest           #T element rest data (its rest volume weighs the mean)
/// @param[out] outPrincipal     #G, overwritten
/// Refused, writing nothing, when the sizes do not fit the links, a group has no element or the links name
/// an element outside [0, #T).
CRUMPLE_API Status GroupPrincipalStress(const FractureLinks& inLinks, std::span<const Mat3> inElementStress,
                          std::span<const TetElementRest> inRest, std::span<PrincipalStress> outPrincipal);

} // namespace crumple::fem
