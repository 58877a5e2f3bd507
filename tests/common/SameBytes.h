// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Math.h>
#include <crumple/plugin/Collision.h>

#include <cstring>
#include <span>

namespace crumple::common
{

/// True when inA and inB hold the same vectors bit for bit (the determinism tests' comparison: -0.0 and +0.0
/// differ, NaNs of the same bits agree).
inline bool SameBytes(std::span<const Vec3> inA, std::span<const Vec3> inB)
{
    return inA.size() == inB.size() && std::memcmp(inA.data(), inB.data(), inA.size() * sizeof(Vec3)) == 0;
}

/// True when two collision contacts hold the same points, normal, impulses, approach speed and absorbed
/// energy bit for bit, and the same time.
inline bool SameContact(const plugin::CollisionContact& inA, const plugin::CollisionContact& inB)
{
    return std::memcmp(inA.mPointOnA.data(), inB.mPointOnA.data(), sizeof(Vec3)) == 0 &&
           std::memcmp(inA.mPointOnB.data(), inB.mPointOnB.data(), sizeof(Vec3)) == 0 &&
           std::memcmp(inA.mNormal.data(), inB.mNormal.data(), sizeof(Vec3)) == 0 &&
           std::memcmp(inA.mFrictionImpulse.data(), inB.mFrictionImpulse.data(), sizeof(Vec3)) == 0 &&
           std::memcmp(&inA.mImpulse, &inB.mImpulse, sizeof(double)) == 0 &&
           std::memcmp(&inA.mApproachSpeed, &inB.mApproachSpeed, sizeof(double)) == 0 &&
           std::memcmp(&inA.mAbsorbedEnergy, &inB.mAbsorbedEnergy, sizeof(double)) == 0 &&
           inA.mTime == inB.mTime;
}

} // namespace crumple::common
