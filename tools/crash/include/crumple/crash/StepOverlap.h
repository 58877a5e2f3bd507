// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Math.h>
#include <crumple/crash/CrashScenario.h>

#include <string>

namespace crumple::crash
{

/// How far the car closes on its target in one engine step against how far across its path the two
/// overlap. A rigid-body engine separates a new contact along the axis of least penetration; when the car
/// closes more in one step than it overlaps the target sideways, that axis can be the sideways one, and the
/// engine pushes the car past the target instead of stopping it: a 64 km/h car meeting a 5 % offset wall at
/// 1/120 s closes 0.148 m per step against a 0.09 m overlap, and both engines slid it past with no collision
/// for Crumple, where at 1/1000 s it crushed 0.66 m. Walls that span the path (a rigid wall at any angle)
/// cannot be passed so and have no overlap here.
struct StepOverlap
{
    double mClosingPerStep = 0.0; ///< The closing speed along the path times time_step_s (m)
    double mOverlap = 0.0;        ///< The smaller sideways move that clears the target (m); infinity for a
                                  ///< target that spans the path, <= 0 for one the car misses
    /// True when the car closes more in one step than the overlap (and does meet the target)
    bool IsTooCoarse() const { return mOverlap > 0.0 && mClosingPerStep > mOverlap; }
};

/// The step and overlap of a scenario whose car has the collision box inHalfExtents (body frame, x forward,
/// m): the box's width across the path at the impact's heading, the target's (an offset wall's covered
/// share, a pole's diameter, another car's box at its heading and offset), and the closing speed (the car's
/// speed less a target car's along the path).
StepOverlap MeasureStepOverlap(const CrashScenario& inScenario, const Vec3& inHalfExtents);

/// The warning for a step that is too coarse (IsTooCoarse()), empty otherwise: both lengths, and the step
/// that would close half the overlap.
std::string StepOverlapWarning(const CrashScenario& inScenario, const StepOverlap& inStep);

} // namespace crumple::crash
