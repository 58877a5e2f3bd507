// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include "FrictionContactRow.h"

#include <vector>

namespace crumple::plugin
{

/// One subspace-minimization step of the joint friction solve (Silcowitz-Hansen, Niebe and Erleben 2010,
/// "Projected Gauss-Seidel subspace minimization method for interactive rigid body dynamics"): Gauss-Seidel
/// finds which contacts push and which of those stick or slide long before it converges, then can crawl for
/// hundreds of sweeps while sliding contacts turn their friction's direction a little each sweep, or
/// redundant contacts trade impulse. This step holds the states of ioRows' current impulses (a pushing
/// contact meets its normal target exactly, a sticking one stops its slip, a sliding one's friction is mu j
/// against its slip, the others stay at zero), solves the nonlinear system they make by Newton's method from
/// the current impulses (least-norm linear solves: redundant contacts make it singular), and keeps the answer
/// when it converged, keeps every state (pushing impulses >= 0, sticking friction inside its cone) and breaks
/// Coulomb's conditions by less than the current impulses do (MeritOfRows). Deterministic.
/// @param[in] inSpeedScale  the largest approach speed (m/s): the scale of the velocity equations
/// @param[in,out] ioRows    the contacts with the current impulses; replaced by the step's only when it is
/// kept
/// @return whether ioRows changed
bool FrictionSubspaceStep(const PairInverseMass& inPair, double inSpeedScale,
                          std::vector<ContactRow>& ioRows);

/// How far ioRows' impulses are from Coulomb's conditions (m/s): the largest, over the contacts, of the
/// normal velocity change missing from a pushing contact's target or an idle one's, the slip of a sticking
/// contact, and the part of a sliding contact's slip not against its friction.
double MeritOfRows(const PairInverseMass& inPair, const std::vector<ContactRow>& inRows);

} // namespace crumple::plugin
