// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Math.h>

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

} // namespace crumple::common
