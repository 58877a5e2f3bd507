// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/crash/CrashRun.h>

#include <string>
#include <vector>

namespace crumple::crash
{

/// A check that a run is physically possible, whatever its expectations say: a run that fails one
/// measured nothing trustworthy, so crumple-crash exits 1 and the report names it.
struct SanityResult
{
    std::string mName;    ///< e.g. "no_tunnelling"
    bool mApplies = true; ///< False: the check means nothing for this scene (it then passes), mDetail says why
    bool mPassed = true;
    double mValue = 0.0;  ///< What was measured (unit in mDetail)
    double mLimit = 0.0;  ///< The bound it was held to
    std::string mDetail;  ///< One sentence: what was measured against what
};

/// The sanity checks of a run:
/// - no_tunnelling: against a full rigid wall the car's centre ends on the approach side of the wall's face;
///   against a pole it does not end past the pole with the pole inside its width. (At 1000 km/h a car
///   passes a wall between two engine steps and is never stopped.)
/// - energy_balance: the energy the car lost is >= 0 and <= its kinetic energy at the start (a standing or
///   moving target vehicle can hand the car energy: there the check does not apply).
/// - impulse_momentum: over the collisions' own time span, the car's momentum change along the summed
///   impulse agrees with Crumple's impulses (the vectors on the car, summed) within
///   CrashScenario::mImpulseTolerance of the larger. Friction and the ground act across or beside it. With
///   no collision at all, the car's horizontal velocity may change by no more than that share of its start
///   speed (an engine that stops a car Crumple never saw touch anything).
/// - no_folded_vertices: no vertex normal of the car body turned against its rest normal (FoldedVertices).
/// Folded triangles (slivers a smooth dent may tip) are reported, not failed.
std::vector<SanityResult> CheckSanity(const CrashScenario& inScenario, const CrashOutcome& inOutcome);

/// True when every check passes.
bool AllSane(const std::vector<SanityResult>& inResults);

} // namespace crumple::crash
