// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Result.h>
#include <crumple/fem/HexMeshSettings.h>

#include <Eigen/Core>

#include <array>

namespace crumple::fem
{

/// Node positions of a hexahedral mesh: #nodes by 3, one row (x, y, z) per node, body frame (m).
using HexNodeMatrix = Eigen::Matrix<double, Eigen::Dynamic, 3>;
/// Element connectivity: #elements by 8 node indices (row-major), in the corner order documented on HexMesh.
using HexElementMatrix = Eigen::Matrix<int, Eigen::Dynamic, 8, Eigen::RowMajor>;
/// The 8 corner positions of one element: 8 by 3 (m), rows in the corner order documented on HexMesh.
using HexCornerMatrix = Eigen::Matrix<double, 8, 3>;

/// Smallest accepted Jacobian determinant of an element at its 8 Gauss points and its centre, relative to
/// (longest edge / 2)^3 (the value of a cube is 1). Flatter, inverted or self-intersecting elements are refused
/// as EError::DegenerateGeometry: their stiffness would be singular or indefinite.
constexpr double cHexMinJacobianRatio = 1.0e-6;

/// A mesh of trilinear hexahedra (8-node bricks).
///
/// Corner order of an element (VTK_HEXAHEDRON, Abaqus C3D8), with natural coordinates (xi, eta, zeta) in
/// [-1, 1]^3: 0 (-,-,-), 1 (+,-,-), 2 (+,+,-), 3 (-,+,-), 4 (-,-,+), 5 (+,-,+), 6 (+,+,+), 7 (-,+,+); i.e. the
/// face zeta = -1 counter-clockwise seen from +zeta, then the face zeta = +1 in the same order. Every element
/// must map [-1, 1]^3 onto its volume with a positive Jacobian (right-handed, not inverted).
///
/// A structured mesh (from HexMeshSettings) numbers node (i, j, k), 0 <= i <= nx, as i + (nx + 1) (j + (ny + 1) k)
/// and cell (i, j, k) as i + nx (j + ny k); xi runs along +x, eta along +y, zeta along +z.
class CRUMPLE_API HexMesh
{
public:
    /// Builds the structured mesh of a box. Refuses non-finite or non-positive sizes (NonFinite,
    /// DegenerateGeometry) and cell counts outside [1, cMaxCellsPerAxis] or above cMaxCellTotal (InvalidArgument).
    static Result<HexMesh> Create(const HexMeshSettings& inSettings);

    /// Builds an unstructured mesh from explicit arrays (e.g. a structured mesh with moved nodes). Refuses
    /// non-finite positions, no elements, node indices out of range or repeated within an element, more than
    /// cMaxNodeCount nodes or cMaxElementCount elements, and elements failing cHexMinJacobianRatio.
    /// @param[in] inNodes     #nodes by 3 positions (m)
    /// @param[in] inElements  #elements by 8 node indices in the documented corner order
    static Result<HexMesh> Create(HexNodeMatrix inNodes, HexElementMatrix inElements);

    /// #nodes by 3 positions, body frame (m)
    const HexNodeMatrix& GetNodes() const { return mNodes; }
    /// #elements by 8 node indices
    const HexElementMatrix& GetElements() const { return mElements; }
    /// Number of nodes
    int GetNodeCount() const { return static_cast<int>(mNodes.rows()); }
    /// Number of elements
    int GetElementCount() const { return static_cast<int>(mElements.rows()); }
    /// The 8 corner positions of element inElement (m), in corner order.
    HexCornerMatrix GetCorners(int inElement) const;

    /// True when the mesh was built from HexMeshSettings, so that GetGridNodeIndex() applies.
    bool IsStructured() const { return mGridCellCount[0] > 0; }
    /// Cells per axis of a structured mesh; {0, 0, 0} for an unstructured one.
    const std::array<int, 3>& GetGridCellCount() const { return mGridCellCount; }
    /// Index of grid node (i, j, k) of a structured mesh, 0 <= i <= nx etc.: i + (nx + 1) (j + (ny + 1) k).
    int GetGridNodeIndex(int inI, int inJ, int inK) const
    {
        return inI + (mGridCellCount[0] + 1) * (inJ + (mGridCellCount[1] + 1) * inK);
    }

    static constexpr int cMaxNodeCount = 1 << 20;                          ///< At most 1,048,576 nodes
    static constexpr int cMaxElementCount = HexMeshSettings::cMaxCellTotal; ///< At most 262,144 elements

private:
    HexMesh(HexNodeMatrix inNodes, HexElementMatrix inElements, const std::array<int, 3>& inGridCellCount);

    HexNodeMatrix mNodes;
    HexElementMatrix mElements;
    std::array<int, 3> mGridCellCount{{0, 0, 0}};
};

} // namespace crumple::fem
