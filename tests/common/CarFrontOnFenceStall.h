// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/plugin/BaraffImpulse.h>

#include <vector>

namespace crumple::common
{

/// The racing car (1,200 kg) breaking into the held fence (50 kg, its inertia small about the fence's length)
/// with sixteen contacts of its front (dumped from the threaded Bullet racing session of 2da9d9a, the batch
/// whose joint friction solve ran to its 1,000-sweep bound; hexadecimal: the bits that were solved).
/// Gauss-Seidel's distance from Coulomb's conditions stalls at 6.5e-6 of the approach speed after about 100
/// sweeps while each sweep still moves a point by about 1e-10 of it, and every subspace step is refused (the
/// contacts' states cannot all hold): the case a stalled solve's stop is for. Gauss-Seidel alone converges
/// (to 1e-12) only after 48,807 sweeps.
struct CarFrontOnFenceStall
{
    plugin::BodyState mCar;                        ///< the racing car, body A
    plugin::BodyState mFence;                      ///< the held fence, body B
    std::vector<plugin::ImpulseContact> mContacts; ///< sixteen contacts, friction 0.25
    double mRestitution = 0.1;                     ///< DamageWorldSettings' default
    double mClosingSpeed = 0.5;                    ///< DamageWorldSettings' resting speed (m/s)
};

/// The CarFrontOnFenceStall's bodies and contacts, bit for bit as dumped.
CarFrontOnFenceStall MakeCarFrontOnFenceStall();

} // namespace crumple::common
