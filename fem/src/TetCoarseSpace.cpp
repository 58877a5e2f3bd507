// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/TetCoarseSpace.h>

#include "TetRestSystemBlocks.h"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <string>

namespace crumple::fem
{

namespace
{

// Fewest free nodes whose rigid rotations a coarse space keeps: three could be collinear, four of a
// tetrahedron are not.
constexpr int cMinRotatingNodes = 4;

// Free-node neighbours over the elements' edges, ascending per node (CSR).
struct NodeNeighbours
{
    std::vector<int> mStart;
    std::vector<int> mNodes;
};

NodeNeighbours FreeNeighbours(std::span<const TetIndices> inElementNodes,
                              std::span<const double> inInverseMasses)
{
    const std::size_t node_count = inInverseMasses.size();
    NodeNeighbours neighbours;
    neighbours.mStart.assign(node_count + 1, 0);
    auto for_each_edge = [&](auto&& inVisit)
    {
        for (const TetIndices& tet : inElementNodes)
            for (int a = 0; a < 4; ++a)
                for (int b = 0; b < 4; ++b)
                    if (a != b && inInverseMasses[static_cast<std::size_t>(tet[a])] > 0.0 &&
                        inInverseMasses[static_cast<std::size_t>(tet[b])] > 0.0)
                        inVisit(static_cast<std::size_t>(tet[a]), tet[b]);
    };
    for_each_edge([&](std::size_t inNode, int) { ++neighbours.mStart[inNode + 1]; });
    for (std::size_t node = 0; node < node_count; ++node)
        neighbours.mStart[node + 1] += neighbours.mStart[node];
    std::vector<int> all(static_cast<std::size_t>(neighbours.mStart[node_count]));
    std::vector<int> fill(neighbours.mStart.begin(), neighbours.mStart.end() - 1);
    for_each_edge([&](std::size_t inNode, int inOther)
                  { all[static_cast<std::size_t>(fill[inNode]++)] = inOther; });
    // intent: sorted and made unique per node, compacted in place
    std::vector<int> start(node_count + 1, 0);
    std::size_t kept = 0;
    for (std::size_t node = 0; node < node_count; ++node)
    {
        const auto begin = all.begin() + neighbours.mStart[node],
                   end = all.begin() + neighbours.mStart[node + 1];
        std::sort(begin, end);
        const auto unique_end = std::unique(begin, end);
        for (auto it = begin; it != unique_end; ++it)
            all[kept++] = *it;
        start[node + 1] = static_cast<int>(kept);
    }
    all.resize(kept);
    neighbours.mStart = std::move(start);
    neighbours.mNodes = std::move(all);
    return neighbours;
}

// Free nodes grouped breadth-first into connected aggregates of inTarget nodes, the lowest unassigned node
// seeding the next; an aggregate of fewer than inTarget / 2 nodes then joins the aggregate of its first
// neighbour outside it (if any). Returns the aggregate count; outAggregate -1 for anchored nodes.
int Aggregate(const NodeNeighbours& inNeighbours, std::span<const double> inInverseMasses, int inTarget,
              std::vector<int>& outAggregate)
{
    const std::size_t node_count = inInverseMasses.size();
    outAggregate.assign(node_count, -1);
    std::vector<int> queue;
    std::vector<int> sizes;
    for (std::size_t seed = 0; seed < node_count; ++seed)
    {
        if (!(inInverseMasses[seed] > 0.0) || outAggregate[seed] >= 0)
            continue;
        const int id = static_cast<int>(sizes.size());
        queue.assign(1, static_cast<int>(seed));
        outAggregate[seed] = id;
        for (std::size_t head = 0; head < queue.size() && static_cast<int>(queue.size()) < inTarget; ++head)
        {
            const auto node = static_cast<std::size_t>(queue[head]);
            for (int n = inNeighbours.mStart[node];
                 n < inNeighbours.mStart[node + 1] && static_cast<int>(queue.size()) < inTarget; ++n)
            {
                const int other = inNeighbours.mNodes[static_cast<std::size_t>(n)];
                if (outAggregate[static_cast<std::size_t>(other)] < 0)
                {
                    outAggregate[static_cast<std::size_t>(other)] = id;
                    queue.push_back(other);
                }
            }
        }
        sizes.push_back(static_cast<int>(queue.size()));
    }

    // intent: small aggregates (the leftovers between grown ones) join a neighbour, in aggregate order
    std::vector<int> merged_into(sizes.size());
    for (std::size_t id = 0; id < sizes.size(); ++id)
        merged_into[id] = static_cast<int>(id);
    auto root = [&](int inId)
    {
        while (merged_into[static_cast<std::size_t>(inId)] != inId)
            inId = merged_into[static_cast<std::size_t>(inId)];
        return inId;
    };
    std::vector<std::vector<int>> members(sizes.size());
    for (std::size_t node = 0; node < node_count; ++node)
        if (outAggregate[node] >= 0)
            members[static_cast<std::size_t>(outAggregate[node])].push_back(static_cast<int>(node));
    for (std::size_t id = 0; id < sizes.size(); ++id)
    {
        if (2 * sizes[id] >= inTarget)
            continue;
        int into = -1;
        for (int node : members[id])
        {
            for (int n = inNeighbours.mStart[static_cast<std::size_t>(node)];
                 n < inNeighbours.mStart[static_cast<std::size_t>(node) + 1] && into < 0; ++n)
            {
                const int other = root(
                    outAggregate[static_cast<std::size_t>(inNeighbours.mNodes[static_cast<std::size_t>(n)])]);
                if (other != root(static_cast<int>(id)))
                    into = other;
            }
            if (into >= 0)
                break;
        }
        if (into < 0)
            continue;
        merged_into[id] = into;
        sizes[static_cast<std::size_t>(into)] += sizes[id];
    }

    // intent: aggregates renumbered in the order of their lowest node
    std::vector<int> number(sizes.size(), -1);
    int count = 0;
    for (std::size_t node = 0; node < node_count; ++node)
    {
        if (outAggregate[node] < 0)
            continue;
        const int id = root(outAggregate[node]);
        if (number[static_cast<std::size_t>(id)] < 0)
            number[static_cast<std::size_t>(id)] = count++;
        outAggregate[node] = number[static_cast<std::size_t>(id)];
    }
    return count;
}

// The node's 3 x 6 block of P: [I, -[d]x] (a rotation w moves it by w x d).
Eigen::Matrix<double, 3, 6> ModeBlock(const Vec3& inOffset)
{
    Eigen::Matrix<double, 3, 6> block = Eigen::Matrix<double, 3, 6>::Zero();
    block.leftCols<3>().setIdentity();
    block(0, 4) = inOffset.z();
    block(0, 5) = -inOffset.y();
    block(1, 3) = -inOffset.z();
    block(1, 5) = inOffset.x();
    block(2, 3) = inOffset.y();
    block(2, 4) = -inOffset.x();
    return block;
}

} // namespace

Result<TetCoarseSpace>
BuildTetCoarseSpace(std::span<const TetIndices> inElementNodes, std::span<const TetElementRest> inRest,
                    std::span<const Vec3> inRestPositions, std::span<const double> inMasses,
                    std::span<const double> inInverseMasses, const Matrix6& inMaterialMatrix,
                    double inMassScale, double inStiffnessScale, const TetCoarseSpaceSettings& inSettings,
                    std::span<const Quat> inFrames, std::span<const Vec3> inPositions)
{
    const std::size_t node_count = inRestPositions.size();
    if (inRest.size() != inElementNodes.size())
        return MakeError(EError::InvalidArgument, "BuildTetCoarseSpace: " + std::to_string(inRest.size()) +
                                                      " rest entries for " +
                                                      std::to_string(inElementNodes.size()) + " elements");
    if (inMasses.size() != node_count || inInverseMasses.size() != node_count)
        return MakeError(EError::InvalidArgument,
                         "BuildTetCoarseSpace: masses and inverse masses must have one entry per node (" +
                             std::to_string(node_count) + ")");
    for (std::size_t tet = 0; tet < inElementNodes.size(); ++tet)
        for (int node : inElementNodes[tet])
            if (node < 0 || static_cast<std::size_t>(node) >= node_count)
                return MakeError(EError::OutOfRange, "BuildTetCoarseSpace: element " + std::to_string(tet) +
                                                         " names node " + std::to_string(node) + " of " +
                                                         std::to_string(node_count));
    if ((!inFrames.empty() && inFrames.size() != inElementNodes.size()) ||
        (!inPositions.empty() && inPositions.size() != node_count))
        return MakeError(EError::InvalidArgument,
                         "BuildTetCoarseSpace: frames must be one per element and positions one "
                         "per node (or none)");
    for (const Quat& frame : inFrames)
        if (!frame.coeffs().allFinite())
            return MakeError(EError::InvalidArgument, "BuildTetCoarseSpace: a frame is not finite");
    for (const Vec3& position : inPositions)
        if (!position.allFinite())
            return MakeError(EError::InvalidArgument, "BuildTetCoarseSpace: a position is not finite");
    if (!(std::isfinite(inMassScale) && inMassScale > 0.0) ||
        !(std::isfinite(inStiffnessScale) && inStiffnessScale >= 0.0))
        return MakeError(EError::InvalidArgument,
                         "BuildTetCoarseSpace: the mass scale must be finite and > 0, the stiffness "
                         "scale finite and >= 0");
    if (inSettings.mMaxCoarseUnknowns < 6 || inSettings.mMinAggregateNodes < 1 ||
        inSettings.mMinAggregates < 1)
        return MakeError(EError::InvalidArgument, "TetCoarseSpaceSettings: mMaxCoarseUnknowns must be >= 6, "
                                                  "mMinAggregateNodes and mMinAggregates >= 1");
    int free_count = 0;
    for (std::size_t node = 0; node < node_count; ++node)
    {
        if (!inRestPositions[node].allFinite() || !std::isfinite(inMasses[node]) || !(inMasses[node] > 0.0) ||
            !std::isfinite(inInverseMasses[node]) || inInverseMasses[node] < 0.0)
            return MakeError(EError::InvalidArgument,
                             "BuildTetCoarseSpace: node " + std::to_string(node) +
                                 " has a non-finite rest position or a mass that is not positive");
        free_count += inInverseMasses[node] > 0.0 ? 1 : 0;
    }
    if (free_count == 0)
        return MakeError(EError::InvalidArgument, "BuildTetCoarseSpace: every node is anchored");

    // intent: aggregates grown until six unknowns each fit the limit
    TetCoarseSpace space;
    const NodeNeighbours neighbours = FreeNeighbours(inElementNodes, inInverseMasses);
    const int cap = inSettings.mMaxCoarseUnknowns / 6;
    int target = std::max(inSettings.mMinAggregateNodes, (free_count + cap - 1) / cap);
    int aggregates = Aggregate(neighbours, inInverseMasses, target, space.mNodeAggregate);
    while (aggregates > cap && target < free_count)
    {
        target = std::min(2 * target, free_count);
        aggregates = Aggregate(neighbours, inInverseMasses, target, space.mNodeAggregate);
    }
    // intent: more separate pieces than the limit has aggregates for (a shattered prop whose pieces stay in
    // it): no space, as for too few aggregates
    if (aggregates > cap || aggregates < inSettings.mMinAggregates)
    {
        space.mNodeAggregate.assign(node_count, -1);
        space.mNodeOffset.assign(node_count, Vec3::Zero());
        space.mAggregateStart.assign(1, 0);
        return space;
    }

    // intent: members (CSR, ascending), rest centres and offsets; an aggregate too small to rotate keeps zero
    // offsets
    space.mAggregateStart.assign(static_cast<std::size_t>(aggregates) + 1, 0);
    for (int aggregate : space.mNodeAggregate)
        if (aggregate >= 0)
            ++space.mAggregateStart[static_cast<std::size_t>(aggregate) + 1];
    for (std::size_t a = 0; a < static_cast<std::size_t>(aggregates); ++a)
        space.mAggregateStart[a + 1] += space.mAggregateStart[a];
    space.mAggregateNodes.resize(static_cast<std::size_t>(space.mAggregateStart.back()));
    std::vector<int> fill(space.mAggregateStart.begin(), space.mAggregateStart.end() - 1);
    std::vector<Vec3> centre(static_cast<std::size_t>(aggregates), Vec3::Zero());
    for (std::size_t node = 0; node < node_count; ++node)
        if (const int aggregate = space.mNodeAggregate[node]; aggregate >= 0)
        {
            space.mAggregateNodes[static_cast<std::size_t>(fill[static_cast<std::size_t>(aggregate)]++)] =
                static_cast<int>(node);
            centre[static_cast<std::size_t>(aggregate)] +=
                inPositions.empty() ? inRestPositions[node] : inPositions[node];
        }
    std::vector<std::uint8_t> rotates(static_cast<std::size_t>(aggregates), 0);
    for (std::size_t a = 0; a < static_cast<std::size_t>(aggregates); ++a)
    {
        const int members = space.mAggregateStart[a + 1] - space.mAggregateStart[a];
        centre[a] /= static_cast<double>(members);
        rotates[a] = members >= cMinRotatingNodes ? 1 : 0;
    }
    space.mNodeOffset.assign(node_count, Vec3::Zero());
    for (std::size_t node = 0; node < node_count; ++node)
        if (const int aggregate = space.mNodeAggregate[node];
            aggregate >= 0 && rotates[static_cast<std::size_t>(aggregate)] != 0)
            space.mNodeOffset[node] = (inPositions.empty() ? inRestPositions[node] : inPositions[node]) -
                                      centre[static_cast<std::size_t>(aggregate)];

    // intent: P^T A0 P from the rest system's blocks (each node pair's block once, lower triangle)
    std::vector<int> free_index(node_count, -1), node_of_free;
    node_of_free.reserve(static_cast<std::size_t>(free_count));
    for (std::size_t node = 0; node < node_count; ++node)
        if (inInverseMasses[node] > 0.0)
        {
            free_index[node] = static_cast<int>(node_of_free.size());
            node_of_free.push_back(static_cast<int>(node));
        }
    TetElementPassInput input;
    input.mTets = inElementNodes;
    input.mRest = inRest;
    input.mMaterialMatrix = &inMaterialMatrix;
    std::vector<NodeBlock> blocks;
    TetRestSystemBlocks(input, inMasses, free_index, inMassScale, inStiffnessScale, blocks, nullptr,
                        inFrames);
    const Eigen::Index unknowns = 6 * static_cast<Eigen::Index>(aggregates);
    Eigen::MatrixXd coarse = Eigen::MatrixXd::Zero(unknowns, unknowns);
    for (const NodeBlock& block : blocks)
    {
        const auto row_node = static_cast<std::size_t>(node_of_free[static_cast<std::size_t>(block.mRow)]);
        const auto column_node =
            static_cast<std::size_t>(node_of_free[static_cast<std::size_t>(block.mColumn)]);
        const Eigen::Index row = 6 * space.mNodeAggregate[row_node],
                           column = 6 * space.mNodeAggregate[column_node];
        const Eigen::Matrix<double, 3, 6> row_modes = ModeBlock(space.mNodeOffset[row_node]);
        const Eigen::Matrix<double, 3, 6> column_modes = ModeBlock(space.mNodeOffset[column_node]);
        const Eigen::Matrix<double, 6, 6> product = row_modes.transpose() * block.mBlock * column_modes;
        coarse.block<6, 6>(row, column) += product;
        if (block.mRow != block.mColumn)
            coarse.block<6, 6>(column, row) += product.transpose();
    }
    for (std::size_t a = 0; a < static_cast<std::size_t>(aggregates); ++a)
        if (rotates[a] == 0)
            coarse.block<3, 3>(6 * static_cast<Eigen::Index>(a) + 3, 6 * static_cast<Eigen::Index>(a) + 3)
                .setIdentity();

    const Eigen::LLT<Eigen::MatrixXd> factor(coarse);
    if (factor.info() != Eigen::Success)
        return MakeError(EError::InvalidArgument,
                         "BuildTetCoarseSpace: the coarse system is not positive definite (a "
                         "degenerate element or mass)");
    space.mInverse = factor.solve(Eigen::MatrixXd::Identity(unknowns, unknowns));
    if (!space.mInverse.allFinite())
        return MakeError(EError::InvalidArgument,
                         "BuildTetCoarseSpace: the coarse system could not be inverted");
    return space;
}

} // namespace crumple::fem
