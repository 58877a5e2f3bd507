// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "BoxMesh.h"

#include <cmath>
#include <map>

namespace crumple::common
{

ffd::TriangleMesh MakeBoxMesh(const Vec3& inHalfExtents, const std::array<int, 3>& inSegments)
{
    ffd::TriangleMesh mesh;
    // Vertices are keyed by integer grid coordinates so faces share their edges.
    std::map<std::array<int, 3>, std::uint32_t> index_of;
    auto vertex = [&](std::array<int, 3> inGrid) {
        auto [it, inserted] = index_of.try_emplace(inGrid, static_cast<std::uint32_t>(mesh.mPositions.size()));
        if (inserted)
        {
            Vec3 p;
            for (int axis = 0; axis < 3; ++axis)
                p[axis] = inHalfExtents[axis] * (2.0 * inGrid[axis] / inSegments[axis] - 1.0);
            mesh.mPositions.push_back(p);
        }
        return it->second;
    };
    // Each face: fixed axis at 0 or max; (u, v) axes chosen so u x v points outwards.
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side)
        {
            const int u_axis = (axis + 1) % 3, v_axis = (axis + 2) % 3;
            for (int i = 0; i < inSegments[u_axis]; ++i)
                for (int j = 0; j < inSegments[v_axis]; ++j)
                {
                    std::array<std::uint32_t, 4> quad;
                    const int corners[4][2] = {{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}};
                    for (int c = 0; c < 4; ++c)
                    {
                        std::array<int, 3> grid{};
                        grid[axis] = side * inSegments[axis];
                        grid[u_axis] = corners[c][0];
                        grid[v_axis] = corners[c][1];
                        quad[c] = vertex(grid);
                    }
                    if (side == 1)
                    {
                        mesh.mTriangles.push_back({quad[0], quad[1], quad[2]});
                        mesh.mTriangles.push_back({quad[0], quad[2], quad[3]});
                    }
                    else
                    {
                        mesh.mTriangles.push_back({quad[0], quad[2], quad[1]});
                        mesh.mTriangles.push_back({quad[0], quad[3], quad[2]});
                    }
                }
        }
    return mesh;
}

std::array<int, 3> BoxSegmentsForTriangles(const Vec3& inHalfExtents, int inTriangles)
{
    // Area 8 (xy + yz + zx) covered by squares of side s, two triangles each: s = sqrt(2 area / triangles).
    const Vec3 size = 2.0 * inHalfExtents;
    const double area = 2.0 * (size.x() * size.y() + size.y() * size.z() + size.z() * size.x());
    const double side = std::sqrt(2.0 * area / inTriangles);
    std::array<int, 3> segments{};
    for (int axis = 0; axis < 3; ++axis)
        segments[axis] = std::max(1, static_cast<int>(std::lround(size[axis] / side)));
    return segments;
}

} // namespace crumple::common
