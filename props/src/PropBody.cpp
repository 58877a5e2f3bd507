// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/TetVolume.h>
#include <crumple/plugin/BodyState.h>
#include <crumple/props/PropBody.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>

namespace crumple::props
{

Result<std::vector<std::vector<Vec3>>> PropCollisionPieces(std::span<const Vec3> inPositions,
                                                           std::span<const fem::TetIndices> inElements,
                                                           std::span<const std::uint8_t> inLeftOut, double inCellSize)
{
    if (!std::isfinite(inCellSize) || !(inCellSize > 0.0))
        return MakeError(std::isfinite(inCellSize) ? EError::InvalidArgument : EError::NonFinite,
                         "PropCollisionPieces: the cell size must be finite and > 0 m");
    // intent: everything checked before any cube is made; cube indices are exact integers below 2^52 cells
    constexpr double cMaxCubeIndex = 4503599627370496.0; // 2^52
    for (std::size_t element = 0; element < inElements.size(); ++element)
        for (int node : inElements[element])
            if (node < 0 || static_cast<std::size_t>(node) >= inPositions.size())
                return MakeError(EError::OutOfRange, "PropCollisionPieces: element " + std::to_string(element) + " names node " +
                                                         std::to_string(node) + " of " + std::to_string(inPositions.size()));
    for (const Vec3& position : inPositions)
    {
        if (!IsFinite(position))
            return MakeError(EError::NonFinite, "PropCollisionPieces: a node position is not finite");
        if (!(position.cwiseAbs().maxCoeff() / inCellSize < cMaxCubeIndex))
            return MakeError(EError::InvalidArgument, "PropCollisionPieces: the cell size is too small for the positions "
                                                      "(more than 2^52 cubes from the origin)");
    }
    // intent: each cube's nodes, cubes ordered (z, y, x) so that the pieces come out the same every time
    std::map<std::array<std::int64_t, 3>, std::vector<int>> cubes;
    for (std::size_t element = 0; element < inElements.size(); ++element)
    {
        if (element < inLeftOut.size() && inLeftOut[element] != 0)
            continue;
        Vec3 centroid = Vec3::Zero();
        for (int node : inElements[element])
            centroid += inPositions[static_cast<std::size_t>(node)];
        centroid *= 0.25;
        const Vec3 cell = (centroid / inCellSize).array().floor();
        std::vector<int>& nodes = cubes[{static_cast<std::int64_t>(cell.z()), static_cast<std::int64_t>(cell.y()),
                                         static_cast<std::int64_t>(cell.x())}];
        nodes.insert(nodes.end(), inElements[element].begin(), inElements[element].end());
    }
    std::vector<std::vector<Vec3>> pieces;
    pieces.reserve(cubes.size());
    for (auto& [cube, nodes] : cubes)
    {
        std::sort(nodes.begin(), nodes.end());
        nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
        std::vector<Vec3>& piece = pieces.emplace_back();
        for (int node : nodes)
            piece.push_back(inPositions[static_cast<std::size_t>(node)]);
    }
    return pieces;
}

Result<PropBody> MakePropBody(const fem::TetMesh& inMesh, double inDensity, const Transform& inPose, bool inHeld, double inCellSize)
{
    if (!std::isfinite(inDensity) || !(inDensity > 0.0))
        return MakeError(EError::InvalidArgument, "MakePropBody: the density must be finite and > 0 kg/m^3");
    if (!std::isfinite(inCellSize) || !(inCellSize > 0.0))
        return MakeError(EError::InvalidArgument, "MakePropBody: the cell size must be finite and > 0 m");
    if (!IsFinite(inPose.mTranslation) || !IsRotation(inPose.mRotation, 1.0e-6))
        return MakeError(EError::InvalidArgument, "MakePropBody: the pose must be a finite rigid transform");

    // intent: mass, first and second moments over the tetrahedra (exact for a uniform density)
    const std::vector<Vec3>& rest = inMesh.GetRestPositions();
    double mass = 0.0;
    Vec3 first = Vec3::Zero();
    Mat3 second = Mat3::Zero();
    for (const fem::TetIndices& tet : inMesh.GetTets())
    {
        const std::array<Vec3, 4> x{rest[static_cast<std::size_t>(tet[0])], rest[static_cast<std::size_t>(tet[1])],
                                    rest[static_cast<std::size_t>(tet[2])], rest[static_cast<std::size_t>(tet[3])]};
        const double m = inDensity * fem::TetVolume(x[0], x[1], x[2], x[3]);
        const Vec3 sum = x[0] + x[1] + x[2] + x[3];
        Mat3 corners = sum * sum.transpose();
        for (const Vec3& corner : x)
            corners += corner * corner.transpose();
        mass += m;
        first += 0.25 * m * sum;
        second += (m / 20.0) * corners;
    }
    const Vec3 centre = first / mass;
    const Mat3 spread = second - mass * centre * centre.transpose(); // integral of r r^T dm about the centre
    const Mat3 inertia = spread.trace() * Mat3::Identity() - spread;
    const Eigen::SelfAdjointEigenSolver<Mat3> eigen(inertia);
    if (eigen.info() != Eigen::Success || !IsFinite(inertia) || !(mass > 0.0))
        return MakeError(EError::NonFinite, "MakePropBody: the prop's mass or inertia is not finite");
    Mat3 axes = eigen.eigenvectors();
    if (axes.determinant() < 0.0)
        axes.col(2) = -axes.col(2);

    // x_body = axes^T (x_mesh - centre)
    Transform mesh_to_body;
    mesh_to_body.mRotation = axes.transpose();
    mesh_to_body.mTranslation = -(axes.transpose() * centre);
    std::vector<Vec3> moved(rest.size());
    for (std::size_t node = 0; node < rest.size(); ++node)
        moved[node] = mesh_to_body.ToWorld(rest[node]);

    plugin::PropBodySettings body;
    body.mMass = mass;
    body.mPrincipalInertia = eigen.eigenvalues();
    body.mPosition = inPose.ToWorld(centre);
    body.mOrientation = inPose.mRotation * axes;
    body.mHeld = inHeld;
    Result<std::vector<std::vector<Vec3>>> pieces = PropCollisionPieces(moved, inMesh.GetTets(), {}, inCellSize);
    if (pieces.HasError())
        return MakeError(pieces.GetError().mCode, "MakePropBody: " + pieces.GetError().mMessage);
    body.mPieces = std::move(pieces).Get();
    if (Status valid = plugin::ValidatePropBodySettings(body); !valid)
        return MakeError(valid.GetError().mCode, "MakePropBody: " + valid.GetError().mMessage);
    Result<fem::TetMesh> mesh = fem::TetMesh::Create(std::move(moved), inMesh.GetTets(), inMesh.GetGroups());
    if (!mesh)
        return mesh.GetError();
    return PropBody{std::move(mesh).Get(), std::move(body), mesh_to_body};
}

} // namespace crumple::props
