// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/JobSystem.h>
#include <crumple/plugin/CollisionGrouper.h>
#include <crumple/plugin/ESpeculativeContacts.h>
#include <crumple/plugin/FrictionalImpulses.h>

#include <cstddef>

namespace crumple::plugin
{

/// Settings of a DamageWorld.
struct CRUMPLE_API DamageWorldSettings
{
    CollisionGrouperSettings mGrouping; ///< Time window and distance of a collision
    double mRestitution = 0.1;          ///< Coefficient of restitution of impacts, in [0, 1]; car crashes are
                                        ///< nearly plastic
    double mRestingSpeed = 0.5;         ///< Contacts closing slower than this (m/s) are resting and make no
                                        ///< impulse and no dent (like Box2D's hit-event threshold); it must
                                        ///< exceed gravity x step (0.16 m/s at 60 Hz) so a parked car is never dented
    /// Most contacts of one body pair in one step that the impulse solve takes, >= 9: a larger manifold is
    /// reduced to representatives that span its patch (ReduceContacts), so its cost stays bounded
    std::size_t mMaxContactsPerPair = 16;
    /// The joint friction solve of each pair's contacts (FrictionalImpulses): its sweep bound and subspace
    /// steps. A game that must bound a frame's worst case may lower mMaxSweeps (a stopped solve keeps
    /// friction in its cone and makes no energy, but meets Coulomb's conditions only approximately).
    FrictionSolveSettings mFrictionSolve;
    /// A body pair that took an impulse at the previous engine step solves the next step's contacts from the
    /// velocities that impulse left it with instead of the engine's (see DamageWorld::SubmitContacts). An
    /// impact is then counted once however many steps the engine takes to stop it (ODE's soft contacts take
    /// several, Bullet's one), and its impulse no longer depends on the engine. Turn it off only for a
    /// coupling that resolves contacts gradually itself and reports each step's share as a full impulse.
    bool mCountImpactOnce = true;
    /// What the engine's solver does with a hit it predicts from a contact reported before touching (see
    /// ESpeculativeContacts): StopAtSurface for Bullet (and ODE, which reports none), ResolveWhole for Jolt
    /// or Box2D. docs/adapters.md says how to tell for another engine.
    ESpeculativeContacts mSpeculativeContacts = ESpeculativeContacts::StopAtSurface;
    /// The host's job system for the per-vertex work of dents and for the pairs' impulse solves of a step
    /// with many closing contacts (DamageWorld::cParallelClosingContacts: a brick wall bursting; a step of
    /// fewer solves inline) (not owned; it must outlive the world); null: everything runs on the thread that
    /// calls SubmitContacts and Update/Flush. Results are bitwise identical either way.
    const JobSystem* mJobs = nullptr;
    /// Dents run off the game's thread and land one Update later: the Update that closes a collision starts
    /// its dents as one task on mJobs (which needs mStartTask and mWaitTask), and the next Update (or Flush,
    /// or any call that reads or changes damage) waits for it, publishes the moved vertices and calls
    /// OnCollision. Meanwhile the objects' GetPositions, GetNormals and dirty ranges keep showing the state
    /// before the dents (FfdDeformer::SetPublishing); anything else of an object (its zones and controls,
    /// GetCurrentPositions) is the task's until the landing, so read it after Update or Flush returns with
    /// HasDentsInFlight() false. Dents are applied in the same order as inline, so
    /// meshes, damage states and recordings are bitwise the same; the task's per-vertex work runs on the
    /// task's thread (mJobs' parallel for is not called from it).
    bool mDeferDents = false;
    /// With mDeferDents, the contacts' impulses are solved on the dents' task too (the joint friction solve
    /// of a crowd of contacts can cost milliseconds): SubmitContacts only validates a step's contacts and
    /// keeps them with their bodies' states, ForgetImpacts waits in order with them, and the next Update's
    /// task solves them, in order, before its dents. The collisions they close are dispatched one Update
    /// later than with mDeferDents alone (their dents land one more Update later; a body with
    /// SetDispatchEachStep hears of its hit at the end of the next step, not of this one), and Flush and
    /// RemoveBody solve what waits on the calling thread. Collisions, dents and recordings are bitwise those
    /// of mDeferDents alone where nothing reacts to the dispatch (a prop does), whatever the job system.
    bool mDeferImpulses = false;
};

} // namespace crumple::plugin
