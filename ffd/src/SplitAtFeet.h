// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/ffd/RefineLongEdges.h>
#include <crumple/ffd/TriangleMesh.h>

#include <array>
#include <functional>
#include <optional>

namespace crumple::ffd
{

/// A triangle as SplitAtFeet shows it to its selector: the corner facing its longest edge, and that corner's
/// foot on the edge.
struct FootOfLongestEdge
{
    std::array<Vec3, 3> mCorners; ///< The triangle's corners (m)
    int mCorner = 0;              ///< 0..2: the corner facing the longest edge (the largest angle)
    double mLength = 0.0;         ///< The longest edge's length L (m)
    double mFraction = 0.0;       ///< Where the foot lies along that edge from one of its ends, in (0, 1)
    double mHeight = 0.0;         ///< The corner's distance from the edge, its altitude h (m)
};

/// A triangle to split at the foot of its largest angle: how urgently (an edge two such triangles share is
/// split at the more urgent one's foot); no value: not split.
using FootSelector = std::function<std::optional<double>(const FootOfLongestEdge&)>;

/// SplitCaps' and SplitFlipProneTriangles' work: every triangle inSelect picks is split at the foot of its
/// largest angle on its longest edge, and every other triangle on that edge at the same point (seam sides by
/// position too, each with its own vertex), so the surface keeps its shape exactly and stays closed. An edge
/// is split once, at the foot of the most urgent triangle that picked it (the first in triangle order among
/// equals). Degenerate triangles (the corner on the edge to within 1e-9 of its length) are never shown to
/// inSelect. inName prefixes errors.
Result<RefinedMesh> SplitAtFeet(const TriangleMesh& inMesh, const FootSelector& inSelect, const char* inName);

} // namespace crumple::ffd
