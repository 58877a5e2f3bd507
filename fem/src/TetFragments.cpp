// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
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

    // Node lists in ascending order, in one pass over the nodes (a node belongs to its component's fragment;
    // a node of no element has a component of its own, which no group named). Not sorted per fragment: the
    // prop's main piece holds nearly every node, and a sort of it was most of this function's time.
    for (std::size_t node = 0; node < inPositions.size(); ++node)
        if (const int fragment = fragment_of_root[UnionFindRoot(parent, static_cast<int>(node))]; fragment >= 0)
            fragments[fragment].mNodes.push_back(static_cast<int>(node));

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
