// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "SplitTriangle.h"

#include <crumple/ffd/RefineLongEdges.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <unordered_map>

namespace crumple::ffd
{

Result<RefinedMesh> RefineLongEdges(const TriangleMesh& inMesh, double inMaxEdge, std::size_t inMaxTriangles,
                                    double inMaxBend)
{
    if (!(inMaxBend >= 0.0 && inMaxBend <= std::numbers::pi))
        return MakeError(EError::InvalidArgument,
                         "RefineLongEdges: the largest bend must be in [0, pi] rad, not " +
                             std::to_string(inMaxBend));
    if (Status valid = ValidateTriangleMesh(inMesh); !valid)
        return valid.GetError();
    if (!std::isfinite(inMaxEdge) || !(inMaxEdge > 0.0))
        return MakeError(EError::InvalidArgument, "RefineLongEdges: the longest edge wanted must be finite and > 0 m, not " +
                                                      std::to_string(inMaxEdge));
    RefinedMesh refined;
    refined.mMesh = inMesh;
    std::vector<Vec3>& positions = refined.mMesh.mPositions;
    std::vector<std::array<std::uint32_t, 3>>& triangles = refined.mMesh.mTriangles;
    const double max_edge2 = inMaxEdge * inMaxEdge;
    std::unordered_map<std::uint64_t, std::uint32_t> midpoints;
    std::vector<std::array<std::uint32_t, 3>> cuts;
    std::vector<std::array<std::uint32_t, 3>> next;
    // With a bend limit, per edge: the normal of the first triangle met, whether every other one is within
    // inMaxBend of it (a triangle of zero area has no normal: its edges count as bent), and whether every
    // triangle using it may be cut: one whose long edges can all be cut. A triangle with a long edge kept
    // whole is left whole: cutting its other edges would fan out against that edge, pass after pass.
    struct EdgeBend
    {
        Vec3 mNormal;
        bool mFlat = true;
        bool mCuttable = true;
    };
    const bool any_bend = inMaxBend >= std::numbers::pi;
    const double min_cosine = std::cos(inMaxBend);
    std::unordered_map<std::uint64_t, std::uint32_t> edge_ids; // undirected edge -> index into bends
    std::vector<EdgeBend> bends;
    std::vector<std::array<std::uint32_t, 3>> triangle_edges; // per triangle: its edges k = (v[k], v[k+1])
    std::vector<std::uint8_t> long_edges;                     // per triangle: bit k set when edge k is long
    std::vector<std::uint32_t> edge_start, edge_triangles;    // per edge: the triangles using it (CSR)
    std::vector<std::uint8_t> kept_whole;                     // per triangle: found not cuttable
    std::vector<std::uint32_t> edge_fill;                     // per edge: where its next triangle goes
    std::vector<std::uint32_t> pending;                       // triangles to look at again
    // intent: each pass at least halves every edge longer than inMaxEdge; the new edges inside a triangle are
    // no longer than its longest, so a mesh of edges up to L needs about log2(L / inMaxEdge) passes
    for (;;)
    {
        midpoints.clear();
        cuts.assign(triangles.size(), {cNoSplit, cNoSplit, cNoSplit});
        long_edges.assign(triangles.size(), 0);
        for (std::size_t t = 0; t < triangles.size(); ++t)
            for (int k = 0; k < 3; ++k)
                if ((positions[triangles[t][k]] - positions[triangles[t][(k + 1) % 3]]).squaredNorm() >
                    max_edge2)
                    long_edges[t] = static_cast<std::uint8_t>(long_edges[t] | (1u << k));
        if (!any_bend)
        {
            edge_ids.clear();
            bends.clear();
            triangle_edges.resize(triangles.size());
            for (std::size_t t = 0; t < triangles.size(); ++t)
            {
                const std::array<std::uint32_t, 3>& tri = triangles[t];
                const Vec3 area =
                    (positions[tri[1]] - positions[tri[0]]).cross(positions[tri[2]] - positions[tri[0]]);
                const bool has_normal = area.squaredNorm() > 0.0;
                const Vec3 normal = has_normal ? Vec3(area.normalized()) : Vec3::Zero();
                for (int k = 0; k < 3; ++k)
                {
                    const auto [it, first] = edge_ids.try_emplace(UndirectedEdgeKey(tri[k], tri[(k + 1) % 3]),
                                                                  static_cast<std::uint32_t>(bends.size()));
                    if (first)
                        bends.push_back(EdgeBend{normal, has_normal, true});
                    else
                    {
                        EdgeBend& bend = bends[it->second];
                        bend.mFlat = bend.mFlat && has_normal && bend.mNormal.dot(normal) >= min_cosine;
                    }
                    triangle_edges[t][static_cast<std::size_t>(k)] = it->second;
                }
            }
            // intent: the triangles of each edge, for the fixed point below
            edge_start.assign(bends.size() + 1, 0);
            for (const std::array<std::uint32_t, 3>& edges : triangle_edges)
                for (std::uint32_t e : edges)
                    ++edge_start[e + 1];
            for (std::size_t e = 0; e < bends.size(); ++e)
                edge_start[e + 1] += edge_start[e];
            edge_triangles.resize(edge_start.back());
            edge_fill.assign(edge_start.begin(), edge_start.end() - 1);
            for (std::size_t t = 0; t < triangles.size(); ++t)
                for (std::uint32_t e : triangle_edges[t])
                    edge_triangles[edge_fill[e]++] = static_cast<std::uint32_t>(t);

            // intent: a triangle is cut only if every long edge of it is, to the fixed point: one left whole
            // keeps its edges whole for its neighbours too. The kept-whole set is the least one closed under
            // that rule, whatever the order it is found in: each triangle is looked at once, and again only
            // when one of its edges is newly kept whole (instead of passes over every triangle until none
            // changes, which the Toy Car's 89k triangles needed a second for).
            kept_whole.assign(triangles.size(), 0);
            pending.clear();
            const auto look_at = [&](std::uint32_t inTriangle)
            {
                if (kept_whole[inTriangle] != 0)
                    return;
                bool cuttable = true;
                for (int k = 0; k < 3; ++k)
                {
                    const EdgeBend& bend = bends[triangle_edges[inTriangle][static_cast<std::size_t>(k)]];
                    const bool long_edge = (long_edges[inTriangle] >> k & 1u) != 0;
                    cuttable = cuttable && (!long_edge || (bend.mFlat && bend.mCuttable));
                }
                if (cuttable)
                    return;
                kept_whole[inTriangle] = 1;
                for (std::uint32_t e : triangle_edges[inTriangle])
                {
                    if (!bends[e].mCuttable)
                        continue;
                    bends[e].mCuttable = false;
                    for (std::uint32_t i = edge_start[e]; i < edge_start[e + 1]; ++i)
                        pending.push_back(edge_triangles[i]);
                }
            };
            for (std::size_t t = 0; t < triangles.size(); ++t)
            {
                look_at(static_cast<std::uint32_t>(t));
                while (!pending.empty())
                {
                    const std::uint32_t next_look = pending.back();
                    pending.pop_back();
                    look_at(next_look);
                }
            }
        }
        for (std::size_t t = 0; t < triangles.size(); ++t)
            for (int k = 0; k < 3; ++k)
            {
                const std::uint32_t a = triangles[t][k], b = triangles[t][(k + 1) % 3];
                if ((long_edges[t] >> k & 1u) == 0)
                    continue;
                if (!any_bend)
                    if (const EdgeBend& bend = bends[triangle_edges[t][static_cast<std::size_t>(k)]];
                        !bend.mFlat || !bend.mCuttable)
                        continue;
                const auto [it, added] = midpoints.try_emplace(UndirectedEdgeKey(a, b), static_cast<std::uint32_t>(positions.size()));
                if (added)
                {
                    if (positions.size() >= 0xFFFFFFFEu)
                        return MakeError(EError::OutOfRange, "RefineLongEdges: the refined mesh would have more than 2^32 - 2 vertices");
                    // (a + b) / 2 is the same whichever way round: the two sides of a seam get the same point
                    const Vec3 midpoint = 0.5 * (positions[a] + positions[b]);
                    positions.push_back(midpoint);
                    refined.mSplitParents.push_back({std::min(a, b), std::max(a, b)});
                    refined.mSplitFractions.push_back(0.5);
                }
                cuts[t][k] = it->second;
            }
        if (midpoints.empty())
            return refined;
        next.clear();
        next.reserve(triangles.size() * 2);
        for (std::size_t t = 0; t < triangles.size(); ++t)
        {
            SplitTriangle(triangles[t], cuts[t], positions, next);
            if (next.size() > inMaxTriangles)
                return MakeError(EError::OutOfRange, "RefineLongEdges: edges of at most " + std::to_string(inMaxEdge) +
                                                         " m need more than " + std::to_string(inMaxTriangles) +
                                                         " triangles; ask for longer edges or a higher limit");
        }
        triangles.swap(next);
    }
}

} // namespace crumple::ffd
