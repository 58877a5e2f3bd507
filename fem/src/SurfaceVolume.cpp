// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/SurfaceVolume.h>

namespace crumple::fem
{

// Divergence theorem with F = x / 3: V = (1/3) sum_f integral x . n dA, and over a triangle x . n is constant
// (p0 . n), so each triangle adds (1/3) p0 . (p1 - p0) x (p2 - p0) / 2 = p0 . (p1 x p2) / 6.
double SurfaceVolume(std::span<const Vec3> inPositions, std::span<const TriangleIndices> inTriangles)
{
    double six_volume = 0.0;
    for (const TriangleIndices& corners : inTriangles)
        six_volume += inPositions[corners[0]].dot(inPositions[corners[1]].cross(inPositions[corners[2]]));
    return six_volume / 6.0;
}

} // namespace crumple::fem
