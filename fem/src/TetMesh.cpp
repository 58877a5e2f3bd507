// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/TetMesh.h>
#include <crumple/fem/TetVolume.h>

#include <algorithm>
#include <sstream>

namespace crumple::fem
{

namespace
{

// "tet 12 (nodes 3, 4, 5, 9)", for messages.
std::string DescribeTet(int inTet, const TetIndices& inNodes)
{
    std::ostringstream text;
    text << "tet " << inTet << " (nodes " << inNodes[0] << ", " << inNodes[1] << ", " << inNodes[2] << ", "
         << inNodes[3] << ")";
    return text.str();
}

} // namespace

Result<TetMesh> TetMesh::Create(std::vector<Vec3> inRestPositions, std::vector<TetIndices> inTets,
                                std::vector<int> inGroups)
{
    // Sizes first: everything below indexes with int.
    if (inRestPositions.size() < 4 || inTets.empty())
        return MakeError(EError::InvalidArgument, "TetMesh: needs at least 4 nodes and 1 tetrahedron, got " +
                                                      std::to_string(inRestPositions.size()) + " nodes and " +
                                                      std::to_string(inTets.size()) + " tetrahedra");
    if (inRestPositions.size() > static_cast<std::size_t>(cMaxCount) ||
        inTets.size() > static_cast<std::size_t>(cMaxCount))
        return MakeError(EError::InvalidArgument, "TetMesh: more than 2^26 nodes or tetrahedra");
    if (!inGroups.empty() && inGroups.size() != inTets.size())
        return MakeError(EError::InvalidArgument, "TetMesh: " + std::to_string(inGroups.size()) +
                                                      " group ids for " + std::to_string(inTets.size()) +
                                                      " tetrahedra (give one per tetrahedron, or none)");
    const int node_count = static_cast<int>(inRestPositions.size());
    const int tet_count = static_cast<int>(inTets.size());

    // Finite node positions.
    for (int node = 0; node < node_count; ++node)
    {
        if (!IsFinite(inRestPositions[node]))
            return MakeError(EError::NonFinite,
                             "TetMesh: node " + std::to_string(node) + " has a non-finite position");
        // intent: the bound every solver state is held to (TetSolver::cMaxStateMagnitude); past it a volume
        // overflows and the element was refused as degenerate
        if (!(inRestPositions[node].cwiseAbs().maxCoeff() <= 1.0e100))
            return MakeError(EError::OutOfRange,
                             "TetMesh: node " + std::to_string(node) + " lies beyond 1e100 m");
    }

    // Indices in range and distinct, then orientation and shape.
    std::vector<char> used(inRestPositions.size(), 0);
    for (int tet = 0; tet < tet_count; ++tet)
    {
        const TetIndices& nodes = inTets[tet];
        for (int corner = 0; corner < 4; ++corner)
        {
            if (nodes[corner] < 0 || nodes[corner] >= node_count)
                return MakeError(EError::OutOfRange, "TetMesh: " + DescribeTet(tet, nodes) + " names node " +
                                                         std::to_string(nodes[corner]) + ", outside [0, " +
                                                         std::to_string(node_count) + ")");
            for (int other = 0; other < corner; ++other)
                if (nodes[other] == nodes[corner])
                    return MakeError(EError::DegenerateGeometry,
                                     "TetMesh: " + DescribeTet(tet, nodes) + " uses a node twice");
        }
        const Vec3& p0 = inRestPositions[nodes[0]];
        const Vec3& p1 = inRestPositions[nodes[1]];
        const Vec3& p2 = inRestPositions[nodes[2]];
        const Vec3& p3 = inRestPositions[nodes[3]];
        const double volume = TetVolume(p0, p1, p2, p3);
        const double longest_edge = std::max({(p1 - p0).norm(), (p2 - p0).norm(), (p3 - p0).norm(),
                                              (p2 - p1).norm(), (p3 - p1).norm(), (p3 - p2).norm()});
        const double min_volume = cMinVolumeRatio * longest_edge * longest_edge * longest_edge;
        if (volume < -min_volume)
        {
            std::ostringstream message;
            message << "TetMesh: " << DescribeTet(tet, nodes) << " is inverted: signed volume " << volume
                    << " m^3 < 0; swap two of its indices";
            return MakeError(EError::DegenerateGeometry, message.str());
        }
        if (!(volume > min_volume))
        {
            std::ostringstream message;
            message << "TetMesh: " << DescribeTet(tet, nodes) << " is degenerate: volume " << volume
                    << " m^3 <= " << cMinVolumeRatio << " x (longest edge " << longest_edge << " m)^3";
            return MakeError(EError::DegenerateGeometry, message.str());
        }
        for (int corner = 0; corner < 4; ++corner)
            used[nodes[corner]] = 1;
    }

    // Every node carries mass only through an element.
    for (int node = 0; node < node_count; ++node)
        if (used[node] == 0)
            return MakeError(EError::InvalidArgument,
                             "TetMesh: node " + std::to_string(node) +
                                 " belongs to no tetrahedron and would have no mass");

    // Group ids.
    for (int tet = 0; tet < static_cast<int>(inGroups.size()); ++tet)
        if (inGroups[tet] < 0)
            return MakeError(EError::InvalidArgument, "TetMesh: group id " + std::to_string(inGroups[tet]) +
                                                          " of tet " + std::to_string(tet) + " must be >= 0");
    if (inGroups.empty())
    {
        inGroups.resize(inTets.size());
        for (int tet = 0; tet < tet_count; ++tet)
            inGroups[tet] = tet;
    }

    TetMesh mesh;
    mesh.mRestPositions = std::move(inRestPositions);
    mesh.mTets = std::move(inTets);
    mesh.mGroups = std::move(inGroups);
    return mesh;
}

double TetMesh::GetRestVolume(int inTet) const
{
    const TetIndices& nodes = mTets[inTet];
    return TetVolume(mRestPositions[nodes[0]], mRestPositions[nodes[1]], mRestPositions[nodes[2]],
                     mRestPositions[nodes[3]]);
}

double TetMesh::GetTotalVolume() const
{
    double total = 0.0;
    for (int tet = 0; tet < GetTetCount(); ++tet)
        total += GetRestVolume(tet);
    return total;
}

} // namespace crumple::fem
