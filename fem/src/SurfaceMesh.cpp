// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/SurfaceMesh.h>

#include <algorithm>
#include <limits>
#include <sstream>
#include <utility>

namespace crumple::fem
{

Status ValidateClosedSurface(const SurfaceMesh& inSurface)
{
    // Sizes: everything below indexes with int.
    if (inSurface.mTriangles.empty())
        return MakeError(EError::InvalidArgument, "surface has no triangles");
    if (inSurface.mPositions.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()) ||
        inSurface.mTriangles.size() > static_cast<std::size_t>(std::numeric_limits<int>::max() / 3))
        return MakeError(EError::InvalidArgument,
                         "surface has too many vertices or triangles for int indices");
    const int vertex_count = static_cast<int>(inSurface.mPositions.size());

    // Finite positions.
    for (int vertex = 0; vertex < vertex_count; ++vertex)
        if (!IsFinite(inSurface.mPositions[vertex]))
            return MakeError(EError::NonFinite,
                             "surface vertex " + std::to_string(vertex) + " has a non-finite position");

    // Indices in range and distinct within each triangle; collect the undirected edges.
    std::vector<std::pair<int, int>> edges;
    edges.reserve(3 * inSurface.mTriangles.size());
    for (std::size_t triangle = 0; triangle < inSurface.mTriangles.size(); ++triangle)
    {
        const TriangleIndices& corners = inSurface.mTriangles[triangle];
        for (int corner = 0; corner < 3; ++corner)
            if (corners[corner] < 0 || corners[corner] >= vertex_count)
                return MakeError(EError::OutOfRange, "surface triangle " + std::to_string(triangle) +
                                                         " names vertex " + std::to_string(corners[corner]) +
                                                         ", outside [0, " + std::to_string(vertex_count) +
                                                         ")");
        if (corners[0] == corners[1] || corners[1] == corners[2] || corners[2] == corners[0])
            return MakeError(EError::DegenerateGeometry,
                             "surface triangle " + std::to_string(triangle) + " uses a vertex twice");
        for (int corner = 0; corner < 3; ++corner)
        {
            const int a = corners[corner];
            const int b = corners[(corner + 1) % 3];
            edges.emplace_back(std::min(a, b), std::max(a, b));
        }
    }

    // Closed: each edge exactly twice. Sorting keeps the example edge deterministic (the smallest bad one).
    std::sort(edges.begin(), edges.end());
    std::size_t bad_count = 0;
    std::size_t edge_count = 0;
    std::pair<int, int> example{-1, -1};
    std::size_t example_uses = 0;
    for (std::size_t first = 0; first < edges.size();)
    {
        std::size_t last = first;
        while (last < edges.size() && edges[last] == edges[first])
            ++last;
        ++edge_count;
        if (last - first != 2)
        {
            if (bad_count == 0)
            {
                example = edges[first];
                example_uses = last - first;
            }
            ++bad_count;
        }
        first = last;
    }
    if (bad_count != 0)
    {
        const Vec3& a = inSurface.mPositions[example.first];
        const Vec3& b = inSurface.mPositions[example.second];
        std::ostringstream message;
        message << "surface is not closed: " << bad_count << " of " << edge_count
                << " edges are not used by exactly two triangles, e.g. the edge from (" << a.x() << ", "
                << a.y() << ", " << a.z() << ") to (" << b.x() << ", " << b.y() << ", " << b.z()
                << ") m, used by " << example_uses << (example_uses == 1 ? " triangle" : " triangles");
        return MakeError(EError::DegenerateGeometry, message.str());
    }
    return Status::Ok();
}

} // namespace crumple::fem
