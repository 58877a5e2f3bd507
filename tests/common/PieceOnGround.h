// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/plugin/BaraffImpulse.h>

#include <vector>

namespace crumple::common
{

/// A 2.1 kg fence piece sliding on the ground on four contacts, one of which must let go (dumped from ODE's
/// racing sample with props off the game's thread, at 4.15 s; hexadecimal: the bits that were solved).
/// Gauss-Seidel takes 850 sweeps here. With the four contacts pushing and sliding, Newton's method ends at a
/// least-squares point 7e-5 of the approach speed off Coulomb's conditions; with the contact whose velocity
/// passes its target furthest let go, the other three meet them exactly.
struct PieceOnGround
{
    plugin::BodyState mGround;                     ///< static, body A
    plugin::BodyState mPiece;                      ///< the piece, body B
    std::vector<plugin::ImpulseContact> mContacts; ///< four contacts, normal -z (B to A), friction 0.3
    double mRestitution = 0.1;                     ///< DamageWorldSettings' default
    double mClosingSpeed = 0.5;                    ///< DamageWorldSettings' resting speed (m/s)
};

/// The PieceOnGround's bodies and contacts, bit for bit as dumped.
PieceOnGround MakePieceOnGround();

} // namespace crumple::common
