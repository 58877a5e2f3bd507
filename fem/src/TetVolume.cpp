// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/TetVolume.h>

namespace crumple::fem
{

double TetVolume(const Vec3& inP0, const Vec3& inP1, const Vec3& inP2, const Vec3& inP3)
{
    // Triple product of the three edges from p0, written out so the operation order is fixed.
    const Vec3 a = inP1 - inP0;
    const Vec3 b = inP2 - inP0;
    const Vec3 c = inP3 - inP0;
    return a.dot(b.cross(c)) / 6.0;
}

} // namespace crumple::fem
