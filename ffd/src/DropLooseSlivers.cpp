// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/ffd/DropLooseSlivers.h>

#include "SeamTwins.h"
#include "SplitTriangle.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

namespace crumple::ffd
{

namespace
{

bool IsSliver(const std::vector<Vec3>& inPositions, const std::array<std::uint32_t, 3>& inTriangle)
{
    const Vec3 &a = inPositions[inTriangle[0]], &b = inPositions[inTriangle[1]],
               &c = inPositions[inTriangle[2]];
    const double longest = std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
    return (b - a).cross(c - a).norm() <= cSliverAreaRatio * longest;
}

} // namespace

Result<std::size_t> DropLooseSlivers(TriangleMesh& ioMesh)
{
    if (Status valid = ValidateTriangleMesh(ioMesh); valid.HasError())
        return valid.GetError();
    const std::vector<std::uint32_t> twins = SeamTwins(ioMesh.mPositions);
    // intent: how many triangles use each edge, its ends named by their seam twins (an edge whose two ends
    // are at one position is no edge, and is not counted)
    std::unordered_map<std::uint64_t, int> uses;
    uses.reserve(3 * ioMesh.mTriangles.size());
    for (const auto& triangle : ioMesh.mTriangles)
        for (int corner = 0; corner < 3; ++corner)
        {
            const std::uint32_t a = twins[triangle[corner]], b = twins[triangle[(corner + 1) % 3]];
            if (a != b)
                ++uses[UndirectedEdgeKey(a, b)];
        }
    std::vector<std::array<std::uint32_t, 3>> kept;
    kept.reserve(ioMesh.mTriangles.size());
    for (const auto& triangle : ioMesh.mTriangles)
    {
        bool bounds_something = !IsSliver(ioMesh.mPositions, triangle);
        for (int corner = 0; corner < 3 && !bounds_something; ++corner)
        {
            const std::uint32_t a = twins[triangle[corner]], b = twins[triangle[(corner + 1) % 3]];
            // intent: an edge it shares with exactly one other triangle: without it that edge would open
            bounds_something = a != b && uses[UndirectedEdgeKey(a, b)] == 2;
        }
        if (bounds_something)
            kept.push_back(triangle);
    }
    const std::size_t removed = ioMesh.mTriangles.size() - kept.size();
    ioMesh.mTriangles = std::move(kept);
    return removed;
}

} // namespace crumple::ffd
