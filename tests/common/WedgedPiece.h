// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/plugin/BaraffImpulse.h>

#include <vector>

namespace crumple::common
{

/// A fence piece of 0.125 kg wedged against the 50 kg held fence it broke from, four contacts on two faces
/// (dumped from the Bullet racing sample at 3.15 s, props off the thread; hexadecimal: the bits that were
/// solved). Gauss-Seidel crawled here: for 700 sweeps the normal impulses drifted by up to 40 % while the
/// sliding contacts turned their friction a little each sweep, no contact point's velocity changing by more
/// than 1e-5 of the approach speed per sweep, and the solve ended at its 1,000-sweep bound.
struct WedgedPiece
{
    plugin::BodyState mFence;                      ///< the held fence, 50 kg
    plugin::BodyState mPiece;                      ///< the piece, 0.125 kg
    std::vector<plugin::ImpulseContact> mContacts; ///< four contacts on two faces, friction 0.25
    double mRestitution = 0.1;                     ///< DamageWorldSettings' default
    double mClosingSpeed = 0.5;                    ///< DamageWorldSettings' resting speed (m/s)
};

/// The WedgedPiece's bodies and contacts, bit for bit as dumped.
WedgedPiece MakeWedgedPiece();

} // namespace crumple::common
