// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Math.h>
#include <crumple/fem/GroundPlane.h>

#include <cstdint>
#include <span>

namespace crumple::fem
{

// The ground's part of TetSolver's implicit step (GroundPlane): which nodes it holds, the filter that keeps
// their normal velocity out of the solve, and the friction and projection after it. Private to the solver.

/// How a node is held in a step's mask (0: not held). A node held from the step's start may be let go
/// (ReleasePulledNodes); one that joins during the Newton iterations (HoldCrossingNodes) stays held to the
/// step's end. Letting it go again made an active-set cycle: the update after its release took it through the
/// ground, the next put it back on, each switch moved a node of a stiff body by a good part of the step's
/// approach, and the iterations never settled (a car pressing a steel fence into the ground: the
/// preconditioned residual swung between 1e3 and 1e9 J on alternate iterations; a steel bar driven into the
/// ground in TetGroundTest: 19 of 120 steps split, one gained 8.9 kJ, and it stopped dead from 12 m/s). Held
/// to the step's end, such a node may hold on to the ground for that one step (its normal impulse then
/// pulls); the next step starts it on the ground, held, and lets it go when the ground would pull.
constexpr std::uint8_t cHeldReleasable = 1;
constexpr std::uint8_t cHeldToStepEnd = 2;

/// Marks in outHeld (#N, overwritten) the free nodes (inFree) whose rest position (inRest) lies above
/// inGround and whose start position (inStartPositions) is on it or below, and gives each, in the step's
/// velocity iterate ioVelocities, no normal velocity (a node placed below the ground is stopped there, not
/// pushed out, which would do work). A node the step's solve would take through the ground joins later
/// (HoldCrossingNodes): a start velocity alone says little where an impulse struck a few light nodes, whose
/// momentum the solve spreads over the body.
/// @return how many are held
int HoldGroundNodes(const GroundPlane& inGround, std::span<const std::uint8_t> inFree,
                    std::span<const Vec3> inRest, std::span<const Vec3> inStartPositions, double inDeltaTime,
                    std::span<std::uint8_t> outHeld, std::span<Vec3> ioVelocities);

/// After a Newton update: holds to the step's end (cHeldToStepEnd) the free nodes not held yet (rest position
/// above the ground) that the update took below the ground, their normal velocity and position (ioPositions =
/// start + inDeltaTime ioVelocities) set to land on it at the step's end: an approaching node lands instead
/// of going through (its impact reaches the rest of the body through the solve, not through a moved position,
/// which would strain a stiff body by the whole step's approach).
/// @return how many were added
int HoldCrossingNodes(const GroundPlane& inGround, std::span<const std::uint8_t> inFree,
                      std::span<const Vec3> inRest, std::span<const Vec3> inStartPositions,
                      double inDeltaTime, std::span<std::uint8_t> ioHeld, std::span<Vec3> ioPositions,
                      std::span<Vec3> ioVelocities);

/// Lets go of the nodes held from the step's start (cHeldReleasable) whose momentum residual (inResidual, #N)
/// points away from the ground: there the ground would have to pull (Baraff & Witkin release a constraint
/// whose force changes sign).
/// @return how many were let go
int ReleasePulledNodes(const Vec3& inNormal, std::span<const Vec3> inResidual,
                       std::span<std::uint8_t> ioHeld);

/// Removes the normal part of ioValues at the held nodes (Baraff & Witkin's filter S = I - n n^T).
void FilterGroundNormal(const Vec3& inNormal, std::span<const std::uint8_t> inHeld, std::span<Vec3> ioValues);

/// The ground's normal impulse on each held node, -n . r of its momentum residual (N s; >= 0 once
/// ReleasePulledNodes has run, except at the nodes held to the step's end, where it may pull), into
/// outImpulses (#N; 0 at the other nodes), and that normal part taken out of ioResidual (FilterGroundNormal):
/// the ground supplies it.
void TakeGroundImpulses(const Vec3& inNormal, std::span<const std::uint8_t> inHeld,
                        std::span<Vec3> ioResidual, std::span<double> outImpulses);

/// After the solve: each held node's tangential velocity slowed by inGround.mFriction times its impulse per
/// unit mass (at most to zero), its position left where the solve put it: moved to x0 + h v alone, a node of
/// a stiff body was pulled back against its neighbours by its whole slowing over the step (a car pushing a
/// steel fence along the ground at 13 m/s: megajoules of strain where the solve left kilojoules; the steps
/// diverged in up to 32 pieces, 1.1 s of one step). The slowing reaches the neighbours through the next
/// step's solve, as an impulse does. The pushing nodes' impulses are scaled down, for their friction, to the
/// ground's net normal impulse on the body (the held nodes' impulses, those held to the step's end pulling,
/// less the normal residual inResidual (#N) that an unconverged Newton iteration leaves at the other nodes),
/// so the friction stays within mFriction times the ground's net push (Coulomb's bound; a steel bar driven
/// into the ground was slowed 4 % past it by pulling nodes, bars of random stiffness up to 2.7 % by
/// unconverged steps). Each other free node still below the ground (rest position above it;
/// only where Newton stopped at its iteration limit) put on it, its approaching velocity removed and its
/// tangential velocity slowed by inGround.mFriction times the removed speed.
/// @return true when a position changed (a velocity alone leaves the step's last element pass valid)
bool FinishGroundStep(const GroundPlane& inGround, std::span<const std::uint8_t> inFree,
                      std::span<const Vec3> inRest, std::span<const std::uint8_t> inHeld,
                      std::span<const double> inImpulses, std::span<const double> inMasses,
                      std::span<const Vec3> inResidual, std::span<Vec3> ioPositions,
                      std::span<Vec3> ioVelocities);

} // namespace crumple::fem
