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
/// sliding) after 2,242 sweeps. The states Gauss-Seidel holds on the way cannot all hold: the subspace steps'
/// Newton iterations creep towards their least-squares points, and until Newton stopped creeping (stagnation,
/// FrictionSubspaceStep.cpp) every step was refused at its iteration bound and the solve stopped at the
/// 1,000-sweep bound 1.26e-4 off; now the step after 620 sweeps lands on the answer.
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
