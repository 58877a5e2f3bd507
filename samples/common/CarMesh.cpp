// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "CarMesh.h"

#include <crumple/ffd/BoundingBox.h>
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <cstdlib>
#include <functional>

namespace crumple::samples
{

CarMeshSettings ToyCarMesh(const std::filesystem::path& inSharedData)
{
    CarMeshSettings settings;
    settings.mPath = inSharedData / "meshes" / "toycar" / "ToyCar_geometry.gltf";
    settings.mMeshName = "ToyCar";
    // File: x left-right, y up, z forward. Body: x forward, y left, z up (a cyclic permutation: det +1).
    settings.mFileToBody << 0, 0, 1, 1, 0, 0, 0, 1, 0;
    settings.mLength = 4.2;
    return settings;
}

std::filesystem::path SharedDataFolder()
{
    if (const char* custom = std::getenv("CRUMPLE_SHARED_DATA"); custom != nullptr && *custom != '\0')
        return custom;
    return std::filesystem::path(CRUMPLE_SOURCE_DIR) / ".." / "shared" / "data";
}

Result<ffd::TriangleMesh> LoadCarMesh(const CarMeshSettings& inSettings)
{
    if (!std::filesystem::exists(inSettings.mPath))
        return MakeError(EError::IoError, "mesh file not found: " + inSettings.mPath.string());
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(inSettings.mPath.string(), aiProcess_Triangulate | aiProcess_JoinIdenticalVertices);
    if (scene == nullptr || scene->mRootNode == nullptr)
        return MakeError(EError::IoError, "cannot read " + inSettings.mPath.string() + ": " + importer.GetErrorString());

    // Walk the node tree, applying node transforms, keeping meshes whose node or mesh name matches.
    ffd::TriangleMesh mesh;
    std::function<void(const aiNode*, const aiMatrix4x4&)> visit = [&](const aiNode* inNode, const aiMatrix4x4& inParent) {
        const aiMatrix4x4 transform = inParent * inNode->mTransformation;
        for (unsigned i = 0; i < inNode->mNumMeshes; ++i)
        {
            const aiMesh* part = scene->mMeshes[inNode->mMeshes[i]];
            const bool wanted = inSettings.mMeshName.empty() ||
                                std::string(inNode->mName.C_Str()).find(inSettings.mMeshName) != std::string::npos ||
                                std::string(part->mName.C_Str()).find(inSettings.mMeshName) != std::string::npos;
            if (!wanted)
                continue;
            const auto base = static_cast<std::uint32_t>(mesh.mPositions.size());
            for (unsigned v = 0; v < part->mNumVertices; ++v)
            {
                const aiVector3D p = transform * part->mVertices[v];
                mesh.mPositions.push_back(inSettings.mFileToBody * Vec3(p.x, p.y, p.z));
            }
            for (unsigned f = 0; f < part->mNumFaces; ++f)
                if (part->mFaces[f].mNumIndices == 3)
                    mesh.mTriangles.push_back({base + part->mFaces[f].mIndices[0], base + part->mFaces[f].mIndices[1],
                                               base + part->mFaces[f].mIndices[2]});
        }
        for (unsigned c = 0; c < inNode->mNumChildren; ++c)
            visit(inNode->mChildren[c], transform);
    };
    visit(scene->mRootNode, aiMatrix4x4());
    if (mesh.mTriangles.empty())
        return MakeError(EError::DegenerateGeometry, inSettings.mPath.string() + " has no triangles in a mesh named '" +
                                                         inSettings.mMeshName + "'");

    // Centre on the bounding box and scale to the wanted length.
    const ffd::AlignedBox bounds = ffd::BoundingBox(mesh.mPositions);
    const Vec3 lo = bounds.mMin, hi = bounds.mMax;
    const double scale = inSettings.mLength / (hi.x() - lo.x());
    const Vec3 centre = 0.5 * (lo + hi);
    for (Vec3& p : mesh.mPositions)
        p = scale * (p - centre);
    if (Status valid = ffd::ValidateTriangleMesh(mesh); !valid)
        return valid.GetError();
    return mesh;
}

} // namespace crumple::samples
