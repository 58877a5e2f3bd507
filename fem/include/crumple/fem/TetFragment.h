// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/fem/FractureLinks.h>

#include <cstdint>
#include <span>
#include <vector>

namespace crumple::fem
{

/// A connected piece of a prop: element groups joined through shared nodes. What an adapter needs to turn a
/// loose piece into a rigid body: its mass, centre of mass and inertia (uniform density, exact for linear
/// tetrahedra), plus whether it is still held by an anchored node.
struct CRUMPLE_API TetFragment
{
    std::vector<int> mGroups;   ///< Dense group indices (FractureLinks), ascending
    std::vector<int> mElements; ///< Elements, ascending
    std::vector<int> mNodes;    ///< Current node indices, ascending
    double mMass = 0.0;         ///< kg
    Vec3 mCenterOfMass = Vec3::Zero(); ///< m, same frame as the positions
    Mat3 mInertia = Mat3::Zero();      ///< Inertia tensor about the centre of mass (kg m^2), 3 by 3 symmetric
    bool mAnchored = false;            ///< True when one of its nodes is fixed (inverse mass 0)
};

/// The fragments of a prop: its elements joined through shared current nodes (so an open crack, whose nodes
/// fracture duplicated, separates them), ordered by their lowest group (fragment 0 holds group 0). A
/// tetrahedron of mass m and corners x_i has the second moment integral x x^T dm = m / 20 (sum x_i x_i^T +
/// s s^T), s = sum x_i (Tonon 2004), from which the inertia about the fragment's centre of mass follows.
/// @param[in] inLinks          links of the rest mesh (for the element groups)
/// @param[in] inElementNodes   #T current connectivity
/// @param[in] inElementMasses  #T element masses (kg): density x rest volume
/// @param[in] inPositions      #N current node positions (m)
/// @param[in] inInverseMasses  #N (1/kg), 0 = anchored
/// A kernel without an error channel: the solvers' ComputeFragments pass their own consistent arrays; a direct
/// caller must pass #T element masses and #N inverse masses for #N positions, and connectivity within #N (a
/// debug build asserts it).
CRUMPLE_API std::vector<TetFragment> TetFragments(const FractureLinks& inLinks, std::span<const TetIndices> inElementNodes,
                                      std::span<const double> inElementMasses, std::span<const Vec3> inPositions,
                                      std::span<const double> inInverseMasses);

} // namespace crumple::fem
