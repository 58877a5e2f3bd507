// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>
#include <crumple/base/Result.h>

#include <crumple/fem/EFractureMode.h>
#include <crumple/fem/GroupPrincipalStress.h>

#include <cstdint>
#include <span>

namespace crumple::fem
{

/// Cosine of the widest angle between a face normal and the principal direction for which a CrackPlane
/// crack opens that face: 55 degrees, just over the 54.74 degrees by which every direction is within reach
/// of some face normal of a cube.
inline constexpr double cCrackFaceCosine = 0.573576436351046; // cos(55 deg)

/// Rankine's criterion on the links: a group whose largest principal stress exceeds the tensile strength
/// breaks its links as inMode says (EFractureMode). Every group is judged on the same stresses before any
/// link breaks, so the result does not depend on link order.
/// @param[in]     inLinks           links of the rest mesh
/// @param[in]     inPrincipal       #G largest principal stress per group (GroupPrincipalStress)
/// @param[in]     inElementNodes    #T current connectivity
/// @param[in]     inPositions       #N current positions (m): the face normals are taken as they are now
/// @param[in]     inTensileStrength sigma_t (Pa), > 0
/// @param[in]     inMode            which faces open
/// @param[in,out] ioBroken          #L, set to 1 where a link breaks
/// @return number of links broken by this call; refused, breaking nothing, when the sizes do not fit the
/// links (#G stresses, #L flags) or a link face, element or node index is out of range
CRUMPLE_API Result<int> OpenCracks(const FractureLinks& inLinks, std::span<const PrincipalStress> inPrincipal,
               std::span<const TetIndices> inElementNodes, std::span<const Vec3> inPositions,
               double inTensileStrength, EFractureMode inMode, std::span<std::uint8_t> ioBroken);

} // namespace crumple::fem
