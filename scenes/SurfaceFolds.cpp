// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "SurfaceFolds.h"

namespace crumple::common
{

int FoldedVertices(std::span<const Vec3> inRestNormals, std::span<const Vec3> inNormals)
{
    int folded = 0;
    for (std::size_t vertex = 0; vertex < inNormals.size() && vertex < inRestNormals.size(); ++vertex)
        folded += inRestNormals[vertex].dot(inNormals[vertex]) < 0.0 ? 1 : 0;
    return folded;
}

int FoldedTriangles(const ffd::TriangleMesh& inRest, std::span<const Vec3> inPositions)
{
    int folded = 0;
    for (const auto& t : inRest.mTriangles)
    {
        const Vec3& a = inRest.mPositions[t[0]];
        const Vec3 rest = (inRest.mPositions[t[1]] - a).cross(inRest.mPositions[t[2]] - a);
        if (rest.isZero(0.0))
            continue;
        const Vec3& b = inPositions[t[0]];
        const Vec3 now = (inPositions[t[1]] - b).cross(inPositions[t[2]] - b);
        folded += rest.dot(now) < 0.0 ? 1 : 0;
    }
    return folded;
}

} // namespace crumple::common
