// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/plugin/ContactEvent.h>
#include <crumple/plugin/DamageWorld.h>

#include <cstdint>
#include <memory>
#include <vector>

namespace crumple::common
{

/// A brick wall bursting within one engine step, as a car's hit leaves it (the racing samples' brick wall
/// reported 1,117 contacts of 354 pairs in one ODE step): inColumns x inRows bricks (0.24 x 0.115 x 0.07 m,
/// 2.5 kg) stacked in a grid on static ground, each flying off with its own seeded velocity (3-8 m/s out of
/// the wall, row r falling at 1 + 0.6 r m/s onto the one below, +-1 m/s along the wall, +-0.5 m/s up and
/// down, spin up to 5 rad/s), touching its neighbours in four points per shared face and the ground under the
/// bottom row, friction 0.6, overlaps of up to 2 mm. The rows close on each other and on the ground, about
/// half the side-by-side pairs too, so most pairs' joint friction solves work.
struct BrickBurst
{
    std::unique_ptr<plugin::DamageWorld> mWorld; ///< The ground (static) and the bricks, no deformable object
    std::vector<plugin::ContactEvent> mContacts; ///< The step's contacts, at time 1 s
};

/// The burst in a new world made with inSettings (its job system, deferral and friction solve).
BrickBurst MakeBrickBurst(int inColumns, int inRows, std::uint32_t inSeed,
                          const plugin::DamageWorldSettings& inSettings = {});

} // namespace crumple::common
