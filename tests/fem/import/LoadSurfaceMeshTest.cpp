// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "ImportTestShapes.h"

#include <crumple/fem/SurfaceFile.h>
#include <crumple/fem/SurfaceVolume.h>
#include <crumple/fem_import/LoadSurfaceMesh.h>

#include <catch2/catch.hpp>

#include <cmath>

using namespace crumple;
using namespace crumple::fem;

TEST_CASE("LoadSurfaceMesh triangulates, merges meshes and joins corners of a modeller's OBJ",
          "[fem][import]")
{
    const std::filesystem::path path = test::FreshFolder("load-obj") / "cube.obj";
    test::WriteText(path, test::UnitCubeObj());
    Result<SurfaceMesh> loaded = LoadSurfaceMesh(path);
    INFO((loaded.HasError() ? loaded.GetError().mMessage : std::string()));
    REQUIRE(loaded.IsValid());
    const SurfaceMesh& cube = loaded.Get();

    // Six quads with their own normals in two objects: 8 shared corners, 12 triangles, closed, outward.
    CHECK(cube.mPositions.size() == 8);
    CHECK(cube.mTriangles.size() == 12);
    CHECK(ValidateClosedSurface(cube).IsValid());
    CHECK(SurfaceVolume(cube.mPositions, cube.mTriangles) == Approx(1.0).epsilon(1e-15));
    for (const Vec3& p : cube.mPositions)
        for (int axis = 0; axis < 3; ++axis)
            CHECK((p[axis] == 0.0 || p[axis] == 1.0));
}

TEST_CASE("LoadSurfaceMesh reads a binary PLY of doubles at float precision", "[fem][import]")
{
    const SurfaceMesh sphere = test::Icosphere(Vec3(0.3, -0.2, 1.1), 0.25, 2);
    REQUIRE(sphere.mPositions.size() == 162);
    REQUIRE(sphere.mTriangles.size() == 320);
    const std::filesystem::path path = test::FreshFolder("load-ply") / "sphere.ply";
    REQUIRE(SaveSurfacePly(path, sphere.mPositions, sphere.mTriangles).IsValid());

    Result<SurfaceMesh> loaded = LoadSurfaceMesh(path);
    INFO((loaded.HasError() ? loaded.GetError().mMessage : std::string()));
    REQUIRE(loaded.IsValid());
    // Same vertices in the same order, each the float nearest to the double written; same triangles.
    REQUIRE(loaded.Get().mPositions.size() == sphere.mPositions.size());
    for (std::size_t vertex = 0; vertex < sphere.mPositions.size(); ++vertex)
        for (int axis = 0; axis < 3; ++axis)
            CHECK(loaded.Get().mPositions[vertex][axis] ==
                  static_cast<double>(static_cast<float>(sphere.mPositions[vertex][axis])));
    CHECK(loaded.Get().mTriangles == sphere.mTriangles);
}

TEST_CASE("LoadSurfaceMesh refuses missing, corrupt, empty, non-finite and open files with clear messages",
          "[fem][import]")
{
    const std::filesystem::path folder = test::FreshFolder("load-refused");

    Result<SurfaceMesh> missing = LoadSurfaceMesh(folder / "nothing.obj");
    REQUIRE(missing.HasError());
    CHECK(missing.GetError().mCode == EError::IoError);
    CHECK(missing.GetError().mMessage.find("nothing.obj: no such file") != std::string::npos);

    // A PLY header that lies about its format: assimp's message comes through.
    test::WriteText(folder / "corrupt.ply",
                    "ply\nformat binary_big_endian 7.0\nelement vertex 99\nend_header\nxx");
    Result<SurfaceMesh> corrupt = LoadSurfaceMesh(folder / "corrupt.ply");
    REQUIRE(corrupt.HasError());
    CHECK(corrupt.GetError().mCode == EError::CorruptData);
    CHECK(corrupt.GetError().mMessage.find("corrupt.ply: cannot be read: ") != std::string::npos);
    CHECK(corrupt.GetError().mMessage.size() > std::string("corrupt.ply: cannot be read: ").size() + 5);

    // Lines only.
    test::WriteText(folder / "lines.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nl 2 3\n");
    Result<SurfaceMesh> lines = LoadSurfaceMesh(folder / "lines.obj");
    REQUIRE(lines.HasError());
    INFO(lines.GetError().mMessage);
    CHECK((lines.GetError().mCode == EError::DegenerateGeometry ||
           lines.GetError().mCode == EError::CorruptData));

    // The cube with one face missing: the four edges around the hole.
    test::WriteText(folder / "open.obj", test::UnitCubeObj(1));
    Result<SurfaceMesh> open = LoadSurfaceMesh(folder / "open.obj");
    REQUIRE(open.HasError());
    CHECK(open.GetError().mCode == EError::DegenerateGeometry);
    const std::string& message = open.GetError().mMessage;
    CHECK(message.find(
              "open.obj: surface is not closed: 4 of 17 edges are not used by exactly two triangles") !=
          std::string::npos);
    CHECK(message.find("used by 1 triangle") != std::string::npos);
}
