// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/base/Assert.h>
#include <crumple/fem/TetFragment.h>

#include "UnionFindRoot.h"

#include <algorithm>
#include <numeric>

namespace crumple::fem
{

std::vector<TetFragment> TetFragments(const FractureLinks& inLinks, std::span<const TetIndices> inElementNodes,
                                      std::span<const double> inElementMasses, std::span<const Vec3> inPositions,
                                      std::span<const double> inInverseMasses)
{
    CRUMPLE_ASSERT(inElementMasses.size() == inElementNodes.size() && inInverseMasses.size() == inPositions.size() &&
                       std::all_of(inElementNodes.begin(), inElementNodes.end(),
                                   [&](const TetIndices& inNodes) {
                                       return std::all_of(inNodes.begin(), inNodes.end(), [&](int inNode) {
                                           return inNode >= 0 && static_cast<std::size_t>(inNode) < inPositions.size();
                                       });
                                   }),
                   "TetFragments: arrays of different sizes, or a node that is not there");
    // Elements joined through shared current nodes (fracture has duplicated the nodes of open cracks).
    std::vector<int> parent(inPositions.size());
    std::iota(parent.begin(), parent.end(), 0);
    for (const TetIndices& nodes : inElementNodes)
        for (int corner = 1; corner < 4; ++corner)
        {
            const int a = UnionFindRoot(parent, nodes[0]);
            const int b = UnionFindRoot(parent, nodes[corner]);
            parent[std::max(a, b)] = std::min(a, b);
        }

    // Fragment index per component, in order of lowest group (a group's elements always share nodes).
    const int group_count = inLinks.GetGroupCount();
    std::vector<int> fragment_of_root(inPositions.size(), -1), fragment_of_group(group_count, -1);
    std::vector<TetFragment> fragments;
    for (int group = 0; group < group_count; ++group)
    {
        const int first_element = inLinks.mGroupElements[inLinks.mGroupElementOffsets[group]];
        const int root = UnionFindRoot(parent, inElementNodes[first_element][0]);
        if (fragment_of_root[root] < 0)
        {
            fragment_of_root[root] = static_cast<int>(fragments.size());
            fragments.emplace_back();
        }
        fragment_of_group[group] = fragment_of_root[root];
        fragments[fragment_of_group[group]].mGroups.push_back(group);
    }

    // Mass, first and second moments per fragment, element by element (element order: deterministic sums).
    std::vector<Mat3> second_moments(fragments.size(), Mat3::Zero());
    for (std::size_t tet = 0; tet < inElementNodes.size(); ++tet)
    {
        TetFragment& fragment = fragments[fragment_of_group[inLinks.mGroupOfElement[tet]]];
        fragment.mElements.push_back(static_cast<int>(tet));
        const double mass = inElementMasses[tet];
        Vec3 sum = Vec3::Zero();
        Mat3 outer = Mat3::Zero();
        for (int node : inElementNodes[tet])
        {
            sum += inPositions[node];
            outer += inPositions[node] * inPositions[node].transpose();
        }
        fragment.mMass += mass;
        fragment.mCenterOfMass += 0.25 * mass * sum;
        second_moments[&fragment - fragments.data()] += mass / 20.0 * (outer + sum * sum.transpose());
    }

    // Node lists, each ascending and without repeats: the nodes of a piece's elements, gathered node by node
    // through each node's elements (linear; the sort of every element corner this replaces was most of this
    // function's time, the prop's main piece holding nearly every node). Not by union-find root: a group
    // whose elements share no node (a mesh may group them so) lies in two components, yet is one piece.
    std::vector<int> incident_offsets(inPositions.size() + 1, 0);
    for (const TetIndices& nodes : inElementNodes)
        for (int node : nodes)
            ++incident_offsets[static_cast<std::size_t>(node) + 1];
    for (std::size_t node = 0; node < inPositions.size(); ++node)
        incident_offsets[node + 1] += incident_offsets[node];
    std::vector<int> incident(static_cast<std::size_t>(incident_offsets.back()));
    std::vector<int> cursor(incident_offsets.begin(), incident_offsets.end() - 1);
    for (std::size_t tet = 0; tet < inElementNodes.size(); ++tet)
        for (int node : inElementNodes[tet])
            incident[static_cast<std::size_t>(cursor[static_cast<std::size_t>(node)]++)] = static_cast<int>(tet);
    for (std::size_t node = 0; node < inPositions.size(); ++node)
        for (int k = incident_offsets[node]; k < incident_offsets[node + 1]; ++k)
        {
            std::vector<int>& nodes = fragments[fragment_of_group[inLinks.mGroupOfElement[incident[static_cast<std::size_t>(k)]]]].mNodes;
            if (nodes.empty() || nodes.back() != static_cast<int>(node))
                nodes.push_back(static_cast<int>(node));
        }

    // Centre of mass, inertia about it, anchoring.
    for (std::size_t index = 0; index < fragments.size(); ++index)
    {
        TetFragment& fragment = fragments[index];
        fragment.mCenterOfMass /= fragment.mMass;
        const Mat3 central = second_moments[index] -
                             fragment.mMass * fragment.mCenterOfMass * fragment.mCenterOfMass.transpose();
        fragment.mInertia = central.trace() * Mat3::Identity() - central;
        fragment.mInertia = 0.5 * (fragment.mInertia + fragment.mInertia.transpose());
        fragment.mAnchored = std::any_of(fragment.mNodes.begin(), fragment.mNodes.end(),
                                         [&](int inNode) { return inInverseMasses[inNode] == 0.0; });
    }
    return fragments;
}

} // namespace crumple::fem
