// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Result.h>
#include <crumple/ffd/RefineLongEdges.h>
#include <crumple/ffd/TriangleMesh.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace crumple::samples
{

/// A signed axis of a mesh file's frame.
enum class EMeshAxis : std::uint8_t
{
    PlusX,
    MinusX,
    PlusY,
    MinusY,
    PlusZ,
    MinusZ,
};

/// "+x", "-x", "+y", "-y", "+z", "-z" in EMeshAxis order (scenario files spell axes so).
inline constexpr std::string_view cMeshAxisNames[] = {"+x", "-x", "+y", "-y", "+z", "-z"};

/// The rotation from a file's frame to the body frame that takes the file's inForward to +x and inUp to +z
/// (and so up x forward, the left, to +y). An error when the two are the same axis or opposite.
Result<Mat3> FileToBodyRotation(EMeshAxis inForward, EMeshAxis inUp);

/// How to turn a mesh file into a car body in Crumple's body frame (x forward, y left, z up, metres,
/// centred on its bounding box).
struct CarMeshSettings
{
    std::filesystem::path mPath;  ///< OBJ, glTF/GLB, PLY, FBX... anything assimp reads
    std::string mMeshName;        ///< Only meshes whose node or mesh name contains this (empty: all)
    Mat3 mFileToBody = Mat3::Identity(); ///< Rotation from the file's axes to x forward, z up
    double mLength = 4.2;         ///< Scaled so the body is this long along x (m), unless mUnit is set
    double mUnit = 0.0;           ///< Metres per file unit (0.0254 for inches), > 0; 0: scale to mLength instead
    /// Meshes whose node or mesh name contains one of these (any case) are rigid parts of the body
    /// (ffd::FfdDeformerSettings::mRigidParts), one per connected piece of such a mesh (a mesh of both rear
    /// wheels gives two): wheels keep their shape when a crush reaches them. A fragment also matches longer
    /// names ("WheelArch"): name such meshes out with a longer fragment list. Empty: none.
    std::vector<std::string> mRigidPartNames{"wheel", "tire", "tyre"};
};

/// A loaded car body: its mesh, and the vertices of each rigid part (CarMeshSettings::mRigidPartNames).
struct CarBody
{
    ffd::TriangleMesh mMesh;
    std::vector<std::vector<std::uint32_t>> mRigidParts; ///< Vertex indices of each part, in file order
    std::vector<std::string> mRigidPartNames;            ///< The node (or mesh) name of each part that matched
    /// The fragments of CarMeshSettings::mRigidPartNames that no node's or mesh's name (of the wanted meshes,
    /// with vertices) contains: a typo in a scenario's list, or a mesh without such parts
    std::vector<std::string> mUnmatchedRigidPartNames;
};

/// Empty when the body's x extent (the stated forward axis) is its longest one; otherwise why a car loaded so
/// has its axes wrong, with the extents: taller than long (its height, the stated up axis, is its longest
/// extent: a z-forward, y-up file read with z up), or wider than long (probably sideways: a y-forward file
/// read as x-forward).
std::string ForwardAxisWarning(const ffd::TriangleMesh& inBody);

/// The shipped Khronos Toy Car (CC0) as a 4.2 m car: its "ToyCar" body mesh, Y up and Z forward in the file.
CarMeshSettings ToyCarMesh(const std::filesystem::path& inSharedData);

/// Loads and transforms a car body mesh with assimp (each mesh's identical vertices joined), centred on its
/// bounding box, scaled by mUnit or to mLength, with the vertices of its rigid parts. A missing or unreadable
/// file, one without the named mesh, or a bad mUnit or mLength is an error with the reason.
Result<CarBody> LoadCarBody(const CarMeshSettings& inSettings);
/// LoadCarBody's mesh alone.
Result<ffd::TriangleMesh> LoadCarMesh(const CarMeshSettings& inSettings);

/// inParts' vertex lists after ffd::RefineLongEdges or ffd::SplitCaps: a vertex added on the edge between two
/// vertices of one part joins that part (a part's edges join its own vertices only, so nothing else changes).
std::vector<std::vector<std::uint32_t>> PartsAfterRefinement(const std::vector<std::vector<std::uint32_t>>& inParts,
                                                             const ffd::RefinedMesh& inRefined);

/// Where the project's shared data folder is: CRUMPLE_SHARED_DATA if set, else ../shared/data beside the
/// source tree.
std::filesystem::path SharedDataFolder();

} // namespace crumple::samples
