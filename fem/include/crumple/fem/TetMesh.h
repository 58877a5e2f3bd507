// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Math.h>
#include <crumple/base/Result.h>

#include <array>
#include <vector>

namespace crumple::fem
{

/// The four node indices of a tetrahedron, ordered so that its signed volume (TetVolume) is positive.
using TetIndices = std::array<int, 4>;

/// A validated tetrahedral mesh in its rest state: node rest positions and element -> node connectivity.
/// Element and node order is the caller's and is kept: every solver loop runs in this order, so results are
/// deterministic. Each element may carry a group id (the cube it was cut from) so that fracture can later
/// detach whole groups (the paper's section IV.B breaks whole 5-tet cubes away).
class CRUMPLE_API TetMesh
{
public:
    /// Smallest accepted |volume| / (longest edge)^3; a regular tetrahedron has 0.118, a 5-tet cube's corner
    /// tetrahedron 0.059. Below this an element is a sliver whose stiffness would dwarf its mass.
    static constexpr double cMinVolumeRatio = 1.0e-6;
    /// Most nodes or elements a mesh may have (int indices, a guard against absurd allocations).
    static constexpr int cMaxCount = 1 << 26;

    /// Validates and builds a mesh. Refused with a message naming the element or node: fewer than 4 nodes or
    /// no element, non-finite positions, an index out of range or repeated within an element, an inverted
    /// element (negative signed volume: swap two indices), a degenerate one (|V| < cMinVolumeRatio l_max^3),
    /// a node that belongs to no element (it would have no mass), or group ids of the wrong count or
    /// negative.
    /// @param[in] inRestPositions  #N node positions (m), body frame
    /// @param[in] inTets           #T elements, 4 node indices each, positively oriented
    /// @param[in] inGroups         #T group ids >= 0, or empty for "each element its own group"
    static Result<TetMesh> Create(std::vector<Vec3> inRestPositions, std::vector<TetIndices> inTets,
                                  std::vector<int> inGroups = {});

    /// Number of nodes #N
    int GetNodeCount() const { return static_cast<int>(mRestPositions.size()); }
    /// Number of elements #T
    int GetTetCount() const { return static_cast<int>(mTets.size()); }
    /// Node rest positions (m), #N
    const std::vector<Vec3>& GetRestPositions() const { return mRestPositions; }
    /// Element -> node connectivity, #T
    const std::vector<TetIndices>& GetTets() const { return mTets; }
    /// Group id per element (the cube it belongs to), #T
    const std::vector<int>& GetGroups() const { return mGroups; }
    /// Rest volume of element inTet (m^3), > 0
    double GetRestVolume(int inTet) const;
    /// Sum of the rest volumes (m^3)
    double GetTotalVolume() const;

private:
    TetMesh() = default;

    std::vector<Vec3> mRestPositions;
    std::vector<TetIndices> mTets;
    std::vector<int> mGroups;
};

} // namespace crumple::fem
