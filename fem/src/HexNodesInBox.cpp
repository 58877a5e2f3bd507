// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/HexNodesInBox.h>

namespace crumple::fem
{

std::vector<int> HexNodesInBox(const HexMesh& inMesh, const Vec3& inMin, const Vec3& inMax)
{
    // Comparisons written so that a NaN bound is false for every node.
    std::vector<int> nodes;
    const HexNodeMatrix& positions = inMesh.GetNodes();
    for (int n = 0; n < inMesh.GetNodeCount(); ++n)
    {
        bool inside = true;
        for (int axis = 0; axis < 3; ++axis)
            inside = inside && positions(n, axis) >= inMin[axis] && positions(n, axis) <= inMax[axis];
        if (inside)
            nodes.push_back(n);
    }
    return nodes;
}

} // namespace crumple::fem
