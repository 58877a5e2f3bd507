// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Math.h>

namespace crumple::common
{

/// Three draws of inDraw as a vector, z drawn first, then y, then x. C++ leaves the order in which a call's
/// arguments are evaluated unspecified (gcc: right to left, clang: left to right), so Vec3(draw(), draw(),
/// draw()) gave the seeded tests other data under clang than under gcc. The tests were written and measured
/// with gcc's order, which this keeps on every compiler.
template <class Draw> Vec3 DrawVec3(Draw&& inDraw)
{
    const double z = inDraw();
    const double y = inDraw();
    const double x = inDraw();
    return Vec3(x, y, z);
}

} // namespace crumple::common
