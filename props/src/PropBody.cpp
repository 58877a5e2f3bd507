// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/TetVolume.h>
#include <crumple/plugin/BodyState.h>
#include <crumple/props/PropBody.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
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
    // intent: each kept element's cube (z, y, x), then one sort of the elements by cube, with no allocation per
    // cube; each cube's run gives its piece. Pieces and node order are those of an ordered map from cube to
    // nodes, which this replaces (its tree and per-cube lists cost most of a call).
    std::vector<std::array<std::int64_t, 3>> cubes;
    std::vector<std::uint32_t> kept;
    cubes.reserve(inElements.size());
    kept.reserve(inElements.size());
    for (std::size_t element = 0; element < inElements.size(); ++element)
    {
        if (element < inLeftOut.size() && inLeftOut[element] != 0)
            continue;
        Vec3 centroid = Vec3::Zero();
        for (int node : inElements[element])
            centroid += inPositions[static_cast<std::size_t>(node)];
        centroid *= 0.25;
        const Vec3 cell = (centroid / inCellSize).array().floor();
        cubes.push_back({static_cast<std::int64_t>(cell.z()), static_cast<std::int64_t>(cell.y()), static_cast<std::int64_t>(cell.x())});
        kept.push_back(static_cast<std::uint32_t>(element));
    }
    // intent: a cube as one integer, in the same (z, y, x) order, when the cubes' box has fewer than 2^62 cubes
    // (any prop within reason); a far-flung prop is sorted by the triple itself
    std::array<std::int64_t, 3> low{}, extent{};
    bool packed = !cubes.empty();
    for (int axis = 0; axis < 3 && packed; ++axis)
    {
        std::int64_t lo = cubes[0][axis], hi = cubes[0][axis];
        for (const std::array<std::int64_t, 3>& cube : cubes)
        {
            lo = std::min(lo, cube[axis]);
            hi = std::max(hi, cube[axis]);
        }
        low[axis] = lo;
        extent[axis] = hi - lo + 1; // below 2^53: cube indices are below 2^52 in size
        packed = extent[axis] < (std::int64_t{1} << 20);
    }
    std::vector<std::pair<std::uint64_t, std::uint32_t>> order(kept.size()); // (packed cube, index into kept)
    if (packed)
        for (std::size_t k = 0; k < kept.size(); ++k)
        {
            const std::array<std::int64_t, 3>& cube = cubes[k];
            order[k] = {static_cast<std::uint64_t>(((cube[0] - low[0]) * extent[1] + (cube[1] - low[1])) * extent[2] + (cube[2] - low[2])),
                        static_cast<std::uint32_t>(k)};
        }
    else
    {
        std::vector<std::uint32_t> by_triple(kept.size());
        for (std::size_t k = 0; k < kept.size(); ++k)
            by_triple[k] = static_cast<std::uint32_t>(k);
        std::stable_sort(by_triple.begin(), by_triple.end(), [&](std::uint32_t inA, std::uint32_t inB) { return cubes[inA] < cubes[inB]; });
        std::uint64_t rank = 0;
        for (std::size_t k = 0; k < kept.size(); ++k)
        {
            rank += k > 0 && cubes[by_triple[k]] != cubes[by_triple[k - 1]] ? 1 : 0;
            order[k] = {rank, by_triple[k]};
        }
    }
    std::sort(order.begin(), order.end());

    // intent: a cube's distinct nodes by a stamp per node (no sort of the duplicates), then ascending
    std::vector<std::uint32_t> stamp(inPositions.size(), 0);
    std::uint32_t cube_stamp = 0;
    std::vector<std::vector<Vec3>> pieces;
    std::vector<int> nodes;
    for (std::size_t first = 0; first < order.size();)
    {
        ++cube_stamp;
        nodes.clear();
        std::size_t end = first;
        for (; end < order.size() && order[end].first == order[first].first; ++end)
            for (int node : inElements[kept[order[end].second]])
                if (stamp[static_cast<std::size_t>(node)] != cube_stamp)
                {
                    stamp[static_cast<std::size_t>(node)] = cube_stamp;
                    nodes.push_back(node);
                }
        std::sort(nodes.begin(), nodes.end());
        std::vector<Vec3>& piece = pieces.emplace_back();
        piece.reserve(nodes.size());
        for (int node : nodes)
            piece.push_back(inPositions[static_cast<std::size_t>(node)]);
        first = end;
    }
    return pieces;
}

Result<PropBody> MakePropBody(const fem::TetMesh& inMesh, double inDensity, const Transform& inPose, bool inHeld, double inCellSize)
{
    if (!std::isfinite(inDensity) || !(inDensity > 0.0))
        return MakeError(EError::InvalidArgument, "MakePropBody: the density must be finite and > 0 kg/m^3");
    if (!std::isfinite(inCellSize) || !(inCellSize > 0.0))
        return MakeError(EError::InvalidArgument, "MakePropBody: the cell size must be finite and > 0 m");
    if (!IsFinite(inPose.mTranslation) || !IsRotation(inPose.mRotation, plugin::cRotationTolerance))
        return MakeError(EError::InvalidArgument, "MakePropBody: the pose must be a finite rigid transform");
    // intent: a pose from an engine in single precision, orthonormal only to float round-off, made a rotation
    // (plugin::CanonicalBodyState's rule: kept bit for bit within 1e-6)
    Transform pose = inPose;
    if (!IsRotation(pose.mRotation, 1.0e-6))
        pose.mRotation = Quat(pose.mRotation).normalized().toRotationMatrix();

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
    body.mPosition = pose.ToWorld(centre);
    body.mOrientation = pose.mRotation * axes;
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
