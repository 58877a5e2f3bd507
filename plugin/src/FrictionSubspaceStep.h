// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include "FrictionContactRow.h"

#include <vector>

namespace crumple::plugin
{

/// What a subspace step did.
enum class ESubspaceOutcome
{
    Refused, ///< ioRows unchanged
    Kept,    ///< ioRows replaced by the exact answer of their states; Gauss-Seidel goes on from it
    Settled, ///< ioRows replaced by a least-squares point of states that cannot all hold exactly (or the
             ///< point where Newton stagnated on its way to one) that meets Coulomb's conditions to within
             ///< cSettledMerit of the approach speed: the solve ends there
};

/// A least-squares point of the subspace system ends the solve when it misses Coulomb's conditions by at most
/// this fraction of the largest approach speed (MeritOfRows). Measured on the car pressing the racing fence's
/// held body (tests/common/CarOnHeldFence.h): the least-squares point of the states Gauss-Seidel settles on
/// after 20 sweeps misses them by 4.1e-7 of the approach speed, Gauss-Seidel's own answer after the 464
/// sweeps it takes to stop by 5.5e-7; crowds of sticking contacts that cannot all hold miss by far more.
constexpr double cSettledMerit = 1.0e-6;

/// One subspace-minimization step of the joint friction solve (Silcowitz-Hansen, Niebe and Erleben 2010,
/// "Projected Gauss-Seidel subspace minimization method for interactive rigid body dynamics"): Gauss-Seidel
/// finds which contacts push and which of those stick or slide long before it converges, then can crawl for
/// hundreds of sweeps while sliding contacts turn their friction's direction a little each sweep, or
/// redundant contacts trade impulse. This step holds the states of ioRows' current impulses (a pushing
/// contact meets its normal target exactly, a sticking one stops its slip, a sliding one's friction is mu j
/// against its slip, the others stay at zero), solves the nonlinear system they make by Newton's method from
/// the current impulses (least-norm linear solves: redundant contacts make it singular), and keeps the answer
/// when it converged, keeps every state (pushing impulses >= 0, sticking friction inside its cone) and breaks
/// Coulomb's conditions by less than the current impulses do (MeritOfRows). Where the states overdetermine
/// the bodies' velocities (four sticking contacts and two sliding ones on two bodies: fourteen conditions on
/// twelve velocities), Newton ends at a least-squares point that Gauss-Seidel cannot improve on either (it
/// crawls towards a point of its own no closer to the conditions), or stops where it stagnates on its way to
/// one (a step that needed two halvings or more and still left 90 % of |F|^2): that point, when it keeps
/// every state, misses the conditions by at most cSettledMerit and by less than the current impulses,
/// settles the solve.
/// Further off, the pushing contact whose normal velocity passes its target furthest (it pushes the bodies
/// apart more than it must: a piece on more ground contacts than its velocities need) lets go, once per
/// step, and Newton solves again. Deterministic.
/// @param[in] inSpeedScale  the largest approach speed (m/s): the scale of the velocity equations
/// @param[in,out] ioRows    the contacts with the current impulses; replaced by the step's unless refused
/// @param[out] outIterations  the Newton iterations the step took (at most cMaxStepIterations)
/// @return what the step did
ESubspaceOutcome FrictionSubspaceStep(const PairInverseMass& inPair, double inSpeedScale,
                                      std::vector<ContactRow>& ioRows, int& outIterations);

/// Newton iterations per step at most, over all its state changes: each costs a least-norm solve of up to 48
/// unknowns. Over 20,000 adversarial seeded sets (scratch fuzz: 10 g to 10 t, inertias 1e4 apart, duplicated
/// contacts, flipped normals, mu = +inf in one in five) the steps kept needed 2-10 iterations mostly and up
/// to 128; bounded at 32 the slowest solve took 5.2-5.3 ms of CPU instead of 13.1-13.7 ms, and 1,348 sets
/// instead of 1,325 stopped at the sweep bound.
constexpr int cMaxStepIterations = 32;

/// How far ioRows' impulses are from Coulomb's conditions (m/s): the largest, over the contacts, of the
/// normal velocity change missing from a pushing contact's target or an idle one's, the slip of a sticking
/// contact, and the part of a sliding contact's slip not against its friction.
double MeritOfRows(const PairInverseMass& inPair, const std::vector<ContactRow>& inRows);

} // namespace crumple::plugin
