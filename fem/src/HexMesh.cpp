// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "HexFormat.h"
#include "HexShape.h"

#include <crumple/fem/HexMesh.h>

#include <string>

namespace crumple::fem
{

namespace
{

std::string AxisName(int inAxis)
{
    return std::string(1, static_cast<char>('x' + inAxis));
}

} // namespace

Result<HexMesh> HexMesh::Create(const HexMeshSettings& inSettings)
{
    // Refuse sizes and counts that would make a node position non-finite or an allocation absurd.
    if (!IsFinite(inSettings.mOrigin) || !IsFinite(inSettings.mSize))
        return MakeError(EError::NonFinite, "HexMeshSettings: mOrigin and mSize must be finite");
    long long cell_total = 1;
    for (int axis = 0; axis < 3; ++axis)
    {
        if (!(inSettings.mSize[axis] > 0.0))
            return MakeError(EError::DegenerateGeometry, "HexMeshSettings.mSize." + AxisName(axis) + " = " +
                                                             HexFormat(inSettings.mSize[axis]) +
                                                             " m: the box must have a positive size");
        const int n = inSettings.mCellCount[axis];
        if (n < 1 || n > HexMeshSettings::cMaxCellsPerAxis)
            return MakeError(EError::InvalidArgument,
                             "HexMeshSettings.mCellCount." + AxisName(axis) + " = " + std::to_string(n) +
                                 ": need 1 to " + std::to_string(HexMeshSettings::cMaxCellsPerAxis) + " cells per axis");
        cell_total *= n;
    }
    if (cell_total > HexMeshSettings::cMaxCellTotal)
        return MakeError(EError::InvalidArgument, "HexMeshSettings.mCellCount: " + std::to_string(cell_total) +
                                                      " cells exceed the limit of " +
                                                      std::to_string(HexMeshSettings::cMaxCellTotal));

    // Nodes on the grid: x = origin + size * i / n, exact at both faces.
    const std::array<int, 3>& n = inSettings.mCellCount;
    HexNodeMatrix nodes((n[0] + 1) * (n[1] + 1) * (n[2] + 1), 3);
    for (int k = 0; k <= n[2]; ++k)
        for (int j = 0; j <= n[1]; ++j)
            for (int i = 0; i <= n[0]; ++i)
            {
                const int index = i + (n[0] + 1) * (j + (n[1] + 1) * k);
                const std::array<int, 3> ijk{{i, j, k}};
                for (int axis = 0; axis < 3; ++axis)
                    nodes(index, axis) = inSettings.mOrigin[axis] + inSettings.mSize[axis] * ijk[axis] / n[axis];
            }
    // intent: a finite size near the double range overflows size * i before the division
    if (!nodes.allFinite())
        return MakeError(EError::NonFinite, "HexMeshSettings: origin + size * i / n is not finite for every node "
                                            "(a size near the double range)");

    // Cells: corner c sits at grid offset ((c + 1) / 2 % 2, c / 2 % 2, c / 4), matching cHexCornerSigns.
    HexElementMatrix elements(n[0] * n[1] * n[2], 8);
    for (int k = 0; k < n[2]; ++k)
        for (int j = 0; j < n[1]; ++j)
            for (int i = 0; i < n[0]; ++i)
            {
                const int element = i + n[0] * (j + n[1] * k);
                for (int c = 0; c < 8; ++c)
                {
                    const int di = cHexCornerSigns[c][0] > 0.0 ? 1 : 0;
                    const int dj = cHexCornerSigns[c][1] > 0.0 ? 1 : 0;
                    const int dk = cHexCornerSigns[c][2] > 0.0 ? 1 : 0;
                    elements(element, c) = (i + di) + (n[0] + 1) * ((j + dj) + (n[1] + 1) * (k + dk));
                }
            }
    return HexMesh(std::move(nodes), std::move(elements), n);
}

Result<HexMesh> HexMesh::Create(HexNodeMatrix inNodes, HexElementMatrix inElements)
{
    // Sizes and finiteness first, so that no later check reads garbage.
    if (inElements.rows() < 1)
        return MakeError(EError::InvalidArgument, "HexMesh: the mesh has no elements");
    if (inNodes.rows() > cMaxNodeCount || inElements.rows() > cMaxElementCount)
        return MakeError(EError::InvalidArgument, "HexMesh: " + std::to_string(inNodes.rows()) + " nodes and " +
                                                      std::to_string(inElements.rows()) + " elements exceed the limits " +
                                                      std::to_string(cMaxNodeCount) + " and " +
                                                      std::to_string(cMaxElementCount));
    if (!IsFinite(inNodes))
        return MakeError(EError::NonFinite, "HexMesh: a node position is NaN or infinite");

    // Every element names 8 distinct existing nodes and maps the reference cube without inversion.
    const int node_count = static_cast<int>(inNodes.rows());
    for (int e = 0; e < inElements.rows(); ++e)
    {
        HexCornerMatrix corners;
        for (int c = 0; c < 8; ++c)
        {
            const int node = inElements(e, c);
            if (node < 0 || node >= node_count)
                return MakeError(EError::OutOfRange, "HexMesh: element " + std::to_string(e) + " corner " +
                                                         std::to_string(c) + " names node " + std::to_string(node) +
                                                         " of " + std::to_string(node_count));
            for (int d = 0; d < c; ++d)
                if (inElements(e, d) == node)
                    return MakeError(EError::DegenerateGeometry, "HexMesh: element " + std::to_string(e) +
                                                                     " names node " + std::to_string(node) + " twice");
            corners.row(c) = inNodes.row(node);
        }
        const double quality = HexJacobianQuality(corners);
        if (!(quality >= cHexMinJacobianRatio))
            return MakeError(EError::DegenerateGeometry,
                             "HexMesh: element " + std::to_string(e) + " is inverted, flat or twisted (Jacobian ratio " +
                                 HexFormat(quality) + " < " + HexFormat(cHexMinJacobianRatio) +
                                 "); check the corner order");
    }
    return HexMesh(std::move(inNodes), std::move(inElements), {{0, 0, 0}});
}

HexMesh::HexMesh(HexNodeMatrix inNodes, HexElementMatrix inElements, const std::array<int, 3>& inGridCellCount) :
    mNodes(std::move(inNodes)), mElements(std::move(inElements)), mGridCellCount(inGridCellCount)
{
}

HexCornerMatrix HexMesh::GetCorners(int inElement) const
{
    HexCornerMatrix corners;
    for (int c = 0; c < 8; ++c)
        corners.row(c) = mNodes.row(mElements(inElement, c));
    return corners;
}

} // namespace crumple::fem
