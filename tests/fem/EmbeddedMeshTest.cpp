// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/EmbeddedMesh.h>
#include <crumple/fem/SplitMix64.h>
#include <crumple/fem/TetGrid.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>

using namespace crumple;
using namespace crumple::fem;

namespace
{

// A 2 x 2 x 1 grid of 0.5 x 0.4 x 0.3 m cells at (1, -1, 2).
TetMesh Grid(ECubeSplit inSplit = ECubeSplit::Five)
{
    TetGridSettings settings;
    settings.mOrigin = Vec3(1.0, -1.0, 2.0);
    settings.mSize = Vec3(1.0, 0.8, 0.3);
    settings.mCellCount = {{2, 2, 1}};
    settings.mSplit = inSplit;
    return TetGrid(settings).Get();
}

// Random points in each of the four cells (group g = i + 2 j), some of them outside their cell by up to a
// fifth of it, so that they are extrapolated.
void RandomPoints(std::vector<Vec3>& outPositions, std::vector<int>& outGroups, bool inOutside)
{
    SplitMix64 random(7);
    const Vec3 cell(0.5, 0.4, 0.3);
    for (int group = 0; group < 4; ++group)
        for (int point = 0; point < 50; ++point)
        {
            const double reach = inOutside ? 1.4 : 1.0; // fraction of the cell covered
            Vec3 local;
            for (int axis = 0; axis < 3; ++axis)
                local[axis] = 0.5 + 0.5 * reach * random.NextSigned();
            const Vec3 corner(1.0 + 0.5 * (group % 2), -1.0 + 0.4 * (group / 2), 2.0);
            outPositions.push_back(corner + local.cwiseProduct(cell));
            outGroups.push_back(group);
        }
}

// A rotation about a skew axis.
Mat3 SomeRotation()
{
    return Eigen::AngleAxisd(0.7, Vec3(1.0, -2.0, 0.5).normalized()).toRotationMatrix();
}

} // namespace

TEST_CASE("EmbeddedMesh binds each vertex inside an element of its group and reproduces its rest position",
          "[fem]")
{
    for (const ECubeSplit split : {ECubeSplit::Five, ECubeSplit::Six})
    {
        const TetMesh mesh = Grid(split);
        std::vector<Vec3> positions;
        std::vector<int> groups;
        RandomPoints(positions, groups, false);
        Result<EmbeddedMesh> result = EmbeddedMesh::Create(mesh, positions, groups, {});
        REQUIRE(result.IsValid());
        const EmbeddedMesh& embedded = result.Get();
        REQUIRE(embedded.GetVertexCount() == 200);
        CHECK(embedded.GetElementCount() == mesh.GetTetCount());

        // Inside points have all weights >= 0 (up to rounding), summing to 1, in an element of their group.
        CHECK(embedded.GetMinWeight() > -1e-12);
        std::vector<Vec3> rest;
        REQUIRE(embedded.Update(mesh.GetTets(), mesh.GetRestPositions(), rest).IsValid());
        for (int vertex = 0; vertex < 200; ++vertex)
        {
            const EmbeddedVertex& binding = embedded.GetVertices()[vertex];
            CHECK(mesh.GetGroups()[binding.mElement] == groups[vertex]);
            const double sum =
                binding.mWeights[0] + binding.mWeights[1] + binding.mWeights[2] + binding.mWeights[3];
            CHECK(std::abs(sum - 1.0) < 1e-15);
            CHECK((rest[vertex] - positions[vertex]).norm() < 1e-14);
        }
    }
}

TEST_CASE("EmbeddedMesh follows rigid motions and affine maps of the nodes exactly", "[fem]")
{
    const TetMesh mesh = Grid();
    std::vector<Vec3> positions;
    std::vector<int> groups;
    RandomPoints(positions, groups, true); // extrapolated vertices too: still affine in their element
    const EmbeddedMesh embedded = EmbeddedMesh::Create(mesh, positions, groups, {}).Get();
    CHECK(embedded.GetMinWeight() < 0.0);

    // Rigid motion x -> R x + t of every node moves every display vertex by the same motion.
    const Mat3 rotation = SomeRotation();
    const Vec3 translation(3.0, -2.0, 0.5);
    std::vector<Vec3> nodes = mesh.GetRestPositions();
    for (Vec3& node : nodes)
        node = rotation * node + translation;
    std::vector<Vec3> moved;
    REQUIRE(embedded.Update(mesh.GetTets(), nodes, moved).IsValid());
    REQUIRE(moved.size() == positions.size());
    for (std::size_t vertex = 0; vertex < positions.size(); ++vertex)
        CHECK((moved[vertex] - (rotation * positions[vertex] + translation)).norm() < 1e-12);

    // A general affine map x -> A x + b (stretch, shear, reflection-free) is reproduced: linear precision.
    Mat3 affine;
    affine << 1.3, 0.2, -0.1, 0.05, 0.8, 0.3, -0.2, 0.1, 1.1;
    const Vec3 offset(-0.4, 0.7, 0.2);
    nodes = mesh.GetRestPositions();
    for (Vec3& node : nodes)
        node = affine * node + offset;
    REQUIRE(embedded.Update(mesh.GetTets(), nodes, moved).IsValid());
    for (std::size_t vertex = 0; vertex < positions.size(); ++vertex)
        CHECK((moved[vertex] - (affine * positions[vertex] + offset)).norm() < 1e-12);
}

TEST_CASE("EmbeddedMesh takes the element connectivity at update time (duplicated nodes)", "[fem]")
{
    const TetMesh mesh = Grid();
    std::vector<Vec3> positions;
    std::vector<int> groups;
    RandomPoints(positions, groups, false);
    const EmbeddedMesh embedded = EmbeddedMesh::Create(mesh, positions, groups, {}).Get();

    // Fracture duplicates the node at corner 2 of vertex 0's element, moves the copy away and points that
    // corner to it; every other element keeps the original node.
    const int element = embedded.GetVertices()[0].mElement;
    const int corner = 2;
    std::vector<TetIndices> tets = mesh.GetTets();
    std::vector<Vec3> nodes = mesh.GetRestPositions();
    const Vec3 displacement(0.1, -0.2, 0.3);
    nodes.push_back(nodes[tets[element][corner]] + displacement);
    tets[element][corner] = static_cast<int>(nodes.size()) - 1;

    std::vector<Vec3> moved;
    REQUIRE(embedded.Update(tets, nodes, moved).IsValid());
    int moved_count = 0;
    for (std::size_t vertex = 0; vertex < positions.size(); ++vertex)
    {
        const EmbeddedVertex& binding = embedded.GetVertices()[vertex];
        if (binding.mElement == element)
        {
            // Moves by its weight of that corner times the displacement.
            CHECK((moved[vertex] - (positions[vertex] + binding.mWeights[corner] * displacement)).norm() <
                  1e-14);
            moved_count += binding.mWeights[corner] > 1e-3 ? 1 : 0;
        }
        else
        {
            CHECK((moved[vertex] - positions[vertex]).norm() < 1e-14);
        }
    }
    CHECK(moved_count >= 1);
}

TEST_CASE("EmbeddedMesh refuses invalid input and produces nothing", "[fem]")
{
    const TetMesh mesh = Grid();
    const std::vector<Vec3> positions{Vec3(1.1, -0.9, 2.1), Vec3(1.2, -0.9, 2.1), Vec3(1.1, -0.8, 2.1)};
    const std::vector<int> groups{0, 0, 0};
    const auto refused = [](const Result<EmbeddedMesh>& inResult, const std::string& inWords)
    {
        REQUIRE(inResult.HasError());
        INFO(inResult.GetError().mMessage);
        CHECK(inResult.GetError().mMessage.find(inWords) != std::string::npos);
    };

    refused(EmbeddedMesh::Create(mesh, positions, std::vector<int>{0, 0}, {}), "2 group ids");
    refused(
        EmbeddedMesh::Create(mesh, std::vector<Vec3>{Vec3(1.1, std::nan(""), 2.1)}, std::vector<int>{0}, {}),
        "vertex 0 has a non-finite position");
    refused(EmbeddedMesh::Create(mesh, positions, std::vector<int>{0, 9, 0}, {}), "group 9");
    refused(EmbeddedMesh::Create(mesh, positions, groups, {{{0, 1, 3}}}), "names vertex 3");
    refused(EmbeddedMesh::Create(mesh, positions, groups, {{{0, 1, 1}}}), "uses vertex 1 twice");
    // A vertex 3 m away from group 0, which spans 0.5 x 0.4 x 0.3 m: a wrong group id.
    refused(EmbeddedMesh::Create(mesh, std::vector<Vec3>{Vec3(4.0, -0.9, 2.1)}, std::vector<int>{0}, {}),
            "far outside group 0");

    // Update: wrong element count, a node index out of range, a non-finite node; the output stays empty.
    const EmbeddedMesh embedded = EmbeddedMesh::Create(mesh, positions, groups, {{{0, 1, 2}}}).Get();
    std::vector<Vec3> out{Vec3::Zero()};
    std::vector<TetIndices> tets = mesh.GetTets();
    Status status = embedded.Update(std::span<const TetIndices>(tets).first(3), mesh.GetRestPositions(), out);
    REQUIRE(status.HasError());
    CHECK(status.GetError().mMessage.find("3 elements given") != std::string::npos);
    CHECK(out.empty());
    tets[embedded.GetVertices()[0].mElement][1] = mesh.GetNodeCount();
    status = embedded.Update(tets, mesh.GetRestPositions(), out);
    REQUIRE(status.HasError());
    CHECK(status.GetError().mCode == EError::OutOfRange);
    CHECK(out.empty());
    std::vector<Vec3> nodes = mesh.GetRestPositions();
    nodes[mesh.GetTets()[embedded.GetVertices()[2].mElement][3]].x() =
        std::numeric_limits<double>::infinity();
    status = embedded.Update(mesh.GetTets(), nodes, out);
    REQUIRE(status.HasError());
    CHECK(status.GetError().mCode == EError::NonFinite);
    CHECK(out.empty());
}
