// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/CellCountForSections.h>
#include <crumple/fem/ProceduralEdgeMesh.h>
#include <crumple/fem/TetGrid.h>
#include <crumple/fem/TriangleNormals.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <utility>

using namespace crumple;
using namespace crumple::fem;

namespace
{

// A grid, its mesh and its edge mesh.
struct Prop
{
    TetGridSettings mGrid;
    TetMesh mMesh;
    ProceduralEdgeMesh mEdges;
};

Prop MakeProp(const TetGridSettings& inGrid, const ProceduralEdgeSettings& inSettings)
{
    TetMesh mesh = TetGrid(inGrid).Get();
    Result<ProceduralEdgeMesh> edges = ProceduralEdgeMesh::Create(inGrid, mesh, inSettings);
    if (edges.HasError())
        FAIL(edges.GetError().mMessage);
    return Prop{inGrid, std::move(mesh), std::move(edges).Get()};
}

// A wall of inSize at inOrigin cut into sections of about the average size.
TetGridSettings WallGrid(const Vec3& inOrigin, const Vec3& inSize, const ProceduralEdgeSettings& inSettings,
                         int inThicknessCells = 1, ECubeSplit inSplit = ECubeSplit::Five)
{
    TetGridSettings grid;
    grid.mOrigin = inOrigin;
    grid.mSize = inSize;
    grid.mCellCount = CellCountForSections(inSize, inSettings, inThicknessCells).Get();
    grid.mSplit = inSplit;
    return grid;
}

// Signed volume enclosed by triangles [inFirst, inFirst + inCount) (divergence theorem), m^3.
double EnclosedVolume(const EmbeddedMesh& inMesh, int inFirst, int inCount)
{
    double volume = 0.0;
    for (int triangle = inFirst; triangle < inFirst + inCount; ++triangle)
    {
        const TriangleIndices& corners = inMesh.GetTriangles()[triangle];
        const Vec3& a = inMesh.GetRestPositions()[corners[0]];
        const Vec3& b = inMesh.GetRestPositions()[corners[1]];
        const Vec3& c = inMesh.GetRestPositions()[corners[2]];
        volume += a.dot(b.cross(c)) / 6.0;
    }
    return volume;
}

// Every section: its triangles use only its own vertices, every directed edge appears exactly once and its
// reverse exactly once (closed, consistently oriented), positive volume, every vertex bound to its group.
// Returns the sum of the section volumes.
double CheckSections(const Prop& inProp)
{
    const EmbeddedMesh& mesh = inProp.mEdges.GetEmbeddedMesh();
    double total = 0.0;
    int triangle_total = 0;
    for (const EdgeSection& section : inProp.mEdges.GetSections())
    {
        const int first = section.mFirstVertex;
        const int last = first + 2 * section.mOutlineCount;
        CHECK(section.mTriangleCount == 2 * (section.mOutlineCount - 2) + 2 * section.mOutlineCount);
        std::map<std::pair<int, int>, int> directed;
        for (int triangle = section.mFirstTriangle;
             triangle < section.mFirstTriangle + section.mTriangleCount; ++triangle)
        {
            const TriangleIndices& corners = mesh.GetTriangles()[triangle];
            for (int corner = 0; corner < 3; ++corner)
            {
                REQUIRE(corners[corner] >= first);
                REQUIRE(corners[corner] < last);
                ++directed[{corners[corner], corners[(corner + 1) % 3]}];
            }
        }
        bool closed = true;
        for (const auto& [edge, count] : directed)
        {
            const auto reverse = directed.find({edge.second, edge.first});
            closed = closed && count == 1 && reverse != directed.end() && reverse->second == 1;
        }
        CHECK(closed);
        const double volume = EnclosedVolume(mesh, section.mFirstTriangle, section.mTriangleCount);
        CHECK(volume > 0.0);
        total += volume;
        triangle_total += section.mTriangleCount;
        for (int vertex = first; vertex < last; ++vertex)
            CHECK(inProp.mMesh.GetGroups()[mesh.GetVertices()[vertex].mElement] == section.mGroup);
    }
    CHECK(triangle_total == static_cast<int>(mesh.GetTriangles().size()));
    CHECK(mesh.GetMinWeight() >= -EmbeddedMesh::cMaxExtrapolation);
    return total;
}

// Settings with splinters everywhere, near the limits: jitter 0.4, amplitudes at 0.95 of the bound.
ProceduralEdgeSettings RoughSettings(std::uint64_t inSeed)
{
    ProceduralEdgeSettings settings;
    settings.mAverageSectionWidth = 0.4;
    settings.mAverageSectionHeight = 0.3;
    settings.mRandomSectionWidth = 0.4;
    settings.mRandomSectionHeight = 0.4;
    settings.mHorizontalEdgeFrequency = 60.0;
    settings.mVerticalEdgeFrequency = 45.0;
    settings.mHorizontalEdgeAmplitude = 0.95 * 0.4 * 0.2 * 0.3; // cells are exactly 0.4 x 0.3 m below
    settings.mVerticalEdgeAmplitude = 0.95 * 0.4 * 0.2 * 0.4;
    settings.mSeed = inSeed;
    return settings;
}

} // namespace

TEST_CASE("ProceduralEdgeMesh sections are closed, outward and tile the box", "[fem]")
{
    struct Case
    {
        Vec3 mSize;
        int mThicknessCells;
        ECubeSplit mSplit;
    };
    // Frames: (x, y, z) right-handed; (y, z, x) right-handed; (x, z, y) left-handed: triangles get reversed.
    const Case cases[] = {{Vec3(2.0, 1.2, 0.1), 1, ECubeSplit::Five},
                          {Vec3(0.15, 2.0, 1.2), 2, ECubeSplit::Six},
                          {Vec3(2.0, 0.2, 1.2), 3, ECubeSplit::Five}};
    for (const Case& test_case : cases)
        for (std::uint64_t seed : {1ULL, 2ULL, 3ULL})
        {
            const ProceduralEdgeSettings settings = RoughSettings(seed);
            const TetGridSettings grid = WallGrid(Vec3(-1.0, 0.5, 2.0), test_case.mSize, settings,
                                                  test_case.mThicknessCells, test_case.mSplit);
            const Prop prop = MakeProp(grid, settings);
            const auto& n = grid.mCellCount;
            REQUIRE(prop.mEdges.GetSections().size() == static_cast<std::size_t>(n[0] * n[1] * n[2]));
            for (int group = 0; group < n[0] * n[1] * n[2]; ++group)
                CHECK(prop.mEdges.GetSections()[group].mGroup == group);

            // The sections tile the box: their volumes add up to it.
            const double total = CheckSections(prop);
            CHECK(std::abs(total - test_case.mSize.prod()) < 1e-9 * test_case.mSize.prod());
        }
}

TEST_CASE("ProceduralEdgeMesh is bitwise reproducible from its seed", "[fem]")
{
    const Vec3 size(2.0, 1.2, 0.1);
    const TetGridSettings grid = WallGrid(Vec3::Zero(), size, RoughSettings(42));
    const Prop first = MakeProp(grid, RoughSettings(42));
    const Prop second = MakeProp(grid, RoughSettings(42));
    const Prop other = MakeProp(grid, RoughSettings(43));
    const EmbeddedMesh& a = first.mEdges.GetEmbeddedMesh();
    const EmbeddedMesh& b = second.mEdges.GetEmbeddedMesh();
    const EmbeddedMesh& c = other.mEdges.GetEmbeddedMesh();

    REQUIRE(a.GetVertexCount() == b.GetVertexCount());
    CHECK(a.GetTriangles() == b.GetTriangles());
    bool identical = true;
    for (int vertex = 0; vertex < a.GetVertexCount(); ++vertex)
        identical = identical && a.GetRestPositions()[vertex] == b.GetRestPositions()[vertex] &&
                    a.GetVertices()[vertex].mElement == b.GetVertices()[vertex].mElement &&
                    a.GetVertices()[vertex].mWeights == b.GetVertices()[vertex].mWeights;
    CHECK(identical);

    // Another seed moves interior vertices (the counts are the same: they depend on sizes only).
    REQUIRE(c.GetVertexCount() == a.GetVertexCount());
    int differing = 0;
    for (int vertex = 0; vertex < a.GetVertexCount(); ++vertex)
        differing += a.GetRestPositions()[vertex] != c.GetRestPositions()[vertex] ? 1 : 0;
    CHECK(differing > a.GetVertexCount() / 2);
}

TEST_CASE("ProceduralEdgeMesh without jitter or edge vertices gives exactly the cell boxes", "[fem]")
{
    ProceduralEdgeSettings settings;
    settings.mRandomSectionWidth = 0.0;
    settings.mRandomSectionHeight = 0.0;
    settings.mHorizontalEdgeFrequency = 0.0;
    settings.mVerticalEdgeFrequency = 0.0;
    settings.mHorizontalEdgeAmplitude = 0.0;
    settings.mVerticalEdgeAmplitude = 0.0;
    TetGridSettings grid;
    grid.mOrigin = Vec3(0.3, -0.2, 1.0);
    grid.mSize = Vec3(0.1, 0.9, 0.7); // width along y, height along z, thickness along x
    grid.mCellCount = {{2, 3, 2}};
    const Prop prop = MakeProp(grid, settings);
    CHECK(prop.mEdges.GetAxes() == std::array<int, 3>{{1, 2, 0}});
    const EmbeddedMesh& mesh = prop.mEdges.GetEmbeddedMesh();
    CHECK(std::abs(CheckSections(prop) - 0.1 * 0.9 * 0.7) < 1e-9 * 0.1 * 0.9 * 0.7);

    std::vector<Vec3> normals;
    REQUIRE(TriangleNormals(mesh.GetRestPositions(), mesh.GetTriangles(), normals).IsValid());
    for (const EdgeSection& section : prop.mEdges.GetSections())
    {
        // Eight vertices, each bitwise on a grid node of the section's own cell.
        REQUIRE(section.mOutlineCount == 4);
        CHECK(section.mCorners == std::array<int, 4>{{0, 1, 2, 3}});
        for (int vertex = section.mFirstVertex; vertex < section.mFirstVertex + 8; ++vertex)
        {
            bool on_node = false;
            for (int di = 0; di < 2; ++di)
                for (int dj = 0; dj < 2; ++dj)
                    for (int dk = 0; dk < 2; ++dk)
                    {
                        const int node = TetGridNode(grid.mCellCount, section.mCell[0] + di,
                                                     section.mCell[1] + dj, section.mCell[2] + dk);
                        on_node =
                            on_node || mesh.GetRestPositions()[vertex] == prop.mMesh.GetRestPositions()[node];
                    }
            CHECK(on_node);
        }
        // Exactly the cell volume; caps face +-x (the thickness), two triangles each.
        const double cell = 0.05 * 0.3 * 0.35;
        CHECK(EnclosedVolume(mesh, section.mFirstTriangle, section.mTriangleCount) ==
              Approx(cell).epsilon(1e-12));
        for (int cap = 0; cap < 2; ++cap)
        {
            CHECK((normals[section.mFirstTriangle + cap] - Vec3::UnitX()).norm() < 1e-15);
            CHECK((normals[section.mFirstTriangle + 2 + cap] + Vec3::UnitX()).norm() < 1e-15);
        }
    }
}

TEST_CASE("ProceduralEdgeMesh inserts round(f L) vertices per interior edge, within the amplitude", "[fem]")
{
    // 4 x 3 cells of 0.4 x 0.3 m in the xy-plane; no jitter, so the nominal edges are the lattice lines.
    ProceduralEdgeSettings settings;
    settings.mAverageSectionWidth = 0.4;
    settings.mAverageSectionHeight = 0.3;
    settings.mRandomSectionWidth = 0.0;
    settings.mRandomSectionHeight = 0.0;
    settings.mHorizontalEdgeFrequency = 7.3; // 7.3 x 0.4 = 2.92 -> 3 per horizontal edge
    settings.mVerticalEdgeFrequency = 6.0;   // 6 x 0.3 = 1.8 -> 2 per vertical edge
    settings.mHorizontalEdgeAmplitude = 0.02;
    settings.mVerticalEdgeAmplitude = 0.03;
    settings.mSeed = 9;
    const TetGridSettings grid = WallGrid(Vec3::Zero(), Vec3(1.6, 0.9, 0.05), settings);
    REQUIRE(grid.mCellCount == std::array<int, 3>{{4, 3, 1}});
    const Prop prop = MakeProp(grid, settings);
    const EmbeddedMesh& mesh = prop.mEdges.GetEmbeddedMesh();
    CheckSections(prop);

    // The inserted vertices of side inSide (0 bottom, 1 right, 2 top, 3 left) of section inSection, in
    // outline order.
    const auto side = [&](const EdgeSection& inSection, int inSide)
    {
        std::vector<Vec3> points;
        const int begin = inSection.mCorners[inSide] + 1;
        const int end = inSide == 3 ? inSection.mOutlineCount : inSection.mCorners[inSide + 1];
        for (int at = begin; at < end; ++at)
            points.push_back(mesh.GetRestPositions()[inSection.mFirstVertex + at]);
        return points;
    };

    double largest_h = 0.0;
    double largest_v = 0.0;
    for (const EdgeSection& section : prop.mEdges.GetSections())
    {
        const int i = section.mCell[0];
        const int j = section.mCell[1];
        const std::array<bool, 4> interior{{j > 0, i < 3, j<2, i> 0}};
        for (int s = 0; s < 4; ++s)
        {
            const std::vector<Vec3> points = side(section, s);
            const bool horizontal = s == 0 || s == 2;
            CHECK(static_cast<int>(points.size()) == (interior[s] ? (horizontal ? 3 : 2) : 0));
            for (const Vec3& point : points)
            {
                // Offset across the nominal edge within the amplitude, along it strictly inside the cell
                // side.
                if (horizontal)
                {
                    const double offset = std::abs(point.y() - 0.3 * (j + (s == 2 ? 1 : 0)));
                    CHECK(offset <= 0.02);
                    largest_h = std::max(largest_h, offset);
                    CHECK(point.x() > 0.4 * i);
                    CHECK(point.x() < 0.4 * (i + 1));
                }
                else
                {
                    const double offset = std::abs(point.x() - 0.4 * (i + (s == 1 ? 1 : 0)));
                    CHECK(offset <= 0.03);
                    largest_v = std::max(largest_v, offset);
                    CHECK(point.y() > 0.3 * j);
                    CHECK(point.y() < 0.3 * (j + 1));
                }
            }
        }

        // Shared edges: the top side of (i, j) is the bottom side of (i, j + 1) reversed, bitwise; the same
        // for right and left. Front and back outlines coincide in the wall plane.
        if (j < 2)
        {
            const EdgeSection& above = prop.mEdges.GetSections()[i + 4 * (j + 1)];
            std::vector<Vec3> top = side(section, 2);
            std::vector<Vec3> bottom = side(above, 0);
            std::reverse(bottom.begin(), bottom.end());
            REQUIRE(top.size() == bottom.size());
            for (std::size_t at = 0; at < top.size(); ++at)
                CHECK(top[at].head<2>() == bottom[at].head<2>());
        }
        if (i < 3)
        {
            const EdgeSection& beside = prop.mEdges.GetSections()[(i + 1) + 4 * j];
            std::vector<Vec3> right = side(section, 1);
            std::vector<Vec3> left = side(beside, 3);
            std::reverse(left.begin(), left.end());
            REQUIRE(right.size() == left.size());
            for (std::size_t at = 0; at < right.size(); ++at)
                CHECK(right[at].head<2>() == left[at].head<2>());
        }
    }
    // The offsets are used, not all tiny.
    CHECK(largest_h > 0.5 * 0.02);
    CHECK(largest_v > 0.5 * 0.03);
}

TEST_CASE("ProceduralEdgeMesh follows rigid and affine motions of the tet nodes exactly", "[fem]")
{
    const ProceduralEdgeSettings settings = RoughSettings(5);
    const Prop prop = MakeProp(WallGrid(Vec3(0.5, 0.0, -0.3), Vec3(1.6, 0.9, 0.1), settings), settings);
    const EmbeddedMesh& mesh = prop.mEdges.GetEmbeddedMesh();
    const std::vector<Vec3>& rest = mesh.GetRestPositions();

    // Rest nodes give the rest display mesh.
    std::vector<Vec3> moved;
    REQUIRE(mesh.Update(prop.mMesh.GetTets(), prop.mMesh.GetRestPositions(), moved).IsValid());
    for (int vertex = 0; vertex < mesh.GetVertexCount(); ++vertex)
        CHECK((moved[vertex] - rest[vertex]).norm() < 1e-14);

    // Rotation + translation.
    const Mat3 rotation = Eigen::AngleAxisd(2.1, Vec3(0.3, 1.0, -0.4).normalized()).toRotationMatrix();
    const Vec3 translation(-5.0, 2.0, 7.5);
    std::vector<Vec3> nodes = prop.mMesh.GetRestPositions();
    for (Vec3& node : nodes)
        node = rotation * node + translation;
    REQUIRE(mesh.Update(prop.mMesh.GetTets(), nodes, moved).IsValid());
    double worst = 0.0;
    for (int vertex = 0; vertex < mesh.GetVertexCount(); ++vertex)
        worst = std::max(worst, (moved[vertex] - (rotation * rest[vertex] + translation)).norm());
    CHECK(worst < 1e-12);

    // A general affine map.
    Mat3 affine;
    affine << 0.9, 0.3, 0.0, -0.2, 1.2, 0.1, 0.05, 0.0, 0.7;
    const Vec3 offset(1.0, -1.0, 0.25);
    nodes = prop.mMesh.GetRestPositions();
    for (Vec3& node : nodes)
        node = affine * node + offset;
    REQUIRE(mesh.Update(prop.mMesh.GetTets(), nodes, moved).IsValid());
    worst = 0.0;
    for (int vertex = 0; vertex < mesh.GetVertexCount(); ++vertex)
        worst = std::max(worst, (moved[vertex] - (affine * rest[vertex] + offset)).norm());
    CHECK(worst < 1e-12);
}

TEST_CASE("ProceduralEdgeMesh vertices follow a duplicated node only through their own element", "[fem]")
{
    const ProceduralEdgeSettings settings = RoughSettings(6);
    const Prop prop = MakeProp(WallGrid(Vec3::Zero(), Vec3(1.2, 0.6, 0.1), settings), settings);
    const EmbeddedMesh& mesh = prop.mEdges.GetEmbeddedMesh();

    // Element 7 (cell 1) gets its own copy of its corner 0, moved 5 cm.
    const int element = 7;
    std::vector<TetIndices> tets = prop.mMesh.GetTets();
    std::vector<Vec3> nodes = prop.mMesh.GetRestPositions();
    const Vec3 displacement(0.0, 0.0, 0.05);
    nodes.push_back(nodes[tets[element][0]] + displacement);
    tets[element][0] = static_cast<int>(nodes.size()) - 1;

    std::vector<Vec3> moved;
    REQUIRE(mesh.Update(tets, nodes, moved).IsValid());
    std::vector<Vec3> reference; // the same update without the duplicated node
    REQUIRE(mesh.Update(prop.mMesh.GetTets(), prop.mMesh.GetRestPositions(), reference).IsValid());
    int bound = 0;
    int others_moved = 0;
    for (int vertex = 0; vertex < mesh.GetVertexCount(); ++vertex)
    {
        const EmbeddedVertex& binding = mesh.GetVertices()[vertex];
        const Vec3 expected =
            mesh.GetRestPositions()[vertex] +
            (binding.mElement == element ? Vec3(binding.mWeights[0] * displacement) : Vec3::Zero());
        CHECK((moved[vertex] - expected).norm() < 1e-14);
        bound += binding.mElement == element ? 1 : 0;
        others_moved += binding.mElement != element && moved[vertex] != reference[vertex] ? 1 : 0; // bitwise
    }
    CHECK(bound > 0);
    CHECK(others_moved == 0);
}

TEST_CASE("ProceduralEdgeMesh refuses invalid settings, grids and meshes", "[fem]")
{
    const Vec3 size(1.6, 0.9, 0.1);
    const ProceduralEdgeSettings good = RoughSettings(1);
    const TetGridSettings grid = WallGrid(Vec3::Zero(), size, good);
    const TetMesh mesh = TetGrid(grid).Get();
    REQUIRE(ProceduralEdgeMesh::Create(grid, mesh, good).IsValid());
    const auto refused = [&](const TetGridSettings& inGrid, const TetMesh& inMesh,
                             const ProceduralEdgeSettings& inSettings, const std::string& inWords)
    {
        const Result<ProceduralEdgeMesh> result = ProceduralEdgeMesh::Create(inGrid, inMesh, inSettings);
        REQUIRE(result.HasError());
        INFO(result.GetError().mMessage);
        CHECK(result.GetError().mMessage.find(inWords) != std::string::npos);
    };

    ProceduralEdgeSettings settings = good;
    settings.mRandomSectionHeight = std::numeric_limits<double>::quiet_NaN();
    refused(grid, mesh, settings, "mRandomSectionHeight");
    settings = good;
    settings.mAverageSectionWidth = -0.4;
    refused(grid, mesh, settings, "mAverageSectionWidth");
    settings = good;
    settings.mRandomSectionWidth = 0.45;
    refused(grid, mesh, settings, "mRandomSectionWidth");
    settings = good;
    settings.mVerticalEdgeAmplitude = 0.2;
    refused(grid, mesh, settings, "mVerticalEdgeAmplitude");

    // Valid against the average height, too large for the actual 0.1 m cells of a low wall.
    settings = good;
    settings.mRandomSectionHeight = 0.15;
    settings.mHorizontalEdgeAmplitude = 0.03; // <= 0.4 x 0.7 x 0.3 = 0.084, > 0.4 x 0.7 x 0.1 = 0.028
    REQUIRE(ValidateProceduralEdgeSettings(settings).IsValid());
    TetGridSettings low = grid;
    low.mSize = Vec3(1.6, 0.1, 0.05);
    low.mCellCount = {{4, 1, 1}};
    refused(low, TetGrid(low).Get(), settings, "mHorizontalEdgeAmplitude");

    // Invalid grids, and a mesh that is not the grid's.
    TetGridSettings bad = grid;
    bad.mCellCount[0] = 0;
    refused(bad, mesh, good, "mCellCount[0]");
    bad = grid;
    bad.mSize.y() = -0.9;
    refused(bad, mesh, good, "mSize");
    bad = grid;
    bad.mCellCount[1] += 1;
    refused(bad, mesh, good, "the mesh has");
}
