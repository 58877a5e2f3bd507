// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Result.h>
#include <crumple/ffd/TriangleMesh.h>

#include <filesystem>
#include <string>

namespace crumple::samples
{

/// How to turn a mesh file into a car body in Crumple's body frame (x forward, y left, z up, metres,
/// centred on its bounding box).
struct CarMeshSettings
{
    std::filesystem::path mPath;  ///< OBJ, glTF/GLB, PLY, FBX... anything assimp reads
    std::string mMeshName;        ///< Only meshes whose node or mesh name contains this (empty: all)
    Mat3 mFileToBody = Mat3::Identity(); ///< Rotation from the file's axes to x forward, z up
    double mLength = 4.2;         ///< Scaled so the body is this long along x (m)
};

/// The shipped Khronos Toy Car (CC0) as a 4.2 m car: its "ToyCar" body mesh, Y up and Z forward in the file.
CarMeshSettings ToyCarMesh(const std::filesystem::path& inSharedData);

/// Loads, transforms and welds a car body mesh with assimp. A missing or unreadable file, or one without
/// the named mesh, is an error with the reason.
Result<ffd::TriangleMesh> LoadCarMesh(const CarMeshSettings& inSettings);

/// Where the project's shared data folder is: CRUMPLE_SHARED_DATA if set, else ../shared/data beside the
/// source tree.
std::filesystem::path SharedDataFolder();

} // namespace crumple::samples
