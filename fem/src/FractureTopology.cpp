// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/FractureTopology.h>

#include "UnionFindRoot.h"

#include <algorithm>
#include <numeric>
#include <string>

namespace crumple::fem
{

Result<FractureConnectivity> FractureTopology(const TetMesh& inMesh, const FractureLinks& inLinks,
                                              std::span<const std::uint8_t> inBroken)
{
    const int node_count = inMesh.GetNodeCount();
    if (Status valid = ValidateFractureLinks(inLinks, static_cast<int>(inMesh.GetTets().size()), node_count); !valid)
        return MakeError(valid.GetError().mCode, "FractureTopology: " + valid.GetError().mMessage);
    if (inBroken.size() != static_cast<std::size_t>(inLinks.GetLinkCount()))
        return MakeError(EError::InvalidArgument, "FractureTopology: " + std::to_string(inBroken.size()) +
                                                      " broken flags for " + std::to_string(inLinks.GetLinkCount()) + " links");
    // intent: links that fit the arrays but not this mesh (a group missing from a node it touches) are refused
    // where they are read, before an index past a node's groups is used
    const auto not_of_mesh = [](const std::string& inWhere)
    { return MakeError(EError::InvalidArgument, "FractureTopology: the links are not this mesh's (" + inWhere + ")"); };
    FractureConnectivity result;
    result.mNodeOrigin.resize(node_count);
    std::iota(result.mNodeOrigin.begin(), result.mNodeOrigin.end(), 0);

    // Per rest node, the node index each touching group uses (CSR like mNodeGroups).
    std::vector<int> group_node(inLinks.mNodeGroups.size());
    std::vector<int> parent, cluster_node;
    for (int node = 0; node < node_count; ++node)
    {
        const int begin = inLinks.mNodeGroupOffsets[node];
        const int count = inLinks.mNodeGroupOffsets[node + 1] - begin;
        const std::span<const int> groups(inLinks.mNodeGroups.data() + begin, count);

        // Join the groups connected through this node by an unbroken link.
        parent.resize(count);
        std::iota(parent.begin(), parent.end(), 0);
        for (int entry = inLinks.mNodeLinkOffsets[node]; entry < inLinks.mNodeLinkOffsets[node + 1]; ++entry)
        {
            const int link = inLinks.mNodeLinks[entry];
            if (inBroken[link] != 0)
                continue;
            const auto a = std::lower_bound(groups.begin(), groups.end(), inLinks.mLinkGroups[link][0]);
            const auto b = std::lower_bound(groups.begin(), groups.end(), inLinks.mLinkGroups[link][1]);
            if (a == groups.end() || *a != inLinks.mLinkGroups[link][0] || b == groups.end() || *b != inLinks.mLinkGroups[link][1])
                return not_of_mesh("link " + std::to_string(link) + " at node " + std::to_string(node));
            const int root_a = UnionFindRoot(parent, static_cast<int>(a - groups.begin()));
            const int root_b = UnionFindRoot(parent, static_cast<int>(b - groups.begin()));
            // Keep the lower position as root, so a cluster's root is its lowest group.
            parent[std::max(root_a, root_b)] = std::min(root_a, root_b);
        }

        // Number the clusters: the first (lowest group) keeps the rest index, later ones are appended.
        cluster_node.assign(count, -1);
        for (int item = 0; item < count; ++item)
        {
            const int root = UnionFindRoot(parent, item);
            if (cluster_node[root] < 0)
            {
                if (root == 0)
                    cluster_node[root] = node;
                else
                {
                    cluster_node[root] = static_cast<int>(result.mNodeOrigin.size());
                    result.mNodeOrigin.push_back(node);
                }
            }
            group_node[begin + item] = cluster_node[root];
        }
    }

    // Each element corner takes the node of its group's cluster at that rest node.
    const std::vector<TetIndices>& tets = inMesh.GetTets();
    result.mElementNodes.resize(tets.size());
    for (std::size_t tet = 0; tet < tets.size(); ++tet)
    {
        const int group = inLinks.mGroupOfElement[tet];
        for (int corner = 0; corner < 4; ++corner)
        {
            const int node = tets[tet][corner];
            const int begin = inLinks.mNodeGroupOffsets[node];
            const auto first = inLinks.mNodeGroups.begin() + begin;
            const auto last = inLinks.mNodeGroups.begin() + inLinks.mNodeGroupOffsets[node + 1];
            const auto found = std::lower_bound(first, last, group);
            if (found == last || *found != group)
                return not_of_mesh("element " + std::to_string(tet) + " at node " + std::to_string(node));
            result.mElementNodes[tet][corner] = group_node[begin + (found - first)];
        }
    }
    return result;
}

} // namespace crumple::fem
