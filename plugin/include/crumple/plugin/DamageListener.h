// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/ffd/DentReport.h>
#include <crumple/plugin/Collision.h>
#include <crumple/plugin/Ids.h>

#include <span>

namespace crumple::plugin
{

/// What one object did with a dispatched collision.
struct CRUMPLE_API ObjectDent
{
    ObjectId mObject;        ///< The object
    ffd::DentReport mReport; ///< Its dent (all zero when the collision asked for none)
};

/// Receives every collision a DamageWorld dispatches, after the objects have been dented: the hook for
/// game audio, particles, network replication and recorders (a listener per world, no global callback).
///
/// Threading: called synchronously from DamageWorld::Update/Flush on the calling thread, in dispatch order
/// (start time, body ids, creation order). A listener may add or remove listeners of the world (itself
/// included: a dispatch calls the ones registered when it began that are still registered) and read it, but
/// must not change its bodies, objects or contacts (no SubmitContacts, SetBodyState, RemoveBody,
/// ResetDamage, LoadDamage, Update or Flush from a callback).
class CRUMPLE_API DamageListener
{
public:
    virtual ~DamageListener() = default;

    /// A collision is about to dent its objects (a recorder captures objects it has not seen yet here, with
    /// the damage they had before this collision). Optional.
    virtual void OnBeforeCollision(const Collision& inCollision) { (void)inCollision; }

    /// One closed collision and the dents it made.
    /// @param[in] inCollision the collision (contacts with surface points, normals, impulses)
    /// @param[in] inDents     one entry per deformable object attached to either body, in ObjectId order
    virtual void OnCollision(const Collision& inCollision, std::span<const ObjectDent> inDents) = 0;
};

} // namespace crumple::plugin
