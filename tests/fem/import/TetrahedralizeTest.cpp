// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "ImportTestShapes.h"

#include <crumple/fem/SurfaceFile.h>
#include <crumple/fem/SurfaceVolume.h>
#include <crumple/fem/TetBoundary.h>
#include <crumple/fem_import/ImportTetMesh.h>
#include <crumple/fem_import/LoadSurfaceMesh.h>
#include <crumple/fem_import/Tetrahedralize.h>
#include <crumple/fem_import/TetgenOutput.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstring>
#include <limits>
#include <sstream>

using namespace crumple;
using namespace crumple::fem;

namespace
{

// Settings whose scratch folders go into inTemporary, so that a test can see what is left behind.
TetgenSettings SettingsIn(const std::filesystem::path& inTemporary)
{
    TetgenSettings settings;
    settings.mTemporaryDirectory = inTemporary;
    return settings;
}

bool IsEmptyFolder(const std::filesystem::path& inFolder)
{
    return std::filesystem::is_directory(inFolder) && std::filesystem::is_empty(inFolder);
}

// A mesh of a closed surface: the volume and the surface vertices are the surface's.
void CheckFills(const TetMesh& inMesh, const SurfaceMesh& inSurface)
{
    const double enclosed = SurfaceVolume(inSurface.mPositions, inSurface.mTriangles);
    CHECK(inMesh.GetTotalVolume() == Approx(enclosed).epsilon(1e-9));
    REQUIRE(inMesh.GetNodeCount() >= static_cast<int>(inSurface.mPositions.size()));
    for (std::size_t vertex = 0; vertex < inSurface.mPositions.size(); ++vertex)
        CHECK(inMesh.GetRestPositions()[vertex] == inSurface.mPositions[vertex]);
    for (int tet = 0; tet < inMesh.GetTetCount(); ++tet)
        CHECK(inMesh.GetRestVolume(tet) > 0.0);
    // Its own boundary encloses the same volume, outward.
    const std::vector<TriangleIndices> boundary = TetBoundary(inMesh.GetTets());
    CHECK(SurfaceVolume(inMesh.GetRestPositions(), boundary) == Approx(enclosed).epsilon(1e-9));
}

// Sorted node triples, sorted: a triangle set regardless of order and winding.
std::vector<std::array<int, 3>> SortedFaces(const std::vector<TriangleIndices>& inTriangles)
{
    std::vector<std::array<int, 3>> faces;
    for (TriangleIndices triangle : inTriangles)
    {
        std::sort(triangle.begin(), triangle.end());
        faces.push_back(triangle);
    }
    std::sort(faces.begin(), faces.end());
    return faces;
}

double LargestElement(const TetMesh& inMesh)
{
    double largest = 0.0;
    for (int tet = 0; tet < inMesh.GetTetCount(); ++tet)
        largest = std::max(largest, inMesh.GetRestVolume(tet));
    return largest;
}

bool SameMesh(const TetMesh& inA, const TetMesh& inB)
{
    return inA.GetTets() == inB.GetTets() && inA.GetNodeCount() == inB.GetNodeCount() &&
           std::memcmp(inA.GetRestPositions().data(), inB.GetRestPositions().data(),
                       sizeof(Vec3) * inA.GetRestPositions().size()) == 0;
}

} // namespace

TEST_CASE("ImportTetMesh fills a unit cube OBJ exactly, the same way twice", "[fem][import][tetgen]")
{
    const std::filesystem::path folder = test::FreshFolder("tetgen-cube");
    const std::filesystem::path temporary = test::FreshFolder("tetgen-cube-tmp");
    test::WriteText(folder / "cube.obj", test::UnitCubeObj());
    const SurfaceMesh surface = LoadSurfaceMesh(folder / "cube.obj").Get();

    Result<TetMesh> first = ImportTetMesh(folder / "cube.obj", SettingsIn(temporary));
    INFO((first.HasError() ? first.GetError().mMessage : std::string()));
    REQUIRE(first.IsValid());
    CheckFills(first.Get(), surface);
    CHECK(first.Get().GetTotalVolume() == Approx(1.0).epsilon(1e-12));

    Result<TetMesh> second = ImportTetMesh(folder / "cube.obj", SettingsIn(temporary));
    REQUIRE(second.IsValid());
    CHECK(SameMesh(first.Get(), second.Get()));
    CHECK(IsEmptyFolder(temporary));
    WARN("unit cube: " << first.Get().GetNodeCount() << " nodes, " << first.Get().GetTetCount()
                       << " elements");
}

TEST_CASE(
    "ImportTetMesh fills an icosphere PLY, refined by a volume bound, with and without its surface kept",
    "[fem][import][tetgen]")
{
    const SurfaceMesh sphere = test::Icosphere(Vec3(-0.4, 0.25, 2.0), 0.15, 2);
    CHECK(SurfaceVolume(sphere.mPositions, sphere.mTriangles) ==
          Approx(4.0 / 3.0 * 3.14159265358979 * 0.15 * 0.15 * 0.15).epsilon(0.05));
    const std::filesystem::path folder = test::FreshFolder("tetgen-sphere");
    const std::filesystem::path temporary = test::FreshFolder("tetgen-sphere-tmp");
    REQUIRE(SaveSurfacePly(folder / "sphere.ply", sphere.mPositions, sphere.mTriangles).IsValid());
    const SurfaceMesh surface = LoadSurfaceMesh(folder / "sphere.ply").Get();

    // No volume bound: the coarsest mesh tetgen makes at the default quality.
    TetgenSettings coarse_settings = SettingsIn(temporary);
    Result<TetMesh> coarse = ImportTetMesh(folder / "sphere.ply", coarse_settings);
    REQUIRE(coarse.IsValid());
    CheckFills(coarse.Get(), surface);
    const double coarse_largest = LargestElement(coarse.Get());

    for (const bool keep : {true, false})
    {
        INFO("mKeepSurface " << keep);
        TetgenSettings settings = SettingsIn(temporary);
        settings.mMaxVolume = 2.0e-5;
        settings.mKeepSurface = keep;
        Result<TetMesh> mesh = ImportTetMesh(folder / "sphere.ply", settings);
        INFO((mesh.HasError() ? mesh.GetError().mMessage : std::string()));
        REQUIRE(mesh.IsValid());
        CheckFills(mesh.Get(), surface);

        // The bound refines: more elements, their mean below it, the largest smaller than without it (tetgen
        // does not promise every element below it; see TetgenSettings::mMaxVolume).
        const double largest = LargestElement(mesh.Get());
        CHECK(mesh.Get().GetTetCount() > coarse.Get().GetTetCount());
        CHECK(mesh.Get().GetTotalVolume() / mesh.Get().GetTetCount() < settings.mMaxVolume);
        CHECK(largest < coarse_largest);

        // Kept: the boundary is the file's triangles. Not kept: tetgen split them.
        const std::vector<TriangleIndices> boundary = TetBoundary(mesh.Get().GetTets());
        if (keep)
            CHECK(SortedFaces(boundary) == SortedFaces(surface.mTriangles));
        else
            CHECK(boundary.size() > surface.mTriangles.size());

        Result<TetMesh> again = ImportTetMesh(folder / "sphere.ply", settings);
        REQUIRE(again.IsValid());
        CHECK(SameMesh(mesh.Get(), again.Get()));
        WARN("icosphere (162 vertices), mKeepSurface "
             << keep << ": " << mesh.Get().GetNodeCount() << " nodes, " << mesh.Get().GetTetCount()
             << " elements, " << boundary.size() << " boundary triangles, largest " << largest << " m^3 ("
             << coarse.Get().GetTetCount() << " elements, largest " << coarse_largest
             << " m^3 without the bound)");
    }
    CHECK(IsEmptyFolder(temporary));
}

TEST_CASE("Tetrahedralize says clearly when tetgen is not installed", "[fem][import]")
{
    const std::filesystem::path temporary = test::FreshFolder("tetgen-missing-tmp");
    const SurfaceMesh sphere = test::Icosphere(Vec3::Zero(), 1.0, 0);
    TetgenSettings settings = SettingsIn(temporary);
    settings.mExecutable = "/nonexistent/tetgen";
    Result<TetMesh> mesh = Tetrahedralize(sphere, settings);
    REQUIRE(mesh.HasError());
    CHECK(mesh.GetError().mCode == EError::IoError);
    CHECK(mesh.GetError().mMessage == "tetgen not found (looked for '/nonexistent/tetgen'): install Debian's "
                                      "tetgen package (apt-get install "
                                      "tetgen) or set TetgenSettings::mExecutable");

    settings.mExecutable = "crumple-no-such-tetgen";
    mesh = Tetrahedralize(sphere, settings);
    REQUIRE(mesh.HasError());
    CHECK(mesh.GetError().mMessage == "tetgen not found (looked for 'crumple-no-such-tetgen' on PATH): "
                                      "install Debian's tetgen package (apt-get "
                                      "install tetgen) or set TetgenSettings::mExecutable");
    CHECK(IsEmptyFolder(temporary));
}

TEST_CASE("Open and corrupt input is refused without running tetgen", "[fem][import]")
{
    const std::filesystem::path folder = test::FreshFolder("tetgen-refused");
    const std::filesystem::path temporary = test::FreshFolder("tetgen-refused-tmp");
    const std::filesystem::path marker = folder / "tetgen-ran";
    TetgenSettings settings = SettingsIn(temporary);
    settings.mExecutable = (folder / "fake-tetgen").string();
    test::WriteFakeTetgen(settings.mExecutable, marker);

    // An open surface, directly and from a file; a corrupt file.
    test::WriteText(folder / "open.obj", test::UnitCubeObj(1));
    Result<TetMesh> open_file = ImportTetMesh(folder / "open.obj", settings);
    REQUIRE(open_file.HasError());
    CHECK(open_file.GetError().mMessage.find("not closed") != std::string::npos);
    SurfaceMesh open = test::Icosphere(Vec3::Zero(), 1.0, 1);
    open.mTriangles.pop_back();
    Result<TetMesh> open_surface = Tetrahedralize(open, settings);
    REQUIRE(open_surface.HasError());
    CHECK(open_surface.GetError().mMessage.find("Tetrahedralize: surface is not closed: 3 of 120 edges") !=
          std::string::npos);
    test::WriteText(folder / "corrupt.stl", "solid broken\nfacet normal 0 0 1\nouter loop\nvertex 0 0\n");
    CHECK(ImportTetMesh(folder / "corrupt.stl", settings).HasError());

    // Bad settings.
    const SurfaceMesh closed = test::Icosphere(Vec3::Zero(), 1.0, 1);
    for (const double ratio : {1.0, -2.0, std::numeric_limits<double>::quiet_NaN()})
    {
        TetgenSettings bad = settings;
        bad.mMaxRadiusEdgeRatio = ratio;
        CHECK(Tetrahedralize(closed, bad).GetError().mCode == EError::InvalidArgument);
    }
    // A volume bound asking for more elements than a TetMesh holds (the unit sphere's 4 m^3 in pieces of
    // 1e-9 m^3), and the negative and infinite ones.
    for (const double volume : {-1.0, std::numeric_limits<double>::infinity(), 1.0e-9})
    {
        TetgenSettings bad = settings;
        bad.mMaxVolume = volume;
        CHECK(Tetrahedralize(closed, bad).GetError().mCode == EError::InvalidArgument);
    }
    CHECK(!std::filesystem::exists(marker));

    // The control: a closed surface does run the program, and its failure comes back with its output.
    Result<TetMesh> ran = Tetrahedralize(closed, settings);
    REQUIRE(ran.HasError());
    CHECK(std::filesystem::exists(marker));
    CHECK(ran.GetError().mCode == EError::DegenerateGeometry);
    CHECK(ran.GetError().mMessage.find("tetgen failed (exit status 3)") != std::string::npos);
    CHECK(ran.GetError().mMessage.find("fake tetgen ran") != std::string::npos);
    CHECK(IsEmptyFolder(temporary));

    // A temporary folder that does not exist.
    TetgenSettings nowhere;
    nowhere.mTemporaryDirectory = folder / "no" / "such" / "folder";
    CHECK(Tetrahedralize(closed, nowhere).GetError().mCode == EError::IoError);
}

TEST_CASE("Tetrahedralize reports tetgen's own failure on a self-intersecting surface",
          "[fem][import][tetgen]")
{
    // Two closed spheres that overlap: each is closed, together they intersect.
    SurfaceMesh pair = test::Icosphere(Vec3::Zero(), 1.0, 1);
    const SurfaceMesh other = test::Icosphere(Vec3(0.5, 0.1, 0.05), 1.0, 1);
    const int offset = static_cast<int>(pair.mPositions.size());
    pair.mPositions.insert(pair.mPositions.end(), other.mPositions.begin(), other.mPositions.end());
    for (TriangleIndices t : other.mTriangles)
        pair.mTriangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    REQUIRE(ValidateClosedSurface(pair).IsValid());

    const std::filesystem::path temporary = test::FreshFolder("tetgen-intersect-tmp");
    Result<TetMesh> mesh = Tetrahedralize(pair, SettingsIn(temporary));
    REQUIRE(mesh.HasError());
    INFO(mesh.GetError().mMessage);
    const std::string& message = mesh.GetError().mMessage;
    CHECK(mesh.GetError().mCode == EError::DegenerateGeometry);
    CHECK(message.find("tetgen failed (") != std::string::npos);
    CHECK(message.find("the surface intersects itself (tetgen -d found ") != std::string::npos);

    // The example names two real triangles, one of each sphere.
    const std::size_t example = message.find("e.g. the triangle of vertices ");
    REQUIRE(example != std::string::npos);
    std::istringstream fields(message.substr(example + 30));
    std::array<int, 3> first{}, second{};
    char comma = 0;
    std::string skip;
    fields >> first[0] >> comma >> first[1] >> comma >> first[2];
    while (fields >> skip && skip != "vertices")
        ;
    fields >> second[0] >> comma >> second[1] >> comma >> second[2];
    REQUIRE(fields);
    const std::vector<std::array<int, 3>> faces = SortedFaces(pair.mTriangles);
    std::sort(first.begin(), first.end());
    std::sort(second.begin(), second.end());
    CHECK(std::binary_search(faces.begin(), faces.end(), first));
    CHECK(std::binary_search(faces.begin(), faces.end(), second));
    CHECK(((first[0] < offset) != (second[0] < offset)));
    CHECK(IsEmptyFolder(temporary));

    // Two disjoint spheres are fine: one mesh, two pieces.
    SurfaceMesh apart = test::Icosphere(Vec3::Zero(), 1.0, 1);
    const SurfaceMesh far = test::Icosphere(Vec3(3.0, 0.0, 0.0), 0.5, 1);
    apart.mPositions.insert(apart.mPositions.end(), far.mPositions.begin(), far.mPositions.end());
    for (TriangleIndices t : far.mTriangles)
        apart.mTriangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    Result<TetMesh> two = Tetrahedralize(apart, SettingsIn(temporary));
    INFO((two.HasError() ? two.GetError().mMessage : std::string()));
    REQUIRE(two.IsValid());
    CheckFills(two.Get(), apart);
    CHECK(IsEmptyFolder(temporary));
}

TEST_CASE("ParseTetgenOutput refuses a coordinate that is not finite, naming the node", "[fem][import]")
{
    const std::string elements = "1 4 0\n0 0 1 2 3\n";
    const std::string good = "4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n";
    REQUIRE(ParseTetgenOutput(good, elements).IsValid());
    for (const char* bad : {"nan", "inf", "-inf", "1e400"})
    {
        const std::string nodes = "4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 " + std::string(bad) + " 0\n3 0 0 1\n";
        const Result<TetgenOutput> parsed = ParseTetgenOutput(nodes, elements);
        INFO(bad << ": " << (parsed.HasError() ? parsed.GetError().mMessage : std::string("accepted")));
        REQUIRE(parsed.HasError());
        CHECK(parsed.GetError().mCode == EError::CorruptData);
    }
}
