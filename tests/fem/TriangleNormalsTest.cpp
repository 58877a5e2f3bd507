// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/TriangleNormals.h>

#include <catch2/catch.hpp>

using namespace crumple;
using namespace crumple::fem;

TEST_CASE("TriangleNormals gives unit normals on the counter-clockwise side", "[fem]")
{
    const std::vector<Vec3> positions{Vec3(0.0, 0.0, 0.0), Vec3(2.0, 0.0, 0.0), Vec3(0.0, 3.0, 0.0),
                                      Vec3(0.0, 0.0, 5.0), Vec3(4.0, 0.0, 0.0)};
    const std::vector<TriangleIndices> triangles{
        {{0, 1, 2}}, {{0, 2, 1}}, {{0, 3, 1}}, {{1, 2, 3}}, {{0, 1, 4}}};
    std::vector<Vec3> normals;
    REQUIRE(TriangleNormals(positions, triangles, normals).IsValid());
    REQUIRE(normals.size() == 5);
    CHECK(normals[0] == Vec3(0.0, 0.0, 1.0));
    CHECK(normals[1] == Vec3(0.0, 0.0, -1.0));
    CHECK(normals[2] == Vec3(0.0, 1.0, 0.0));
    // Plane x/2 + y/3 + z/5 = 1: normal (1/2, 1/3, 1/5) normalised.
    CHECK((normals[3] - Vec3(0.5, 1.0 / 3.0, 0.2).normalized()).norm() < 1e-15);
    // Three collinear points: zero area, zero normal.
    CHECK(normals[4] == Vec3::Zero());
}

TEST_CASE("TriangleNormals refuses an index out of range", "[fem]")
{
    const std::vector<Vec3> positions{Vec3::Zero(), Vec3::UnitX(), Vec3::UnitY()};
    std::vector<Vec3> normals{Vec3::Zero()};
    const std::vector<TriangleIndices> triangles{{{0, 1, 2}}, {{0, 1, 3}}};
    const Status status = TriangleNormals(positions, triangles, normals);
    REQUIRE(status.HasError());
    CHECK(status.GetError().mMessage.find("triangle 1 names vertex 3") != std::string::npos);
    CHECK(normals.empty());
}
