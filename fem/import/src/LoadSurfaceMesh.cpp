// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem_import/LoadSurfaceMesh.h>

#include <crumple/base/IsolatedCall.h>
#include <crumple/base/MeshBytes.h>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <Eigen/Core>

#include <cmath>
#include <map>
#include <sstream>

namespace crumple::fem
{

namespace
{

// An assimp node transform (row-major, column vectors) in double precision.
Eigen::Matrix4d ToMatrix(const aiMatrix4x4& inMatrix)
{
    Eigen::Matrix4d matrix;
    matrix << inMatrix.a1, inMatrix.a2, inMatrix.a3, inMatrix.a4, inMatrix.b1, inMatrix.b2, inMatrix.b3,
        inMatrix.b4, inMatrix.c1, inMatrix.c2, inMatrix.c3, inMatrix.c4, inMatrix.d1, inMatrix.d2,
        inMatrix.d3, inMatrix.d4;
    return matrix;
}

// Collects the triangles of the scene with vertices joined by exact position.
class SceneMerger
{
  public:
    SceneMerger(const aiScene& inScene, std::string inPath) : mScene(inScene), mPath(std::move(inPath)) {}

    // Visits a node and its children depth first, in the file's order.
    Status Visit(const aiNode& inNode, const Eigen::Matrix4d& inParent)
    {
        const Eigen::Matrix4d transform = inParent * ToMatrix(inNode.mTransformation);
        for (unsigned i = 0; i < inNode.mNumMeshes; ++i)
            if (Status added = AddMesh(*mScene.mMeshes[inNode.mMeshes[i]], transform); !added)
                return added;
        for (unsigned child = 0; child < inNode.mNumChildren; ++child)
            if (Status visited = Visit(*inNode.mChildren[child], transform); !visited)
                return visited;
        return Status::Ok();
    }

    SurfaceMesh& GetSurface() { return mSurface; }

  private:
    // Appends one mesh's triangles, joining its vertices with those seen before.
    Status AddMesh(const aiMesh& inMesh, const Eigen::Matrix4d& inTransform)
    {
        std::vector<int> joined(inMesh.mNumVertices);
        for (unsigned vertex = 0; vertex < inMesh.mNumVertices; ++vertex)
        {
            const aiVector3D& p = inMesh.mVertices[vertex];
            const Vec3 position = (inTransform * Eigen::Vector4d(p.x, p.y, p.z, 1.0)).head<3>();
            if (!IsFinite(position))
            {
                std::ostringstream message;
                message << mPath << ": vertex " << vertex << " of mesh '" << inMesh.mName.C_Str()
                        << "' has a non-finite position (" << p.x << ", " << p.y << ", " << p.z << ")";
                return MakeError(EError::NonFinite, message.str());
            }
            const auto [entry, inserted] = mIndex.try_emplace({position.x(), position.y(), position.z()},
                                                              static_cast<int>(mSurface.mPositions.size()));
            if (inserted)
                mSurface.mPositions.push_back(position);
            joined[vertex] = entry->second;
        }
        for (unsigned face = 0; face < inMesh.mNumFaces; ++face)
        {
            const aiFace& corners = inMesh.mFaces[face];
            if (corners.mNumIndices != 3)
                continue; // points and lines
            // assimp passes a file's face indices through: a corrupt file can name vertices it does not have.
            if (corners.mIndices[0] >= inMesh.mNumVertices || corners.mIndices[1] >= inMesh.mNumVertices ||
                corners.mIndices[2] >= inMesh.mNumVertices)
            {
                std::ostringstream message;
                message << mPath << ": face " << face << " of mesh '" << inMesh.mName.C_Str()
                        << "' names a vertex beyond its " << inMesh.mNumVertices;
                return MakeError(EError::CorruptData, message.str());
            }
            const TriangleIndices triangle{joined[corners.mIndices[0]], joined[corners.mIndices[1]],
                                           joined[corners.mIndices[2]]};
            if (triangle[0] != triangle[1] && triangle[1] != triangle[2] && triangle[2] != triangle[0])
                mSurface.mTriangles.push_back(triangle);
        }
        return Status::Ok();
    }

    const aiScene& mScene;
    std::string mPath;
    SurfaceMesh mSurface;
    std::map<std::array<double, 3>, int> mIndex; // exact position -> joined vertex (-0.0 joins 0.0)
};

// The parse itself, in whatever process runs it.
Result<SurfaceMesh> ParseSurfaceMesh(const std::string& path)
{
    // Parse, triangulate; assimp's own joining only merges within a mesh and with equal normals and UVs.
    Assimp::Importer importer;
    // ValidateDataStructure first: a corrupt file (a face index of -1) otherwise crashes the later steps.
    const aiScene* scene = importer.ReadFile(path, aiProcess_ValidateDataStructure | aiProcess_Triangulate | aiProcess_JoinIdenticalVertices);
    if (scene == nullptr || scene->mRootNode == nullptr)
        return MakeError(EError::CorruptData, path + ": cannot be read: " + importer.GetErrorString());

    // Every mesh instance, placed by its node transforms.
    SceneMerger merger(*scene, path);
    if (Status merged = merger.Visit(*scene->mRootNode, Eigen::Matrix4d::Identity()); !merged)
        return merged.GetError();
    SurfaceMesh& surface = merger.GetSurface();
    if (surface.mTriangles.empty())
        return MakeError(EError::DegenerateGeometry, path + ": holds no triangles");

    // A solid needs a closed surface.
    if (Status closed = ValidateClosedSurface(surface); !closed)
        return MakeError(closed.GetError().mCode, path + ": " + closed.GetError().mMessage);
    return std::move(surface);
}

} // namespace

Result<SurfaceMesh> LoadSurfaceMesh(const std::filesystem::path& inPath, double inTimeout)
{
    // A missing file is the caller's path, not a parse error.
    const std::string path = inPath.string();
    std::error_code error;
    if (!std::filesystem::is_regular_file(inPath, error))
        return MakeError(EError::IoError, path + ": no such file");
    if (!(inTimeout > 0.0) || !std::isfinite(inTimeout))
        return MakeError(EError::InvalidArgument, "LoadSurfaceMesh: the timeout must be finite and > 0 s");
    Result<std::vector<std::byte>> bytes = RunIsolated(
        [&]() -> Result<std::vector<std::byte>> {
            Result<SurfaceMesh> surface = ParseSurfaceMesh(path);
            if (surface.HasError())
                return surface.GetError();
            return EncodeMeshBytes<int>(surface.Get().mPositions, surface.Get().mTriangles);
        },
        inTimeout, path);
    if (bytes.HasError())
        return bytes.GetError();
    // The child ran ValidateClosedSurface on exactly these values: decoding checks only that they arrived whole.
    SurfaceMesh surface;
    if (Status decoded = DecodeMeshBytes(bytes.Get(), path, surface.mPositions, surface.mTriangles); !decoded)
        return decoded.GetError();
    return surface;
}

} // namespace crumple::fem
