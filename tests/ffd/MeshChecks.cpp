// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "MeshChecks.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

namespace crumple::ffd::test
{

Vec3 AreaVector(const TriangleMesh& inMesh, const std::array<std::uint32_t, 3>& inTriangle)
{
    const Vec3& a = inMesh.mPositions[inTriangle[0]];
    return 0.5 * (inMesh.mPositions[inTriangle[1]] - a).cross(inMesh.mPositions[inTriangle[2]] - a);
}

double TotalArea(const TriangleMesh& inMesh)
{
    double area = 0.0;
    for (const auto& t : inMesh.mTriangles)
        area += AreaVector(inMesh, t).norm();
    return area;
}

bool IsClosedManifold(const TriangleMesh& inMesh)
{
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
    for (const auto& t : inMesh.mTriangles)
        for (int k = 0; k < 3; ++k)
            ++directed[{t[k], t[(k + 1) % 3]}];
    for (const auto& [edge, count] : directed)
        if (count != 1 || directed.count({edge.second, edge.first}) != 1 ||
            directed.at({edge.second, edge.first}) != 1)
            return false;
    return true;
}

int TurnedOver(const TriangleMesh& inRest, const TriangleMesh& inNow)
{
    int turned = 0;
    for (const auto& t : inRest.mTriangles)
        turned += AreaVector(inRest, t).dot(AreaVector(inNow, t)) < 0.0 ? 1 : 0;
    return turned;
}

AngleRange CornerAngleRange(const TriangleMesh& inMesh)
{
    AngleRange range{std::numbers::pi, 0.0};
    for (const auto& t : inMesh.mTriangles)
        for (int k = 0; k < 3; ++k)
        {
            const Vec3 u = inMesh.mPositions[t[(k + 1) % 3]] - inMesh.mPositions[t[k]];
            const Vec3 v = inMesh.mPositions[t[(k + 2) % 3]] - inMesh.mPositions[t[k]];
            const double angle = std::atan2(u.cross(v).norm(), u.dot(v));
            range.mSmallest = std::min(range.mSmallest, angle);
            range.mLargest = std::max(range.mLargest, angle);
        }
    return range;
}

TriangleMesh Pocket(const TriangleMesh& inMesh)
{
    TriangleMesh dented = inMesh;
    for (Vec3& p : dented.mPositions)
        p.x() -= 0.27 * std::exp(-(p.y() / 0.3) * (p.y() / 0.3));
    return dented;
}

} // namespace crumple::ffd::test
