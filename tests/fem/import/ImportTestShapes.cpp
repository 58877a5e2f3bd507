// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "ImportTestShapes.h"

#include "ScratchDirectory.h"

#include <cmath>
#include <fstream>
#include <map>

namespace crumple::fem::test
{

std::filesystem::path FreshFolder(const std::string& inName)
{
    const std::filesystem::path folder = common::ScratchDirectory() / inName;
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    return folder;
}

SurfaceMesh Icosphere(const Vec3& inCentre, double inRadius, int inSubdivisions)
{
    // The icosahedron: (0, +-1, +-g) and its cyclic permutations, g the golden ratio.
    const double g = (1.0 + std::sqrt(5.0)) / 2.0;
    std::vector<Vec3> unit = {Vec3(-1, g, 0), Vec3(1, g, 0), Vec3(-1, -g, 0), Vec3(1, -g, 0),
                              Vec3(0, -1, g), Vec3(0, 1, g), Vec3(0, -1, -g), Vec3(0, 1, -g),
                              Vec3(g, 0, -1), Vec3(g, 0, 1), Vec3(-g, 0, -1), Vec3(-g, 0, 1)};
    for (Vec3& p : unit)
        p.normalize();
    std::vector<TriangleIndices> triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                              {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                              {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                              {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};

    // Split each triangle into four at its edge midpoints, shared between neighbours.
    for (int level = 0; level < inSubdivisions; ++level)
    {
        std::map<std::pair<int, int>, int> midpoints;
        auto midpoint = [&](int inA, int inB)
        {
            const std::pair<int, int> key(std::min(inA, inB), std::max(inA, inB));
            const auto found = midpoints.find(key);
            if (found != midpoints.end())
                return found->second;
            unit.push_back((unit[inA] + unit[inB]).normalized());
            midpoints[key] = static_cast<int>(unit.size()) - 1;
            return static_cast<int>(unit.size()) - 1;
        };
        std::vector<TriangleIndices> finer;
        for (const TriangleIndices& t : triangles)
        {
            const int ab = midpoint(t[0], t[1]);
            const int bc = midpoint(t[1], t[2]);
            const int ca = midpoint(t[2], t[0]);
            finer.push_back({t[0], ab, ca});
            finer.push_back({t[1], bc, ab});
            finer.push_back({t[2], ca, bc});
            finer.push_back({ab, bc, ca});
        }
        triangles = std::move(finer);
    }

    SurfaceMesh mesh;
    for (const Vec3& p : unit)
        mesh.mPositions.push_back(inCentre + inRadius * p);
    mesh.mTriangles = std::move(triangles);
    return mesh;
}

std::string UnitCubeObj(int inMissingFaces)
{
    // Corners 1..8 (OBJ is 1-based), one normal per face, faces counter-clockwise seen from outside.
    std::string text = "# unit cube\n"
                       "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                       "vn 0 0 -1\nvn 0 0 1\nvn 0 -1 0\nvn 1 0 0\nvn 0 1 0\nvn -1 0 0\n";
    const char* faces[6] = {"f 1//1 4//1 3//1 2//1\n", "f 5//2 6//2 7//2 8//2\n", "f 1//3 2//3 6//3 5//3\n",
                            "f 2//4 3//4 7//4 6//4\n", "f 3//5 4//5 8//5 7//5\n", "f 4//6 1//6 5//6 8//6\n"};
    for (int face = 0; face < 6 - inMissingFaces; ++face)
    {
        if (face == 0)
            text += "o bottom_half\n";
        if (face == 3)
            text += "o top_half\n";
        text += faces[face];
    }
    return text;
}

void WriteText(const std::filesystem::path& inPath, const std::string& inText)
{
    std::ofstream(inPath, std::ios::binary | std::ios::trunc) << inText;
}

void WriteFakeTetgen(const std::filesystem::path& inPath, const std::filesystem::path& inMarker)
{
    WriteText(inPath, "#!/bin/sh\ntouch '" + inMarker.string() + "'\necho 'fake tetgen ran'\nexit 3\n");
    std::filesystem::permissions(inPath, std::filesystem::perms::owner_all);
}

} // namespace crumple::fem::test
