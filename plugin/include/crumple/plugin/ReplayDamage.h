// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/plugin/DeformableObject.h>
#include <crumple/plugin/ReplayFormat.h>

#include <cstddef>
#include <functional>
#include <vector>

namespace crumple::plugin
{

/// An object rebuilt from a recording, with its replayed damage.
struct CRUMPLE_API ReplayedObject
{
    ObjectId mObject; ///< Its id in the recorded world
    BodyId mBody;     ///< Its body in the recorded world
    std::uint64_t mFirstCollision = 0; ///< Index of the first recorded collision that can dent it
    DeformableObject mDeformable; ///< Mesh and deformer after the replay
};

/// Rebuilds every object of a recording with the damage it had when recording began, in object id order
/// (the dispatch order of the live world). Fails, building nothing further, on the first object whose
/// settings or initial damage the library refuses.
CRUMPLE_API Result<std::vector<ReplayedObject>> CreateReplayedObjects(const Replay& inReplay);

/// Applies each recorded collision to ioObjects (from CreateReplayedObjects of the same recording): the
/// objects of body A, then of body B, in object id order, exactly as DamageWorld dispatched them; an
/// object created mid-run only takes the collisions recorded after it.
/// A replay made by hand whose collisions ValidateCollision refuses returns the first one's error, naming
/// its index, before any collision is applied (DecodeReplay has checked a read one).
/// @param[in] inAfterCollision called after each collision with its index and the objects; may be empty
CRUMPLE_API Status ApplyReplayedCollisions(
    const Replay& inReplay, std::vector<ReplayedObject>& ioObjects,
    const std::function<void(std::size_t, const std::vector<ReplayedObject>&)>& inAfterCollision = {});

/// Replays a recording without any physics engine: rebuilds every object (restoring its initial damage),
/// then applies each collision to the objects of body A, then of body B, in object id order, exactly as
/// DamageWorld dispatched them; an object created mid-run only takes the collisions recorded after it. The deformed meshes are bitwise identical to the live run's.
/// @param[in] inAfterCollision called after each collision with its index and the objects (for a frame
///            sequence); may be empty
CRUMPLE_API Result<std::vector<ReplayedObject>> ReplayDamage(
    const Replay& inReplay,
    const std::function<void(std::size_t, const std::vector<ReplayedObject>&)>& inAfterCollision = {});

} // namespace crumple::plugin
