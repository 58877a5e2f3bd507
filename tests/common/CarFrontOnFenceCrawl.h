// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/plugin/BaraffImpulse.h>

#include <vector>

namespace crumple::common
{

/// The racing car (1,200 kg) pressing its front into the held fence (50 kg, moving at 0.97 m/s with the
/// struck timbers) with sixteen contacts (dumped from the threaded Bullet racing session of e81d451 at t
/// = 3.74 s, the batch whose joint friction solve was the session's costliest; hexadecimal: the bits that
/// were solved). Unlike CarFrontOnFenceStall, Gauss-Seidel does not stall: its distance from Coulomb's
/// conditions sits at 8.7e-5 of the approach speed from about 500 sweeps on while each sweep still moves a
/// contact point by 1.6e-7 of it, trading impulse among nearly coplanar contacts until only three push (all
/// sliding) after 2,242 sweeps; every subspace step on the way is refused (the states Gauss-Seidel holds then
/// cannot all hold). The case the 1,000-sweep bound is for.
struct CarFrontOnFenceCrawl
{
    plugin::BodyState mCar;                        ///< the racing car, body A
    plugin::BodyState mFence;                      ///< the held fence, body B
    std::vector<plugin::ImpulseContact> mContacts; ///< sixteen contacts, friction 0.25
    double mRestitution = 0.1;                     ///< DamageWorldSettings' default
    double mClosingSpeed = 0.5;                    ///< DamageWorldSettings' resting speed (m/s)
};

/// The CarFrontOnFenceCrawl's bodies and contacts, bit for bit as dumped.
CarFrontOnFenceCrawl MakeCarFrontOnFenceCrawl();

} // namespace crumple::common
