// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/plugin/BaraffImpulse.h>

#include <span>
#include <vector>

namespace crumple::plugin
{

/// One contact's impulse: +mNormal n + mFriction on A, the opposite on B (world frame).
struct CRUMPLE_API ContactImpulse
{
    double mNormal = 0.0;          ///< Along the contact normal n (B to A) (N s), >= 0
    Vec3 mFriction = Vec3::Zero(); ///< Tangential impulse on A (N s), perpendicular to n, |mFriction| <= mu mNormal
};

/// How the joint friction solve is bounded and sped up (FrictionalImpulses).
struct CRUMPLE_API FrictionSolveSettings
{
    /// Gauss-Seidel sweeps at most (>= 1): crowds of redundant contacts can crawl.
    int mMaxSweeps = 1000;
    /// Sweeps before the first subspace step (0: none), each later one twice as many as the one before. A
    /// step solves the nonlinear system of the contacts' current states (pushing, sticking, sliding) by
    /// Newton's method and is kept when it keeps those states and meets Coulomb's conditions better. Where
    /// Gauss-Seidel crawls this ends it; where the states overdetermine the velocities a little, the
    /// least-squares point ends the solve when it meets the conditions to 1e-6 of the approach speed
    /// (FrictionSolveStats::mSettled), and further off the contact that pushes apart most beyond its target
    /// lets go; where no such answer exists the doubling bounds the steps' cost (crumple-bench
    /// friction_crawl rows). A scheduled step after a refused one waits until Gauss-Seidel has halved the
    /// distance from Coulomb's conditions since the refusal (from a state no better it would fail as it did);
    /// a Gauss-Seidel that stalls (over 50 sweeps no point moved by more than 1e-9 of the largest approach
    /// speed and that distance fell by less than 1 %) gets a step at once, and where that step is refused too
    /// the solve stops (FrictionSolveStats::mStalled): the car's 16 contacts on the racing fence's held body
    /// stopped after 150 sweeps and two refused steps instead of at the 1,000-sweep bound after five (2.1
    /// against 4.7 ms in a scratch driver, the two alternated), the impulses' sums the same to 1e-3 N s.
    /// 0: no steps, and no stall stop either.
    int mSubspaceInterval = 20;
    /// Pairs of more contacts take no subspace steps: a step costs O((3N)^3), at 64 sliding contacts 2.5
    /// times the 143 sweeps it saved. DamageWorldSettings::mMaxContactsPerPair (16) reduces an engine's
    /// manifold to this many.
    int mSubspaceMaxContacts = 16;
};

/// What one joint friction solve did.
struct CRUMPLE_API FrictionSolveStats
{
    int mSweeps = 0; ///< Gauss-Seidel sweeps run (0: no friction acted, the frictionless answer stands)
    int mSubspaceSteps = 0; ///< subspace steps kept
    int mNewtonIterations = 0;   ///< Newton iterations of all the subspace steps, kept or refused
    int mMostStepIterations = 0; ///< the most one step took (at most 32: a step that needs more is refused)
    /// False: stopped at FrictionSolveSettings::mMaxSweeps while a sweep still moved a contact point's
    /// velocity by more than 1e-12 of the largest approach speed, or stopped stalled (mStalled).
    bool mConverged = true;
    /// Stopped at the bound with impulses that made kinetic energy: the frictionless answer
    /// (SimultaneousImpulses' normal impulses, friction zero) was returned instead, as it made less.
    bool mFrictionDropped = false;
    /// Ended (converged) at a subspace step's least-squares point, or where its Newton stagnated on its way
    /// to one: the contacts' states overdetermine the bodies' velocities a little, and the point meets
    /// Coulomb's conditions to within 1e-6 of the largest approach speed, closer than Gauss-Seidel comes
    /// before it stops
    bool mSettled = false;
    /// Stopped before its bound (not converged): Gauss-Seidel had stalled (over 50 sweeps no point's velocity
    /// moved by more than 1e-9 of the largest approach speed, the distance from Coulomb's conditions fell by
    /// less than 1 %) and a subspace step from there was refused too
    bool mStalled = false;
};

/// Impulses with Coulomb friction of contacts that one engine step reported together for the same body pair.
///
/// Starts from SimultaneousImpulses' normal impulses (closing contacts only, K j = -(1+e) v, minimum norm,
/// pushing only). Each contact's friction impulse t then stops its sliding (zero relative tangential velocity
/// after the impulses, no tangential restitution) where Coulomb's isotropic cone |t| <= mu j allows;
/// otherwise it slides and t lies on the cone against the slip (maximal dissipation). Friction at a lever arm
/// changes the normal approach speeds and the normal impulses bound friction, so both are solved together:
/// projected Gauss-Seidel over every contact's normal row and 2x2 tangent block, as engines solve contact,
/// until a sweep moves no contact point's velocity by more than 1e-12 of the largest approach speed (or it
/// stalls where a subspace step cannot help either: FrictionSolveSettings::mSubspaceInterval), with
/// subspace minimization steps (Silcowitz-Hansen, Niebe and Erleben 2010) between (FrictionSolveSettings). A
/// solve stopped at its sweep bound whose impulses made kinetic energy returns the frictionless answer where
/// that makes less (FrictionSolveStats::mFrictionDropped). Every contact joins, so one that friction presses
/// onto the other body is held too. The restitution target stays the approach speed before any impulse: after
/// the solve each pushing contact separates at e times the speed it closed with. With mu = 0 on every contact
/// the normal impulses are SimultaneousImpulses' bit for bit and friction is zero. Deterministic: the same
/// input gives the same bits.
/// @param[in] inContacts       contacts with their mu (ImpulseContact::mFriction, >= 0, +inf for no sliding)
/// @param[in] inRestitution    coefficient of restitution e in [0, 1]
/// @param[in] inClosingSpeed   contacts approaching slower than this (m/s, >= 0), after their speculative
///                             speed, count as resting: zero impulse, normal and tangential
/// @param[in] inSettings       the solve's sweep bound and subspace interval
/// @param[out] outStats        when not null, what the solve did
/// @return one ContactImpulse per contact, in order
CRUMPLE_API std::vector<ContactImpulse> FrictionalImpulses(const BodyState& inA, const BodyState& inB,
                                                           std::span<const ImpulseContact> inContacts,
                                                           double inRestitution, double inClosingSpeed,
                                                           const FrictionSolveSettings& inSettings = {},
                                                           FrictionSolveStats* outStats = nullptr);

} // namespace crumple::plugin
