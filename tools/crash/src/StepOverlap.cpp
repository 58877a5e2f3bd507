// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/crash/StepOverlap.h>

#include "EngineCrash.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

namespace crumple::crash
{

namespace
{

// Half the width across the path (world y) of a box of inHalfExtents turned by inYawDegrees about the
// vertical.
double HalfWidthAcross(const Vec3& inHalfExtents, double inYawDegrees)
{
    const double yaw = inYawDegrees * std::numbers::pi / 180.0;
    return std::abs(inHalfExtents.x() * std::sin(yaw)) + std::abs(inHalfExtents.y() * std::cos(yaw));
}

// The smaller sideways move that takes [inLow, inHigh] clear of [inOtherLow, inOtherHigh] (<= 0: clear now).
double SidewaysClearance(double inLow, double inHigh, double inOtherLow, double inOtherHigh)
{
    return std::min(inHigh - inOtherLow, inOtherHigh - inLow);
}

} // namespace

StepOverlap MeasureStepOverlap(const CrashScenario& inScenario, const Vec3& inHalfExtents)
{
    const ImpactSpec& impact = inScenario.mImpact;
    const TargetSpec& target = inScenario.mTarget;
    const double half = HalfWidthAcross(inHalfExtents, impact.mHeadingDegrees);
    const double low = impact.mOffset - half, high = impact.mOffset + half;
    StepOverlap result;
    result.mClosingPerStep = impact.mSpeed * inScenario.mTimeStep;
    result.mOverlap = std::numeric_limits<double>::infinity();
    switch (target.mType)
    {
    case ETarget::RigidWall:
    case ETarget::FemBarrier: // met by the runner's own coupling, not by the engine
        break;
    case ETarget::Pole:
        // A pole at the origin, across the path y in [-r, r].
        result.mOverlap = SidewaysClearance(low, high, -target.mPoleRadius, target.mPoleRadius);
        break;
    case ETarget::OffsetWall:
    {
        // It covers mOverlapPercent of the car's width on the car's left (+y) side and everything beyond, so
        // only a move to the right clears it; its edge is the one the engine scenes build.
        common::EngineCrashSettings crash;
        crash.mOffset = impact.mOffset;
        crash.mHalfExtents = inHalfExtents;
        crash.mOverlapFraction = target.mOverlapPercent / 100.0;
        result.mOverlap = high - common::CrashWallLeftEdge(crash);
        break;
    }
    case ETarget::Vehicle:
    {
        const double other = HalfWidthAcross(0.5 * target.mVehicleSize, target.mVehicleHeadingDegrees);
        result.mOverlap =
            SidewaysClearance(low, high, target.mVehicleOffset - other, target.mVehicleOffset + other);
        const double along =
            target.mVehicleSpeed * std::cos(target.mVehicleHeadingDegrees * std::numbers::pi / 180.0);
        result.mClosingPerStep = std::abs(impact.mSpeed - along) * inScenario.mTimeStep;
        break;
    }
    }
    return result;
}

std::string StepOverlapWarning(const CrashScenario& inScenario, const StepOverlap& inStep)
{
    if (!inStep.IsTooCoarse())
        return {};
    const double closing_speed = inStep.mClosingPerStep / inScenario.mTimeStep;
    char text[480];
    std::snprintf(
        text, sizeof(text),
        "the car closes %.3g m on the target per engine step (time_step_s %.3g s), more than the %.3g m "
        "it overlaps the target across its path: the engine may push it aside instead of stopping it "
        "(a glance, no crush); time_step_s %.2g s or less closes half the overlap per step",
        inStep.mClosingPerStep, inScenario.mTimeStep, inStep.mOverlap, 0.5 * inStep.mOverlap / closing_speed);
    return text;
}

} // namespace crumple::crash
