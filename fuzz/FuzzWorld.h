// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/plugin/DamageWorld.h>
#include <crumple/plugin/DeformableObjectSettings.h>

#include <memory>

namespace crumple::fuzz
{

/// A small damage world for the fuzz targets and their seeds: a 4.2 m box car (about 2,000 triangles) and
/// a static wall it hits at 15 m/s head-on.
class FuzzWorld
{
public:
    FuzzWorld();
    /// The hit: four contacts on the car's front face, dispatched (the front dented).
    void Dent();
    plugin::DamageWorld& Get() { return mWorld; }
    /// The static wall's body (its frame is the world's)
    plugin::BodyId GetWall() const { return mWall; }
    /// The car's deformable object settings (what a recording stores).
    const plugin::DeformableObjectSettings& GetCarSettings() const { return mCarSettings; }

private:
    plugin::DeformableObjectSettings mCarSettings;
    std::unique_ptr<plugin::DamageWorld> mWorldOwner; ///< On the heap: the world never moves
    plugin::DamageWorld& mWorld;
    plugin::BodyId mCar, mWall;
};

} // namespace crumple::fuzz
