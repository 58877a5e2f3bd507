// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "TetGroundContact.h"

#include <algorithm>

namespace crumple::fem
{

namespace
{

// A node this close above the ground (m) still rests on it: a node put on the ground lands within round-off
// of the plane, on either side.
constexpr double cTouchDistance = 1.0e-9;

// Set into the ground as made (a footing): the ground does not hold it.
bool IsBelowAtRest(const GroundPlane& inGround, const Vec3& inRest)
{
    return inGround.mNormal.dot(inRest) < inGround.mOffset;
}

// Slows the tangential part of ioVelocity by inSlowing (m/s), at most to zero (Coulomb friction at velocity
// level).
void SlowTangentially(const Vec3& inNormal, double inSlowing, Vec3& ioVelocity)
{
    const Vec3 tangential = ioVelocity - inNormal.dot(ioVelocity) * inNormal;
    const double speed = tangential.norm();
    if (speed <= inSlowing)
        ioVelocity -= tangential;
    else
        ioVelocity -= (inSlowing / speed) * tangential;
}

} // namespace

int HoldGroundNodes(const GroundPlane& inGround, std::span<const std::uint8_t> inFree,
                    std::span<const Vec3> inRest, std::span<const Vec3> inStartPositions, double inDeltaTime,
                    std::span<std::uint8_t> outHeld, std::span<Vec3> ioVelocities)
{
    const Vec3& normal = inGround.mNormal;
    int held = 0;
    for (std::size_t node = 0; node < inStartPositions.size(); ++node)
    {
        outHeld[node] = 0;
        if (inFree[node] == 0 || IsBelowAtRest(inGround, inRest[node]))
            continue;
        const double height = normal.dot(inStartPositions[node]) - inGround.mOffset;
        if (height > cTouchDistance)
            continue;
        outHeld[node] = cHeldReleasable;
        ++held;
        // intent: a node below the ground (placed there) is stopped, not pushed out: a push would do work
        ioVelocities[node] +=
            (-std::max(height, 0.0) / inDeltaTime - normal.dot(ioVelocities[node])) * normal;
    }
    return held;
}

int HoldCrossingNodes(const GroundPlane& inGround, std::span<const std::uint8_t> inFree,
                      std::span<const Vec3> inRest, std::span<const Vec3> inStartPositions,
                      double inDeltaTime, std::span<std::uint8_t> ioHeld, std::span<Vec3> ioPositions,
                      std::span<Vec3> ioVelocities)
{
    const Vec3& normal = inGround.mNormal;
    int added = 0;
    for (std::size_t node = 0; node < ioPositions.size(); ++node)
    {
        if (ioHeld[node] != 0 || inFree[node] == 0 || IsBelowAtRest(inGround, inRest[node]) ||
            normal.dot(ioPositions[node]) >= inGround.mOffset - cTouchDistance)
            continue;
        ioHeld[node] = cHeldToStepEnd;
        ++added;
        const double height = normal.dot(inStartPositions[node]) - inGround.mOffset;
        ioVelocities[node] += (-height / inDeltaTime - normal.dot(ioVelocities[node])) * normal;
        ioPositions[node] = inStartPositions[node] + inDeltaTime * ioVelocities[node];
    }
    return added;
}

int ReleasePulledNodes(const Vec3& inNormal, std::span<const Vec3> inResidual, std::span<std::uint8_t> ioHeld)
{
    int released = 0;
    for (std::size_t node = 0; node < ioHeld.size(); ++node)
        if (ioHeld[node] == cHeldReleasable && inNormal.dot(inResidual[node]) > 0.0)
        {
            ioHeld[node] = 0;
            ++released;
        }
    return released;
}

void FilterGroundNormal(const Vec3& inNormal, std::span<const std::uint8_t> inHeld, std::span<Vec3> ioValues)
{
    for (std::size_t node = 0; node < inHeld.size(); ++node)
        if (inHeld[node] != 0)
            ioValues[node] -= inNormal.dot(ioValues[node]) * inNormal;
}

void TakeGroundImpulses(const Vec3& inNormal, std::span<const std::uint8_t> inHeld,
                        std::span<Vec3> ioResidual, std::span<double> outImpulses)
{
    for (std::size_t node = 0; node < inHeld.size(); ++node)
    {
        outImpulses[node] = 0.0;
        if (inHeld[node] == 0)
            continue;
        const double normal_part = inNormal.dot(ioResidual[node]);
        outImpulses[node] = -normal_part;
        ioResidual[node] -= normal_part * inNormal;
    }
}

bool FinishGroundStep(const GroundPlane& inGround, std::span<const std::uint8_t> inFree,
                      std::span<const Vec3> inRest, std::span<const std::uint8_t> inHeld,
                      std::span<const double> inImpulses, std::span<const double> inMasses,
                      std::span<const Vec3> inResidual, std::span<Vec3> ioPositions,
                      std::span<Vec3> ioVelocities)
{
    const Vec3& normal = inGround.mNormal;
    // The pushing nodes' impulses scaled to the net one (see the header): the held nodes' impulses less the
    // normal residual left at the others (zero once Newton has converged).
    double pushing = 0.0, net = 0.0;
    for (std::size_t node = 0; node < ioPositions.size(); ++node)
    {
        if (inFree[node] == 0)
            continue;
        if (inHeld[node] != 0)
        {
            pushing += std::max(inImpulses[node], 0.0);
            net += inImpulses[node];
        }
        else
            net -= normal.dot(inResidual[node]);
    }
    const double share = net > 0.0 ? std::min(1.0, net / pushing) : 0.0;
    bool changed = false;
    for (std::size_t node = 0; node < ioPositions.size(); ++node)
    {
        if (inFree[node] == 0)
            continue;
        if (inHeld[node] != 0)
        {
            // intent: the velocity only; the step's position stays the solve's (see the header)
            if (inImpulses[node] > 0.0 && inGround.mFriction > 0.0)
                SlowTangentially(normal, inGround.mFriction * share * inImpulses[node] / inMasses[node],
                                 ioVelocities[node]);
            continue;
        }
        const double depth = inGround.mOffset - normal.dot(ioPositions[node]);
        if (!(depth > 0.0) || IsBelowAtRest(inGround, inRest[node]))
            continue;
        ioPositions[node] += depth * normal;
        const double approach = normal.dot(ioVelocities[node]);
        if (approach < 0.0)
        {
            ioVelocities[node] -= approach * normal;
            SlowTangentially(normal, -inGround.mFriction * approach, ioVelocities[node]);
        }
        changed = true;
    }
    return changed;
}

} // namespace crumple::fem
