// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/fem/SurfaceMesh.h>

#include <filesystem>
#include <string>

namespace crumple::fem::test
{

/// A folder of this process for the import tests, emptied on each call with a new name.
std::filesystem::path FreshFolder(const std::string& inName);

/// The closed icosphere of radius inRadius (m) around inCentre: an icosahedron with each triangle split into
/// four inSubdivisions times, vertices pushed onto the sphere; outward triangles, 10 4^s + 2 vertices, 20 4^s
/// triangles.
SurfaceMesh Icosphere(const Vec3& inCentre, double inRadius, int inSubdivisions);

/// The text of a Wavefront OBJ of the unit cube [0, 1]^3 as a modeller writes it: two objects ("o"), quads
/// with per-face normals ("f a//n ..."), so loading must triangulate, merge meshes and join corners across
/// normals. inMissingFace > 0 leaves out that many of the six faces (an open surface).
std::string UnitCubeObj(int inMissingFaces = 0);

/// Writes inText to inPath.
void WriteText(const std::filesystem::path& inPath, const std::string& inText);

/// A shell script at inPath standing in for tetgen: it creates inMarker, prints "fake tetgen ran", exits 3.
/// It proves whether Tetrahedralize ran the program.
void WriteFakeTetgen(const std::filesystem::path& inPath, const std::filesystem::path& inMarker);

} // namespace crumple::fem::test
