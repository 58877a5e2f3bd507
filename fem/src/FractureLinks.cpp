// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "TetFaceCorners.h"

#include <crumple/fem/FractureLinks.h>

#include <algorithm>
#include <map>
#include <string>
#include <tuple>

namespace crumple::fem
{

namespace
{

// An element face keyed by its sorted rest nodes.
struct FaceKey
{
    std::array<int, 3> mNodes;
    bool operator<(const FaceKey& inOther) const { return mNodes < inOther.mNodes; }
};

struct FaceUse
{
    int mElement;
    std::uint8_t mFace;
};

// Fills a CSR offsets array from per-row counts.
std::vector<int> Offsets(const std::vector<int>& inCounts)
{
    std::vector<int> offsets(inCounts.size() + 1, 0);
    for (std::size_t row = 0; row < inCounts.size(); ++row)
        offsets[row + 1] = offsets[row] + inCounts[row];
    return offsets;
}

} // namespace

FractureLinks BuildFractureLinks(const TetMesh& inMesh)
{
    FractureLinks links;
    const std::vector<TetIndices>& tets = inMesh.GetTets();
    const std::vector<Vec3>& rest = inMesh.GetRestPositions();
    const int tet_count = inMesh.GetTetCount();
    const int node_count = inMesh.GetNodeCount();

    // Dense group numbering in the order of the mesh's ids.
    links.mGroupIds = inMesh.GetGroups();
    std::sort(links.mGroupIds.begin(), links.mGroupIds.end());
    links.mGroupIds.erase(std::unique(links.mGroupIds.begin(), links.mGroupIds.end()), links.mGroupIds.end());
    links.mGroupOfElement.resize(tet_count);
    std::vector<int> group_counts(links.mGroupIds.size(), 0);
    for (int tet = 0; tet < tet_count; ++tet)
    {
        const auto it = std::lower_bound(links.mGroupIds.begin(), links.mGroupIds.end(), inMesh.GetGroups()[tet]);
        links.mGroupOfElement[tet] = static_cast<int>(it - links.mGroupIds.begin());
        ++group_counts[links.mGroupOfElement[tet]];
    }
    links.mGroupElementOffsets = Offsets(group_counts);
    links.mGroupElements.resize(tet_count);
    std::vector<int> cursor(links.mGroupElementOffsets.begin(), links.mGroupElementOffsets.end() - 1);
    for (int tet = 0; tet < tet_count; ++tet)
        links.mGroupElements[cursor[links.mGroupOfElement[tet]]++] = tet;

    // Faces used by elements of two different groups are the shared faces; collect them per group pair.
    std::map<FaceKey, std::vector<FaceUse>> faces;
    for (int tet = 0; tet < tet_count; ++tet)
        for (std::uint8_t face = 0; face < 4; ++face)
        {
            FaceKey key;
            for (int corner = 0; corner < 3; ++corner)
                key.mNodes[corner] = tets[tet][cTetFaceCorners[face][corner]];
            std::sort(key.mNodes.begin(), key.mNodes.end());
            faces[key].push_back({tet, face});
        }
    std::map<std::array<int, 2>, std::vector<FractureLinkFace>> pair_faces;
    for (const auto& [key, uses] : faces)
    {
        if (uses.size() != 2)
            continue; // a boundary face (or a non-manifold one, which conforming meshes do not have)
        int group_a = links.mGroupOfElement[uses[0].mElement];
        int group_b = links.mGroupOfElement[uses[1].mElement];
        if (group_a == group_b)
            continue;
        const FaceUse& use_a = group_a < group_b ? uses[0] : uses[1];
        pair_faces[{std::min(group_a, group_b), std::max(group_a, group_b)}].push_back(
            {use_a.mElement, cTetFaceCorners[use_a.mFace]});
    }

    // One link per group pair: its faces, rest normal (area-weighted, A to B) and shared nodes.
    std::vector<std::vector<int>> node_links(node_count);
    std::vector<int> face_counts, node_counts;
    for (const auto& [groups, link_faces] : pair_faces)
    {
        const int link = static_cast<int>(links.mLinkGroups.size());
        links.mLinkGroups.push_back(groups);
        Vec3 normal = Vec3::Zero();
        std::vector<int> shared;
        for (const FractureLinkFace& face : link_faces)
        {
            const TetIndices& element = tets[face.mElement];
            const Vec3& x0 = rest[element[face.mCorners[0]]];
            normal += (rest[element[face.mCorners[1]]] - x0).cross(rest[element[face.mCorners[2]]] - x0);
            for (std::uint8_t corner : face.mCorners)
                shared.push_back(element[corner]);
            links.mLinkFaces.push_back(face);
        }
        links.mLinkRestNormals.push_back(normal.normalized());
        std::sort(shared.begin(), shared.end());
        shared.erase(std::unique(shared.begin(), shared.end()), shared.end());
        for (int node : shared)
        {
            links.mLinkNodes.push_back(node);
            node_links[node].push_back(link);
        }
        face_counts.push_back(static_cast<int>(link_faces.size()));
        node_counts.push_back(static_cast<int>(shared.size()));
    }
    links.mLinkFaceOffsets = Offsets(face_counts);
    links.mLinkNodeOffsets = Offsets(node_counts);

    // Per rest node: the groups touching it and the links through it, both ascending.
    std::vector<std::vector<int>> node_groups(node_count);
    for (int tet = 0; tet < tet_count; ++tet)
        for (int node : tets[tet])
            node_groups[node].push_back(links.mGroupOfElement[tet]);
    std::vector<int> group_node_counts(node_count), link_node_counts(node_count);
    for (int node = 0; node < node_count; ++node)
    {
        std::vector<int>& groups = node_groups[node];
        std::sort(groups.begin(), groups.end());
        groups.erase(std::unique(groups.begin(), groups.end()), groups.end());
        group_node_counts[node] = static_cast<int>(groups.size());
        link_node_counts[node] = static_cast<int>(node_links[node].size()); // ascending by construction
    }
    links.mNodeGroupOffsets = Offsets(group_node_counts);
    links.mNodeLinkOffsets = Offsets(link_node_counts);
    for (int node = 0; node < node_count; ++node)
    {
        links.mNodeGroups.insert(links.mNodeGroups.end(), node_groups[node].begin(), node_groups[node].end());
        links.mNodeLinks.insert(links.mNodeLinks.end(), node_links[node].begin(), node_links[node].end());
    }
    return links;
}

namespace
{

// An offset table of inRows + 1 entries, from 0, ascending, ending at inSize.
bool ValidOffsets(const std::vector<int>& inOffsets, std::size_t inRows, std::size_t inSize)
{
    if (inOffsets.size() != inRows + 1 || inOffsets.front() != 0 || static_cast<std::size_t>(inOffsets.back()) != inSize)
        return false;
    for (std::size_t row = 0; row < inRows; ++row)
        if (inOffsets[row] > inOffsets[row + 1])
            return false;
    return true;
}

// Every value in [0, inCount).
bool InRange(const std::vector<int>& inValues, int inCount)
{
    return std::all_of(inValues.begin(), inValues.end(), [inCount](int inValue) { return inValue >= 0 && inValue < inCount; });
}

// Each row's values strictly ascending (what FractureTopology's binary searches need).
bool RowsAscending(const std::vector<int>& inOffsets, const std::vector<int>& inValues)
{
    for (std::size_t row = 0; row + 1 < inOffsets.size(); ++row)
        for (int entry = inOffsets[row] + 1; entry < inOffsets[row + 1]; ++entry)
            if (!(inValues[static_cast<std::size_t>(entry) - 1] < inValues[static_cast<std::size_t>(entry)]))
                return false;
    return true;
}

} // namespace

Status ValidateFractureLinks(const FractureLinks& inLinks, int inElementCount, int inNodeCount)
{
    const auto bad = [](const std::string& inWhat) { return MakeError(EError::InvalidArgument, "FractureLinks: " + inWhat); };
    if (inElementCount < 0 || inNodeCount < 0)
        return bad("negative element or node count");
    const int groups = inLinks.GetGroupCount(), links = inLinks.GetLinkCount();
    const auto elements = static_cast<std::size_t>(inElementCount), nodes = static_cast<std::size_t>(inNodeCount);
    if (inLinks.mGroupOfElement.size() != elements || !InRange(inLinks.mGroupOfElement, groups))
        return bad("mGroupOfElement must give each of the " + std::to_string(inElementCount) + " elements a group in [0, " +
                   std::to_string(groups) + ")");
    if (!ValidOffsets(inLinks.mGroupElementOffsets, static_cast<std::size_t>(groups), inLinks.mGroupElements.size()) ||
        !InRange(inLinks.mGroupElements, inElementCount))
        return bad("mGroupElementOffsets / mGroupElements do not list elements by group");
    for (const std::array<int, 2>& pair : inLinks.mLinkGroups)
        if (pair[0] < 0 || pair[0] >= groups || pair[1] < 0 || pair[1] >= groups)
            return bad("mLinkGroups names a group outside [0, " + std::to_string(groups) + ")");
    if (inLinks.mLinkRestNormals.size() != static_cast<std::size_t>(links))
        return bad("mLinkRestNormals must have one normal per link");
    if (!ValidOffsets(inLinks.mLinkFaceOffsets, static_cast<std::size_t>(links), inLinks.mLinkFaces.size()))
        return bad("mLinkFaceOffsets do not index mLinkFaces");
    for (const FractureLinkFace& face : inLinks.mLinkFaces)
        if (face.mElement < 0 || face.mElement >= inElementCount || face.mCorners[0] > 3 || face.mCorners[1] > 3 ||
            face.mCorners[2] > 3)
            return bad("mLinkFaces names an element or corner slot out of range");
    if (!ValidOffsets(inLinks.mLinkNodeOffsets, static_cast<std::size_t>(links), inLinks.mLinkNodes.size()) ||
        !InRange(inLinks.mLinkNodes, inNodeCount))
        return bad("mLinkNodeOffsets / mLinkNodes do not list rest nodes by link");
    if (!ValidOffsets(inLinks.mNodeGroupOffsets, nodes, inLinks.mNodeGroups.size()) || !InRange(inLinks.mNodeGroups, groups) ||
        !RowsAscending(inLinks.mNodeGroupOffsets, inLinks.mNodeGroups))
        return bad("mNodeGroupOffsets / mNodeGroups do not list groups by node, ascending, for " + std::to_string(inNodeCount) +
                   " nodes");
    if (!ValidOffsets(inLinks.mNodeLinkOffsets, nodes, inLinks.mNodeLinks.size()) || !InRange(inLinks.mNodeLinks, links))
        return bad("mNodeLinkOffsets / mNodeLinks do not list links by node for " + std::to_string(inNodeCount) + " nodes");
    return Status::Ok();
}

} // namespace crumple::fem
