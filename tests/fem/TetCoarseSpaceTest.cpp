// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// fem::BuildTetCoarseSpace: its inverse against P^T A0 P of the assembled rest system, rigid motions that
// cost no strain energy, connected aggregates that follow cracks, its limits and its refusals.
#include "AssembledSystemCheck.h"

#include <crumple/fem/FemMaterial.h>
#include <crumple/fem/FractureLinks.h>
#include <crumple/fem/FractureTopology.h>
#include <crumple/fem/LumpedNodeMass.h>
#include <crumple/fem/TetCoarseSpace.h>
#include <crumple/fem/TetGrid.h>

#include "TetRestSystemBlocks.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <set>

using namespace crumple;
using namespace crumple::fem;

namespace
{

// A steel block of 20 x 3 x 3 cells (900 tetrahedra) with its x = 0 face anchored (or none).
struct Body
{
    TetMesh mMesh;
    std::vector<TetElementRest> mRest;
    FemMaterial mMaterial;
    std::vector<double> mMasses, mInverseMasses;
};

Body MakeBody(bool inAnchored, int inLengthCells = 20)
{
    TetGridSettings grid;
    grid.mSize = Vec3(1.0, 0.3, 0.3);
    grid.mCellCount = {inLengthCells, 3, 3};
    TetMesh mesh = TetGrid(grid).Get();
    FemMaterialSettings settings;
    settings.mYoungsModulus = 2.1e11;
    settings.mPoissonRatio = 0.3;
    settings.mDensity = 7850.0;
    Body body{
        mesh, TetRestData(mesh), FemMaterial::Create(settings).Get(), LumpedNodeMass(mesh, 7850.0).Get(), {}};
    for (std::size_t node = 0; node < body.mMasses.size(); ++node)
    {
        const bool anchored = inAnchored && mesh.GetRestPositions()[node].x() == 0.0;
        body.mInverseMasses.push_back(anchored ? 0.0 : 1.0 / body.mMasses[node]);
    }
    return body;
}

constexpr double cStep = 1.0 / 60.0;
constexpr double cMassScale = 1.0 + cStep * 0.2;
constexpr double cStiffnessScale = cStep * cStep + cStep * 2.0e-6;

Result<TetCoarseSpace> Build(const Body& inBody, std::span<const TetIndices> inElements,
                             std::span<const Vec3> inRestPositions, std::span<const double> inMasses,
                             std::span<const double> inInverseMasses,
                             const TetCoarseSpaceSettings& inSettings = {})
{
    return BuildTetCoarseSpace(inElements, inBody.mRest, inRestPositions, inMasses, inInverseMasses,
                               inBody.mMaterial.GetMaterialMatrix(), cMassScale, cStiffnessScale, inSettings);
}

Result<TetCoarseSpace> Build(const Body& inBody, const TetCoarseSpaceSettings& inSettings = {})
{
    return Build(inBody, inBody.mMesh.GetTets(), inBody.mMesh.GetRestPositions(), inBody.mMasses,
                 inBody.mInverseMasses, inSettings);
}

// P over the free nodes (numbered in node order), built from the space's aggregates and offsets as the
// shaders read them: a node's rows [I, -[d]x] in its aggregate's six columns.
Eigen::MatrixXd ModeMatrix(const TetCoarseSpace& inSpace, std::span<const double> inInverseMasses)
{
    std::vector<int> free_nodes;
    for (std::size_t node = 0; node < inInverseMasses.size(); ++node)
        if (inInverseMasses[node] > 0.0)
            free_nodes.push_back(static_cast<int>(node));
    Eigen::MatrixXd modes = Eigen::MatrixXd::Zero(3 * static_cast<Eigen::Index>(free_nodes.size()),
                                                  6 * inSpace.GetAggregateCount());
    for (std::size_t f = 0; f < free_nodes.size(); ++f)
    {
        const auto node = static_cast<std::size_t>(free_nodes[f]);
        const Eigen::Index row = 3 * static_cast<Eigen::Index>(f), column = 6 * inSpace.mNodeAggregate[node];
        modes.block<3, 3>(row, column).setIdentity();
        for (int axis = 0; axis < 3; ++axis)
            modes.block<3, 1>(row, column + 3 + axis) = Vec3::Unit(axis).cross(inSpace.mNodeOffset[node]);
    }
    return modes;
}

} // namespace

TEST_CASE(
    "Coarse space: its inverse is that of P^T A0 P, the assembled rest system on the aggregates' rigid modes",
    "[fem]")
{
    const Body body = MakeBody(true);
    const TetCoarseSpace space = Build(body).Get();
    REQUIRE(space.GetAggregateCount() >= TetCoarseSpaceSettings{}.mMinAggregates);

    std::vector<int> free_index(body.mMasses.size(), -1);
    int free_count = 0;
    for (std::size_t node = 0; node < free_index.size(); ++node)
        if (body.mInverseMasses[node] > 0.0)
            free_index[node] = free_count++;
    const TetElementPassInput input{body.mMesh.GetTets(),
                                    body.mRest,
                                    &body.mMaterial.GetMaterialMatrix(),
                                    body.mMaterial.GetLambda(),
                                    body.mMaterial.GetShearModulus(),
                                    EElasticModel::CorotatedLinear,
                                    {}};
    std::vector<NodeBlock> blocks;
    TetRestSystemBlocks(input, body.mMasses, free_index, cMassScale, cStiffnessScale, blocks);
    const Eigen::MatrixXd system = test::DenseSymmetric(blocks, free_count);
    const Eigen::MatrixXd modes = ModeMatrix(space, body.mInverseMasses);
    const Eigen::MatrixXd coarse = modes.transpose() * system * modes;
    const Eigen::MatrixXd identity = space.mInverse * coarse;
    const double error =
        (identity - Eigen::MatrixXd::Identity(identity.rows(), identity.cols())).cwiseAbs().maxCoeff();
    INFO(space.GetAggregateCount() << " aggregates; largest entry of inverse * P^T A0 P - I: " << error);
    CHECK(error < 1.0e-9);
}

namespace
{

// How far (P^T A0 P)^-1 a P^T M P y is from y, relative, for y a rigid motion of the whole body at
// inPositions: K P y = 0 there exactly when the space's system and modes follow the body's frames and
// positions.
double RigidMotionError(const Body& inBody, std::span<const Vec3> inPositions, std::span<const Quat> inFrames,
                        std::span<const Vec3> inModePositions)
{
    const TetCoarseSpace space =
        BuildTetCoarseSpace(inBody.mMesh.GetTets(), inBody.mRest, inBody.mMesh.GetRestPositions(),
                            inBody.mMasses, inBody.mInverseMasses, inBody.mMaterial.GetMaterialMatrix(),
                            cMassScale, cStiffnessScale, {}, inFrames, inModePositions)
            .Get();
    REQUIRE(space.GetAggregateCount() > 0);
    const Vec3 translation(0.3, -0.2, 0.5), rotation(0.7, 0.1, -0.4);
    Eigen::VectorXd motion(6 * space.GetAggregateCount());
    for (int aggregate = 0; aggregate < space.GetAggregateCount(); ++aggregate)
    {
        // The aggregate's centre from any node of it: position less offset.
        const auto first = static_cast<std::size_t>(
            space.mAggregateNodes[static_cast<std::size_t>(space.mAggregateStart[aggregate])]);
        const Vec3 centre = inPositions[first] - space.mNodeOffset[first];
        motion.segment<3>(6 * aggregate) = translation + rotation.cross(centre);
        motion.segment<3>(6 * aggregate + 3) = rotation;
    }
    const Eigen::MatrixXd modes = ModeMatrix(space, inBody.mInverseMasses);
    Eigen::VectorXd masses(modes.rows());
    for (std::size_t node = 0; node < inBody.mMasses.size(); ++node)
        masses.segment<3>(3 * static_cast<Eigen::Index>(node)).setConstant(cMassScale * inBody.mMasses[node]);
    const Eigen::VectorXd moved = modes * motion;
    // intent: the motion is rigid at every node (the modes and offsets agree)
    double rigid_error = 0.0;
    for (std::size_t node = 0; node < inBody.mMasses.size(); ++node)
        rigid_error = std::max(rigid_error, (Vec3(moved.segment<3>(3 * static_cast<Eigen::Index>(node))) -
                                             (translation + rotation.cross(inPositions[node])))
                                                .norm());
    CHECK(rigid_error < 1.0e-12);
    const Eigen::VectorXd back = space.mInverse * (modes.transpose() * masses.asDiagonal() * moved);
    return (back - motion).cwiseAbs().maxCoeff() / motion.cwiseAbs().maxCoeff();
}

} // namespace

TEST_CASE("Coarse space: a rigid motion of a free body costs no strain energy on the coarse level", "[fem]")
{
    // K0 P y = 0 when P y moves every node rigidly, so (P^T A0 P) y = a P^T M P y: the inverse must give y
    // back from the mass term alone (independent of the assembly: masses and kinematics only). The stiffness
    // (2e11 Pa x h^2) dwarfs the mass term: the bound is round-off of its cancellation.
    const Body body = MakeBody(false);
    const double at_rest = RigidMotionError(body, body.mMesh.GetRestPositions(), {}, {});
    INFO("at rest: relative error of the recovered motion " << at_rest);
    CHECK(at_rest < 1.0e-6);

    // The body turned 60 degrees about an oblique axis and moved: built at its element frames and positions,
    // the same holds; with the positions but the rest frames the turned elements resist the rigid motion.
    const Quat turn(Eigen::AngleAxisd(1.047, Vec3(1.0, 2.0, -0.5).normalized()));
    std::vector<Vec3> turned;
    for (const Vec3& rest : body.mMesh.GetRestPositions())
        turned.push_back(turn * rest + Vec3(3.0, -1.0, 0.5));
    const std::vector<Quat> frames(body.mRest.size(), turn);
    const double at_frames = RigidMotionError(body, turned, frames, turned);
    const double rest_frames = RigidMotionError(body, turned, {}, turned);
    INFO("turned: " << at_frames << " at its frames, " << rest_frames << " with the rest frames");
    CHECK(at_frames < 1.0e-6);
    CHECK(rest_frames > 1.0e-3);
}

TEST_CASE("Coarse space: connected aggregates of the free nodes, within the limit, that do not cross cracks",
          "[fem]")
{
    const Body body = MakeBody(true, 30);
    // The block cut through at x = 0.5 m: every link across that plane broken.
    const FractureLinks links = BuildFractureLinks(body.mMesh);
    auto group_centre_x = [&](int inGroup)
    {
        const auto element = static_cast<std::size_t>(links.mGroupElements[static_cast<std::size_t>(
            links.mGroupElementOffsets[static_cast<std::size_t>(inGroup)])]);
        double x = 0.0;
        for (int corner : body.mMesh.GetTets()[element])
            x += 0.25 * body.mMesh.GetRestPositions()[static_cast<std::size_t>(corner)].x();
        return x;
    };
    std::vector<std::uint8_t> broken(static_cast<std::size_t>(links.GetLinkCount()), 0);
    for (std::size_t link = 0; link < broken.size(); ++link)
        broken[link] = (group_centre_x(links.mLinkGroups[link][0]) < 0.5) !=
                               (group_centre_x(links.mLinkGroups[link][1]) < 0.5)
                           ? 1
                           : 0;
    const FractureConnectivity cracked = FractureTopology(body.mMesh, links, broken).Get();
    const std::size_t node_count = cracked.mNodeOrigin.size();
    REQUIRE(node_count > body.mMasses.size());
    std::vector<Vec3> rest(node_count);
    std::vector<double> inverse_masses(node_count);
    for (std::size_t node = 0; node < node_count; ++node)
    {
        const auto origin = static_cast<std::size_t>(cracked.mNodeOrigin[node]);
        rest[node] = body.mMesh.GetRestPositions()[origin];
        inverse_masses[node] = body.mInverseMasses[origin] == 0.0 ? 0.0 : 1.0;
    }
    const std::vector<double> masses =
        LumpedNodeMass(cracked.mElementNodes, body.mRest, static_cast<int>(node_count), 7850.0).Get();
    const TetCoarseSpaceSettings settings{.mMaxCoarseUnknowns = 120};
    const TetCoarseSpace space =
        Build(body, cracked.mElementNodes, rest, masses, inverse_masses, settings).Get();
    REQUIRE(space.GetAggregateCount() > 0);
    CHECK(6 * space.GetAggregateCount() <= settings.mMaxCoarseUnknowns);

    // Every free node in exactly one aggregate (its members ascending), no anchored node in any.
    std::vector<int> seen(node_count, 0);
    for (int aggregate = 0; aggregate < space.GetAggregateCount(); ++aggregate)
        for (int entry = space.mAggregateStart[static_cast<std::size_t>(aggregate)];
             entry < space.mAggregateStart[static_cast<std::size_t>(aggregate) + 1]; ++entry)
        {
            const int node = space.mAggregateNodes[static_cast<std::size_t>(entry)];
            ++seen[static_cast<std::size_t>(node)];
            CHECK(space.mNodeAggregate[static_cast<std::size_t>(node)] == aggregate);
            if (entry > space.mAggregateStart[static_cast<std::size_t>(aggregate)])
                CHECK(space.mAggregateNodes[static_cast<std::size_t>(entry) - 1] < node);
        }
    for (std::size_t node = 0; node < node_count; ++node)
    {
        CHECK(seen[node] == (inverse_masses[node] > 0.0 ? 1 : 0));
        if (inverse_masses[node] == 0.0)
            CHECK(space.mNodeAggregate[node] == -1);
    }

    // Each aggregate connected through the cracked mesh's edges between its own nodes; none spans the cut.
    std::vector<std::set<int>> neighbours(node_count);
    for (const TetIndices& tet : cracked.mElementNodes)
        for (int a : tet)
            for (int b : tet)
                if (a != b)
                    neighbours[static_cast<std::size_t>(a)].insert(b);
    for (int aggregate = 0; aggregate < space.GetAggregateCount(); ++aggregate)
    {
        const auto begin =
            space.mAggregateNodes.begin() + space.mAggregateStart[static_cast<std::size_t>(aggregate)];
        const auto end =
            space.mAggregateNodes.begin() + space.mAggregateStart[static_cast<std::size_t>(aggregate) + 1];
        std::set<int> reached{*begin};
        std::vector<int> queue{*begin};
        while (!queue.empty())
        {
            const int node = queue.back();
            queue.pop_back();
            for (int other : neighbours[static_cast<std::size_t>(node)])
                if (space.mNodeAggregate[static_cast<std::size_t>(other)] == aggregate &&
                    reached.insert(other).second)
                    queue.push_back(other);
        }
        CHECK(static_cast<std::ptrdiff_t>(reached.size()) == end - begin);
        bool left = false, right = false;
        for (auto it = begin; it != end; ++it)
        {
            // A node on the cut plane belongs to the side of the elements that hold it (a copy per side).
            double x = 0.0;
            int corners = 0;
            for (const TetIndices& tet : cracked.mElementNodes)
                for (int corner : tet)
                    if (corner == *it)
                    {
                        double centre = 0.0;
                        for (int c : tet)
                            centre += 0.25 * rest[static_cast<std::size_t>(c)].x();
                        x += centre;
                        ++corners;
                    }
            (x / corners < 0.5 ? left : right) = true;
        }
        CHECK_FALSE((left && right));
    }
}

TEST_CASE("Coarse space: a body of too few aggregates gets none, bad input is refused", "[fem]")
{
    const Body body = MakeBody(true);
    const TetCoarseSpace few = Build(body, {.mMinAggregates = 1000}).Get();
    CHECK(few.GetAggregateCount() == 0);
    CHECK(few.mInverse.size() == 0);
    for (int aggregate : few.mNodeAggregate)
        CHECK(aggregate == -1);

    // A shattered body: 80 separate tetrahedra need 80 aggregates, more than 384 unknowns hold (it used to
    // grow its aggregates for ever).
    std::vector<Vec3> shards;
    std::vector<TetIndices> shard_tets;
    for (int shard = 0; shard < 80; ++shard)
    {
        const Vec3 corner(0.2 * shard, 0.0, 0.0);
        for (const Vec3& offset :
             {Vec3(0.0, 0.0, 0.0), Vec3(0.1, 0.0, 0.0), Vec3(0.0, 0.1, 0.0), Vec3(0.0, 0.0, 0.1)})
            shards.push_back(corner + offset);
        shard_tets.push_back({4 * shard, 4 * shard + 1, 4 * shard + 2, 4 * shard + 3});
    }
    const TetMesh shattered = TetMesh::Create(shards, shard_tets).Get();
    const std::vector<double> shard_masses = LumpedNodeMass(shattered, 7850.0).Get();
    std::vector<double> shard_inverse;
    for (double mass : shard_masses)
        shard_inverse.push_back(1.0 / mass);
    const TetCoarseSpace none =
        BuildTetCoarseSpace(shattered.GetTets(), TetRestData(shattered), shards, shard_masses, shard_inverse,
                            body.mMaterial.GetMaterialMatrix(), cMassScale, cStiffnessScale)
            .Get();
    CHECK(none.GetAggregateCount() == 0);
    // With room for them, each shard is one aggregate (four free nodes: translations and rotations).
    const TetCoarseSpace shard_space =
        BuildTetCoarseSpace(shattered.GetTets(), TetRestData(shattered), shards, shard_masses, shard_inverse,
                            body.mMaterial.GetMaterialMatrix(), cMassScale, cStiffnessScale,
                            {.mMaxCoarseUnknowns = 480})
            .Get();
    CHECK(shard_space.GetAggregateCount() == 80);

    const std::span<const TetIndices> tets = body.mMesh.GetTets();
    const std::span<const Vec3> rest = body.mMesh.GetRestPositions();
    std::vector<double> short_masses(body.mMasses.begin(), body.mMasses.end() - 1);
    CHECK(Build(body, tets, rest, short_masses, body.mInverseMasses).GetError().mCode ==
          EError::InvalidArgument);
    std::vector<TetIndices> out_of_range(tets.begin(), tets.end());
    out_of_range[3][2] = static_cast<int>(rest.size());
    CHECK(Build(body, out_of_range, rest, body.mMasses, body.mInverseMasses).GetError().mCode ==
          EError::OutOfRange);
    std::vector<Vec3> nan_rest(rest.begin(), rest.end());
    nan_rest[5].y() = std::numeric_limits<double>::quiet_NaN();
    CHECK(Build(body, tets, nan_rest, body.mMasses, body.mInverseMasses).GetError().mCode ==
          EError::InvalidArgument);
    const std::vector<double> anchored(body.mMasses.size(), 0.0);
    CHECK(Build(body, tets, rest, body.mMasses, anchored).GetError().mCode == EError::InvalidArgument);
    CHECK(BuildTetCoarseSpace(tets, body.mRest, rest, body.mMasses, body.mInverseMasses,
                              body.mMaterial.GetMaterialMatrix(), -1.0, cStiffnessScale)
              .GetError()
              .mCode == EError::InvalidArgument);
    CHECK(BuildTetCoarseSpace(tets, body.mRest, rest, body.mMasses, body.mInverseMasses,
                              body.mMaterial.GetMaterialMatrix(), cMassScale,
                              std::numeric_limits<double>::infinity())
              .GetError()
              .mCode == EError::InvalidArgument);
    CHECK(Build(body, {.mMaxCoarseUnknowns = 5}).GetError().mCode == EError::InvalidArgument);
    // Frames and positions: one per element and node, finite (a diverged state read back is refused).
    const Matrix6& material = body.mMaterial.GetMaterialMatrix();
    std::vector<Quat> frames(body.mRest.size(), Quat::Identity());
    std::vector<Vec3> positions(rest.begin(), rest.end());
    const auto build_at = [&]
    {
        return BuildTetCoarseSpace(tets, body.mRest, rest, body.mMasses, body.mInverseMasses, material,
                                   cMassScale, cStiffnessScale, {}, frames, positions);
    };
    CHECK(build_at().IsValid());
    frames.pop_back();
    CHECK(build_at().GetError().mCode == EError::InvalidArgument);
    frames.push_back(Quat(std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0, 0.0));
    CHECK(build_at().GetError().mCode == EError::InvalidArgument);
    frames.back() = Quat::Identity();
    positions[7].z() = std::numeric_limits<double>::infinity();
    CHECK(build_at().GetError().mCode == EError::InvalidArgument);
}
