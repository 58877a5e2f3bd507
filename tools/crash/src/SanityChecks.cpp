// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/crash/SanityChecks.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

namespace crumple::crash
{

namespace
{

std::string Format(double inValue)
{
    char text[64];
    std::snprintf(text, sizeof(text), "%.4g", inValue);
    return text;
}

SanityResult NotApplicable(const char* inName, std::string inWhy)
{
    SanityResult result;
    result.mName = inName;
    result.mApplies = false;
    result.mDetail = std::move(inWhy);
    return result;
}

SanityResult NoTunnelling(const CrashScenario& inScenario, const CrashOutcome& inOutcome)
{
    const Vec3 end = inOutcome.mEndTransform.mTranslation;
    SanityResult result;
    result.mName = "no_tunnelling";
    if (inScenario.mTarget.mType == ETarget::RigidWall)
    {
        // The wall's face is the plane n . x = 0, n pointing into the wall (tests/common/engines).
        const double angle = inScenario.mTarget.mAngleDegrees * std::numbers::pi / 180.0;
        const Vec3 normal(std::cos(angle), std::sin(angle), 0.0);
        result.mValue = normal.dot(end);
        result.mLimit = 0.0;
        result.mPassed = result.mValue < 0.0;
        result.mDetail = "the car's centre ends " + Format(result.mValue) +
                         " m along the wall's normal from its face (< 0: on the approach side)";
        return result;
    }
    if (inScenario.mTarget.mType == ETarget::Pole)
    {
        // The pole stands at the origin; the car came along +x. Past it with the pole inside its width: through it.
        const double half_width = 0.5 * inScenario.mVehicle.mBoxSize.y();
        const bool beside = std::abs(end.y()) > half_width + inScenario.mTarget.mPoleRadius;
        result.mValue = end.x();
        result.mLimit = 0.0;
        result.mPassed = beside || result.mValue < 0.0;
        result.mDetail = "the car's centre ends at x = " + Format(end.x()) + " m, y = " + Format(end.y()) +
                         " m from the pole (x < 0, or beside it)";
        return result;
    }
    return NotApplicable("no_tunnelling", "an offset wall, a vehicle or a destructible barrier may be passed or pushed");
}

SanityResult EnergyBalance(const CrashScenario& inScenario, const CrashOutcome& inOutcome)
{
    if (inScenario.mTarget.mType == ETarget::Vehicle && inScenario.mTarget.mVehicleSpeed > 0.0)
        return NotApplicable("energy_balance", "a moving target vehicle can hand the car energy");
    SanityResult result;
    result.mName = "energy_balance";
    const double kinetic = 0.5 * inOutcome.mMass * inOutcome.mStartVelocity.squaredNorm();
    result.mValue = inOutcome.EnergyAbsorbed();
    result.mLimit = kinetic;
    // Round-off of the two squared speeds: a millionth of the kinetic energy.
    const double slack = 1.0e-6 * kinetic;
    result.mPassed = result.mValue >= -slack && result.mValue <= kinetic + slack;
    result.mDetail = "energy the car lost " + Format(result.mValue) + " J, within [0, " + Format(kinetic) +
                     " J] (its kinetic energy at the start)";
    return result;
}

// The car's velocity at the last sample at or before inTime (the first sample when none is).
Vec3 VelocityAt(const CrashOutcome& inOutcome, double inTime)
{
    Vec3 velocity = inOutcome.mHistory.front().mVelocity;
    for (const CarSample& sample : inOutcome.mHistory)
        if (sample.mTime <= inTime)
            velocity = sample.mVelocity;
    return velocity;
}

SanityResult ImpulseMomentum(const CrashScenario& inScenario, const CrashOutcome& inOutcome)
{
    if (inScenario.mTarget.mType == ETarget::FemBarrier)
        return NotApplicable("impulse_momentum", "the barrier coupling pushes the car outside the engine");
    SanityResult result;
    result.mName = "impulse_momentum";
    result.mLimit = inScenario.mImpulseTolerance;
    if (std::isnan(inOutcome.mImpactStartTime))
    {
        // No collision reached Crumple: the car may lose only what the ground's rolling resistance takes over
        // the run; the rest of its change, as a share of its start speed, must stay within the tolerance.
        // intent: the allowance, not a share: rolling resistance takes the same speed whatever the car's, so
        // a crawling car's share of it is large (2 km/h over 0.5 s: 13 %)
        const Vec3 start(inOutcome.mStartVelocity.x(), inOutcome.mStartVelocity.y(), 0.0);
        const Vec3 end(inOutcome.mEndVelocity.x(), inOutcome.mEndVelocity.y(), 0.0);
        const double duration = inOutcome.mHistory.back().mTime - inOutcome.mHistory.front().mTime;
        const double rolling = inOutcome.mGroundDeceleration * duration;
        const double change = (end - start).norm();
        result.mValue = start.norm() > 0.0 ? std::max(0.0, change - rolling) / start.norm() : 0.0;
        result.mPassed = result.mValue <= result.mLimit;
        result.mDetail =
            "no collision reached Crumple, and the car's horizontal velocity changed by " + Format(change) +
            " m/s, of which the ground's rolling resistance accounts for up to " + Format(rolling) +
            " m/s: " + Format(result.mValue) + " of its start speed unexplained";
        return result;
    }
    // One step before the first contact to one step after the last: the whole exchange, little else.
    const double step = inOutcome.mHistory[1].mTime - inOutcome.mHistory[0].mTime;
    const Vec3 change = inOutcome.mMass * (VelocityAt(inOutcome, inOutcome.mImpactEndTime + step) -
                                           VelocityAt(inOutcome, inOutcome.mImpactStartTime - step));
    const double impulse = inOutcome.mCarImpulse.norm();
    const double along = impulse > 0.0 ? change.dot(inOutcome.mCarImpulse / impulse) : change.norm();
    const double scale = std::max(impulse, change.norm());
    result.mValue = scale > 0.0 ? std::abs(along - impulse) / scale : 0.0;
    result.mPassed = result.mValue <= result.mLimit;
    result.mDetail = "Crumple's impulses on the car " + Format(impulse) + " N s, the car's momentum change along them " +
                     Format(along) + " N s over " + Format(inOutcome.mImpactStartTime) + "-" +
                     Format(inOutcome.mImpactEndTime) + " s: relative difference " + Format(result.mValue);
    return result;
}

SanityResult NoFoldedVertices(const CrashOutcome& inOutcome)
{
    SanityResult result;
    result.mName = "no_folded_vertices";
    result.mValue = inOutcome.mFoldedVertices;
    result.mLimit = 0.0;
    result.mPassed = inOutcome.mFoldedVertices == 0;
    result.mDetail = std::to_string(inOutcome.mFoldedVertices) + " vertex normals turned against their rest normal (" +
                     std::to_string(inOutcome.mFoldedTriangles) + " triangles turned over, reported only)";
    return result;
}

} // namespace

std::vector<SanityResult> CheckSanity(const CrashScenario& inScenario, const CrashOutcome& inOutcome)
{
    return {NoTunnelling(inScenario, inOutcome), EnergyBalance(inScenario, inOutcome),
            ImpulseMomentum(inScenario, inOutcome), NoFoldedVertices(inOutcome)};
}

bool AllSane(const std::vector<SanityResult>& inResults)
{
    return std::all_of(inResults.begin(), inResults.end(), [](const SanityResult& inResult) { return inResult.mPassed; });
}

} // namespace crumple::crash
