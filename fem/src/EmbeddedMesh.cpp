// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/BarycentricSearch.h>

#include <crumple/fem/EmbeddedMesh.h>

#include <algorithm>
#include <limits>
#include <sstream>
#include <utility>

namespace crumple::fem
{

Result<EmbeddedMesh> EmbeddedMesh::Create(const TetMesh& inMesh, std::span<const Vec3> inRestPositions,
                                          std::span<const int> inVertexGroups,
                                          std::vector<TriangleIndices> inTriangles)
{
    // Sizes first: everything below indexes with int.
    if (inRestPositions.size() != inVertexGroups.size())
        return MakeError(EError::InvalidArgument, "EmbeddedMesh: " + std::to_string(inRestPositions.size()) +
                                                      " vertex positions but " +
                                                      std::to_string(inVertexGroups.size()) + " group ids");
    if (inRestPositions.size() > static_cast<std::size_t>(TetMesh::cMaxCount) ||
        inTriangles.size() > static_cast<std::size_t>(TetMesh::cMaxCount))
        return MakeError(EError::InvalidArgument, "EmbeddedMesh: more than 2^26 vertices or triangles");
    const int vertex_count = static_cast<int>(inRestPositions.size());

    // Triangles name existing, distinct vertices.
    for (std::size_t triangle = 0; triangle < inTriangles.size(); ++triangle)
    {
        const TriangleIndices& corners = inTriangles[triangle];
        for (int corner = 0; corner < 3; ++corner)
        {
            if (corners[corner] < 0 || corners[corner] >= vertex_count)
                return MakeError(EError::OutOfRange, "EmbeddedMesh: triangle " + std::to_string(triangle) +
                                                         " names vertex " + std::to_string(corners[corner]) +
                                                         ", outside [0, " + std::to_string(vertex_count) +
                                                         ")");
            for (int other = 0; other < corner; ++other)
                if (corners[other] == corners[corner])
                    return MakeError(EError::DegenerateGeometry,
                                     "EmbeddedMesh: triangle " + std::to_string(triangle) + " uses vertex " +
                                         std::to_string(corners[corner]) + " twice");
        }
    }

    // Elements sorted by (group, element) so that each group's elements are one range, in element order.
    const std::vector<int>& groups = inMesh.GetGroups();
    std::vector<std::pair<int, int>> by_group;
    by_group.reserve(groups.size());
    for (int element = 0; element < inMesh.GetTetCount(); ++element)
        by_group.emplace_back(groups[element], element);
    std::sort(by_group.begin(), by_group.end());
    std::vector<int> sorted_elements(by_group.size());
    for (std::size_t entry = 0; entry < by_group.size(); ++entry)
        sorted_elements[entry] = by_group[entry].second;

    // Inverse edge matrices of the rest mesh; its elements are non-degenerate (TetMesh::Create checked it).
    Result<BarycentricSearch> made = BarycentricSearch::Create(inMesh.GetTets(), inMesh.GetRestPositions());
    if (!made)
        return made.GetError(); // cannot happen for a TetMesh: its indices were checked when it was made
    const BarycentricSearch& search = made.Get();

    EmbeddedMesh mesh;
    mesh.mVertices.resize(inRestPositions.size());
    for (int vertex = 0; vertex < vertex_count; ++vertex)
    {
        const Vec3& position = inRestPositions[vertex];
        if (!IsFinite(position))
            return MakeError(EError::NonFinite,
                             "EmbeddedMesh: vertex " + std::to_string(vertex) + " has a non-finite position");

        // The group's elements.
        const int group = inVertexGroups[vertex];
        const auto first = std::lower_bound(by_group.begin(), by_group.end(), std::make_pair(group, 0));
        if (first == by_group.end() || first->first != group)
            return MakeError(EError::OutOfRange, "EmbeddedMesh: vertex " + std::to_string(vertex) +
                                                     " follows group " + std::to_string(group) +
                                                     ", which no element belongs to");

        // Largest minimum weight wins; the group's elements are in index order, so ties keep the lowest.
        const auto last = std::partition_point(first, by_group.end(),
                                               [group](const std::pair<int, int>& inEntry)
                                               { return inEntry.first == group; });
        const std::span<const int> candidates(sorted_elements.data() + (first - by_group.begin()),
                                              static_cast<std::size_t>(last - first));
        const BarycentricHit hit = search.FindBest(candidates, position);
        EmbeddedVertex best;
        if (hit.mElement >= 0)
        {
            best.mElement = hit.mElement;
            best.mWeights = hit.mWeights;
        }
        const double best_min = hit.mMinWeight;
        if (!(best_min >= -cMaxExtrapolation))
        {
            std::ostringstream message;
            message << "EmbeddedMesh: vertex " << vertex << " at (" << position.x() << ", " << position.y()
                    << ", " << position.z() << ") m lies far outside group " << group << ": its best element "
                    << best.mElement << " has a barycentric weight " << best_min << " < -"
                    << cMaxExtrapolation << " (wrong group id?)";
            return MakeError(EError::InvalidArgument, message.str());
        }
        mesh.mVertices[vertex] = best;
    }

    mesh.mRestPositions.assign(inRestPositions.begin(), inRestPositions.end());
    mesh.mTriangles = std::move(inTriangles);
    mesh.mElementCount = inMesh.GetTetCount();
    return mesh;
}

Status EmbeddedMesh::Update(std::span<const TetIndices> inElementNodes, std::span<const Vec3> inNodePositions,
                            std::vector<Vec3>& outPositions) const
{
    outPositions.clear();

    // One connectivity entry per element of the bound mesh.
    if (inElementNodes.size() != static_cast<std::size_t>(mElementCount))
        return MakeError(EError::InvalidArgument,
                         "EmbeddedMesh::Update: " + std::to_string(inElementNodes.size()) +
                             " elements given, the mesh was bound to " + std::to_string(mElementCount));

    // Every node a vertex uses exists and is finite, checked before anything is written.
    const std::size_t node_count = inNodePositions.size();
    for (std::size_t vertex = 0; vertex < mVertices.size(); ++vertex)
    {
        const int element = mVertices[vertex].mElement;
        for (const int node : inElementNodes[element])
        {
            if (node < 0 || static_cast<std::size_t>(node) >= node_count)
                return MakeError(EError::OutOfRange, "EmbeddedMesh::Update: element " +
                                                         std::to_string(element) + " names node " +
                                                         std::to_string(node) + ", outside [0, " +
                                                         std::to_string(node_count) + ")");
            if (!IsFinite(inNodePositions[node]))
                return MakeError(EError::NonFinite, "EmbeddedMesh::Update: node " + std::to_string(node) +
                                                        " (of element " + std::to_string(element) +
                                                        ") has a non-finite position");
        }
    }

    // x = sum_i w_i x_i, always in corner order so the result is deterministic.
    outPositions.resize(mVertices.size());
    for (std::size_t vertex = 0; vertex < mVertices.size(); ++vertex)
    {
        const EmbeddedVertex& binding = mVertices[vertex];
        const TetIndices& corners = inElementNodes[binding.mElement];
        Vec3 position = binding.mWeights[0] * inNodePositions[corners[0]];
        for (int corner = 1; corner < 4; ++corner)
            position += binding.mWeights[corner] * inNodePositions[corners[corner]];
        outPositions[vertex] = position;
    }
    return Status::Ok();
}

double EmbeddedMesh::GetMinWeight() const
{
    double smallest = std::numeric_limits<double>::infinity();
    for (const EmbeddedVertex& vertex : mVertices)
        smallest = std::min(smallest, *std::min_element(vertex.mWeights.begin(), vertex.mWeights.end()));
    return smallest;
}

} // namespace crumple::fem
