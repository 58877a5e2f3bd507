// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Math.h>

namespace crumple::fem
{

/// A ground the free nodes of an implicit TetSolver rest on: the half-space mNormal . x >= mOffset in the
/// solver's frame (a held prop's body frame). A node on the ground at the start of a step keeps its normal
/// velocity at zero through the step's solve (Baraff & Witkin 1998's filtered conjugate gradient: the ground
/// takes the normal part of the node's residual), until the solve finds the ground pulling it (the node then
/// leaves, within the same step; one that reached the ground during the step's iterations stays held to its
/// end, so the iterations settle); a node that ends a step below the ground is put on it and loses its
/// approaching velocity (a plastic impact). Either way the ground's normal impulse per unit mass, j, slows
/// the node's tangential velocity by at most mFriction j (Coulomb, at velocity level; the step's positions
/// stay the solve's, and the next step's solve carries the slowing through the body, so a stiff body is not
/// strained by it), so a body resting on it settles and sleeps, and one sliding on it decelerates by
/// mFriction g. A node whose rest position lies below the ground (a footing set into it) is not held by it.
/// The ground is where a game's ground is, so a part left hanging from a held prop falls onto it instead of
/// swinging through it.
struct GroundPlane
{
    bool mEnabled = false;              ///< Off by default: no node is held and nothing is computed
    Vec3 mNormal = Vec3(0.0, 0.0, 1.0); ///< Unit normal pointing out of the ground (solver frame)
    double mOffset = 0.0;               ///< The ground is mNormal . x = mOffset (m)
    double mFriction = 0.6;             ///< Coulomb coefficient, finite and >= 0
};

} // namespace crumple::fem
