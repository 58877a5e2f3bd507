// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/plugin/BaraffImpulse.h>

#include <vector>

namespace crumple::common
{

/// The racing car (1,200 kg) pressing the held fence (50 kg), twelve contacts, six of them speculative
/// (dumped from the Bullet racing sample in the frame before the fence breaks, 3.13-3.15 s, props off the
/// thread; hexadecimal: the bits that were solved). Gauss-Seidel takes 464 sweeps here. The states it settles
/// on (four contacts sticking, two sliding, six idle) overdetermine the two bodies' twelve velocities a
/// little: Newton's method with them held ends at a least-squares point 7e-6 m/s off (of a 20 m/s approach).
/// Every subspace step was refused until such a point, close enough to Coulomb's conditions, settled the
/// solve (cSettledMerit): it now ends after 20 sweeps.
struct CarOnHeldFence
{
    plugin::BodyState mCar;                        ///< the racing car, body A
    plugin::BodyState mFence;                      ///< the held fence, body B
    std::vector<plugin::ImpulseContact> mContacts; ///< twelve contacts, friction 0.25
    double mRestitution = 0.1;                     ///< DamageWorldSettings' default
    double mClosingSpeed = 0.5;                    ///< DamageWorldSettings' resting speed (m/s)
};

/// The racing fence's held body at rest (50 kg, its inertia small about the fence's length), as every dump of
/// a batch against it has it, bit for bit.
plugin::BodyState RacingFenceHeldBody();

/// The CarOnHeldFence's bodies and contacts, bit for bit as dumped.
CarOnHeldFence MakeCarOnHeldFence();

} // namespace crumple::common
