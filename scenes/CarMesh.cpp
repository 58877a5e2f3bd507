// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "CarMesh.h"

#include <crumple/base/ByteReader.h>
#include <crumple/base/ByteWriter.h>
#include <crumple/base/IsolatedCall.h>
#include <crumple/base/MeshBytes.h>

#include <crumple/ffd/BoundingBox.h>
#include <crumple/ffd/RefineLongEdges.h>
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <tuple>

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

Result<Mat3> FileToBodyRotation(EMeshAxis inForward, EMeshAxis inUp)
{
    auto direction = [](EMeshAxis inAxis) {
        const auto index = static_cast<int>(inAxis);
        return Vec3((index % 2 == 0 ? 1.0 : -1.0) * Vec3::Unit(index / 2));
    };
    const Vec3 forward = direction(inForward), up = direction(inUp);
    if (std::abs(forward.dot(up)) > 0.5)
        return MakeError(EError::InvalidArgument, "the mesh's forward and up axes must be different axes");
    // Rows: the body's x (forward), y (left = up x forward) and z (up), each in file coordinates.
    Mat3 rotation;
    rotation.row(0) = forward.transpose();
    rotation.row(1) = up.cross(forward).transpose();
    rotation.row(2) = up.transpose();
    return rotation;
}

std::string ForwardAxisWarning(const ffd::TriangleMesh& inBody)
{
    if (inBody.mPositions.empty())
        return {};
    const ffd::AlignedBox bounds = ffd::BoundingBox(inBody.mPositions);
    const Vec3 size = bounds.mMax - bounds.mMin;
    char text[256];
    // intent: a car is longer than it is tall too: a z-forward, y-up export read with the default axes has
    // its length along the stated up axis, and would crash 4 m tall and 1.8 m long
    if (size.x() < size.z() && size.y() <= size.z())
    {
        std::snprintf(
            text, sizeof(text),
            "the mesh is %.3g tall along the stated up axis and %.3g long along the stated forward "
            "axis: a car is longer than tall, so its axes are probably wrong (state its forward and "
            "up axes)",
            size.z(), size.x());
        return text;
    }
    if (size.x() >= size.y())
        return {};
    std::snprintf(text, sizeof(text),
                  "the mesh is %.3g wide across the stated forward axis and %.3g long along it: a car is longer "
                  "than wide, so it is probably sideways (state its forward axis)",
                  size.y(), size.x());
    return text;
}

namespace
{

// inText contains one of inNeedles, ignoring case (ASCII).
bool ContainsAnyOf(std::string inText, const std::vector<std::string>& inNeedles)
{
    const auto lower = [](std::string ioText) {
        std::transform(ioText.begin(), ioText.end(), ioText.begin(),
                       [](unsigned char inChar) { return static_cast<char>(std::tolower(inChar)); });
        return ioText;
    };
    inText = lower(std::move(inText));
    return std::any_of(inNeedles.begin(), inNeedles.end(), [&](const std::string& inNeedle)
                       { return !inNeedle.empty() && inText.find(lower(inNeedle)) != std::string::npos; });
}

// A rigid part as found in the file: a run of the mesh's vertices and the name that made it one.
struct FoundPart
{
    std::uint32_t mBegin = 0;
    std::uint32_t mEnd = 0;
    std::string mName;
};

// Each part split into its connected pieces (vertices joined by the part's triangles, or at the same position:
// files keep a vertex per face where normals or texture coordinates differ), in order of their first vertex:
// a file's mesh that holds both rear wheels gives two parts, each moving with the body at its own centre,
// not one centred between them. A vertex nothing joins is a piece of its own.
void SplitPartsIntoPieces(const ffd::TriangleMesh& inMesh, std::vector<std::vector<std::uint32_t>>& ioParts,
                          std::vector<std::string>& ioNames)
{
    std::vector<int> part_of(inMesh.mPositions.size(), -1);
    for (std::size_t part = 0; part < ioParts.size(); ++part)
        for (std::uint32_t v : ioParts[part])
            part_of[v] = static_cast<int>(part);
    std::vector<std::uint32_t> root(inMesh.mPositions.size());
    for (std::uint32_t v = 0; v < root.size(); ++v)
        root[v] = v;
    const auto find = [&root](std::uint32_t inVertex) {
        while (root[inVertex] != inVertex)
            inVertex = root[inVertex] = root[root[inVertex]];
        return inVertex;
    };
    const auto join = [&](std::uint32_t inA, std::uint32_t inB) {
        const std::uint32_t a = find(inA), b = find(inB);
        root[std::max(a, b)] = std::min(a, b); // the smaller index roots: pieces in first-vertex order
    };
    for (const auto& triangle : inMesh.mTriangles)
        for (int corner = 1; corner < 3; ++corner)
            if (part_of[triangle[0]] >= 0 && part_of[triangle[0]] == part_of[triangle[static_cast<std::size_t>(corner)]])
                join(triangle[0], triangle[static_cast<std::size_t>(corner)]);
    for (const std::vector<std::uint32_t>& part : ioParts)
    {
        std::vector<std::uint32_t> by_position = part;
        const auto less = [&](std::uint32_t inA, std::uint32_t inB) {
            const Vec3& a = inMesh.mPositions[inA];
            const Vec3& b = inMesh.mPositions[inB];
            return std::tie(a.x(), a.y(), a.z(), inA) < std::tie(b.x(), b.y(), b.z(), inB);
        };
        std::sort(by_position.begin(), by_position.end(), less);
        for (std::size_t i = 1; i < by_position.size(); ++i)
            if (inMesh.mPositions[by_position[i]] == inMesh.mPositions[by_position[i - 1]])
                join(by_position[i], by_position[i - 1]);
    }
    std::vector<std::vector<std::uint32_t>> pieces;
    std::vector<std::string> names;
    std::vector<int> piece_of_root(inMesh.mPositions.size(), -1);
    for (std::size_t part = 0; part < ioParts.size(); ++part)
        for (std::uint32_t v : ioParts[part]) // ascending: a piece's root comes first
        {
            int& piece = piece_of_root[find(v)];
            if (piece < 0)
            {
                piece = static_cast<int>(pieces.size());
                pieces.emplace_back();
                names.push_back(ioNames[part]);
            }
            pieces[static_cast<std::size_t>(piece)].push_back(v);
        }
    ioParts = std::move(pieces);
    ioNames = std::move(names);
}

// The parse itself (assimp), in whatever process runs it: the wanted meshes' triangles, node transforms
// applied, in the file's frame and unit, and the vertex runs of the meshes named as rigid parts.
Result<ffd::TriangleMesh> ReadSceneTriangles(const CarMeshSettings& inSettings, std::vector<FoundPart>& outParts,
                                             std::vector<std::string>& outUnmatched)
{
    // Which fragments named a part (by its node's name or its mesh's).
    std::vector<std::uint8_t> matched(inSettings.mRigidPartNames.size(), 0);
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(inSettings.mPath.string(), aiProcess_ValidateDataStructure | aiProcess_Triangulate |
                                                                              aiProcess_JoinIdenticalVertices);
    if (scene == nullptr || scene->mRootNode == nullptr)
    {
        // intent: assimp's validation names its own structure for a file with no mesh in it (an OBJ of
        // vertices only, text that is not a mesh): say so in the caller's words, with assimp's beside
        const std::string why = importer.GetErrorString();
        const bool no_mesh = why.find("mNumMeshes is 0") != std::string::npos ||
                             why.find("contains no faces") != std::string::npos;
        const std::string meshless = no_mesh ? "the file holds no mesh (no faces, or not a mesh file); " : "";
        return MakeError(EError::IoError, "cannot read " + inSettings.mPath.string() + ": " + meshless + why);
    }

    // Walk the node tree, applying node transforms, keeping meshes whose node or mesh name matches.
    ffd::TriangleMesh mesh;
    bool bad_index = false;
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
            const std::string node_name = inNode->mName.C_Str(), mesh_name = part->mName.C_Str();
            // intent: the part keeps the name that matched (the node's first); every fragment that matched either
            // name counts as found
            const bool by_node = ContainsAnyOf(node_name, inSettings.mRigidPartNames);
            const bool by_mesh = ContainsAnyOf(mesh_name, inSettings.mRigidPartNames);
            if (part->mNumVertices > 0 && (by_node || by_mesh))
            {
                outParts.push_back({base, base + part->mNumVertices, by_node ? node_name : mesh_name});
                for (std::size_t f = 0; f < matched.size(); ++f)
                    if (ContainsAnyOf(node_name, {inSettings.mRigidPartNames[f]}) ||
                        ContainsAnyOf(mesh_name, {inSettings.mRigidPartNames[f]}))
                        matched[f] = 1;
            }
            for (unsigned v = 0; v < part->mNumVertices; ++v)
            {
                const aiVector3D p = transform * part->mVertices[v];
                mesh.mPositions.push_back(inSettings.mFileToBody * Vec3(p.x, p.y, p.z));
            }
            for (unsigned f = 0; f < part->mNumFaces; ++f)
            {
                const aiFace& face = part->mFaces[f];
                if (face.mNumIndices != 3)
                    continue;
                // A corrupt file's indices pass through assimp: one beyond the part is refused below.
                if (face.mIndices[0] >= part->mNumVertices || face.mIndices[1] >= part->mNumVertices ||
                    face.mIndices[2] >= part->mNumVertices)
                {
                    bad_index = true;
                    continue;
                }
                mesh.mTriangles.push_back({base + face.mIndices[0], base + face.mIndices[1], base + face.mIndices[2]});
            }
        }
        for (unsigned c = 0; c < inNode->mNumChildren; ++c)
            visit(inNode->mChildren[c], transform);
    };
    visit(scene->mRootNode, aiMatrix4x4());
    for (std::size_t f = 0; f < matched.size(); ++f)
        if (matched[f] == 0)
            outUnmatched.push_back(inSettings.mRigidPartNames[f]);
    if (bad_index)
        return MakeError(EError::CorruptData, inSettings.mPath.string() + ": a face names a vertex its mesh does not have");
    if (mesh.mTriangles.empty())
        return MakeError(EError::DegenerateGeometry, inSettings.mPath.string() + " has no triangles in a mesh named '" +
                                                         inSettings.mMeshName + "'");
    return mesh;
}

} // namespace

Result<ffd::TriangleMesh> LoadCarMesh(const CarMeshSettings& inSettings)
{
    Result<CarBody> body = LoadCarBody(inSettings);
    if (body.HasError())
        return body.GetError();
    return std::move(body.Get().mMesh);
}

std::vector<std::vector<std::uint32_t>> PartsAfterRefinement(const std::vector<std::vector<std::uint32_t>>& inParts,
                                                             const ffd::RefinedMesh& inRefined)
{
    // intent: each vertex's part (-1: none), the added ones from their parents in order (a parent may itself
    // be an added vertex of a lower index)
    const std::size_t vertices = inRefined.mMesh.mPositions.size();
    const std::size_t first_added = vertices - inRefined.mSplitParents.size();
    std::vector<int> part_of(vertices, -1);
    for (std::size_t part = 0; part < inParts.size(); ++part)
        for (std::uint32_t v : inParts[part])
            if (v < first_added)
                part_of[v] = static_cast<int>(part);
    for (std::size_t k = 0; k < inRefined.mSplitParents.size(); ++k)
    {
        const auto& parents = inRefined.mSplitParents[k];
        if (part_of[parents[0]] >= 0 && part_of[parents[0]] == part_of[parents[1]])
            part_of[first_added + k] = part_of[parents[0]];
    }
    std::vector<std::vector<std::uint32_t>> parts(inParts.size());
    for (std::size_t v = 0; v < vertices; ++v)
        if (part_of[v] >= 0)
            parts[static_cast<std::size_t>(part_of[v])].push_back(static_cast<std::uint32_t>(v));
    return parts;
}

Result<CarBody> LoadCarBody(const CarMeshSettings& inSettings)
{
    if (!(std::isfinite(inSettings.mUnit) && inSettings.mUnit >= 0.0))
        return MakeError(EError::InvalidArgument, "CarMeshSettings.mUnit must be finite and >= 0 m per file unit");
    if (!(std::isfinite(inSettings.mLength) && inSettings.mLength > 0.0))
        return MakeError(EError::InvalidArgument, "CarMeshSettings.mLength must be finite and > 0 m");
    if (!std::filesystem::exists(inSettings.mPath))
        return MakeError(EError::IoError, "mesh file not found: " + inSettings.mPath.string());
    // assimp parses in a child process: a malformed file that crashes or hangs it is refused (RunIsolated).
    constexpr double cParseTimeout = 60.0;
    Result<std::vector<std::byte>> bytes = RunIsolated(
        [&]() -> Result<std::vector<std::byte>> {
            // The parts first (u32 count; per part u32 begin, end, name length, name bytes), then the fragments
            // that found no part (u32 count; per fragment its length and bytes), then the mesh.
            std::vector<FoundPart> parts;
            std::vector<std::string> unmatched;
            Result<ffd::TriangleMesh> read = ReadSceneTriangles(inSettings, parts, unmatched);
            if (read.HasError())
                return read.GetError();
            ByteWriter writer;
            writer.WriteU32(static_cast<std::uint32_t>(parts.size()));
            for (const FoundPart& part : parts)
            {
                writer.WriteU32(part.mBegin);
                writer.WriteU32(part.mEnd);
                writer.WriteU32(static_cast<std::uint32_t>(part.mName.size()));
                writer.WriteBytes(std::as_bytes(std::span(part.mName)));
            }
            writer.WriteU32(static_cast<std::uint32_t>(unmatched.size()));
            for (const std::string& fragment : unmatched)
            {
                writer.WriteU32(static_cast<std::uint32_t>(fragment.size()));
                writer.WriteBytes(std::as_bytes(std::span(fragment)));
            }
            std::vector<std::byte> answer = writer.TakeBytes();
            const std::vector<std::byte> mesh = EncodeMeshBytes<std::uint32_t>(read.Get().mPositions, read.Get().mTriangles);
            answer.insert(answer.end(), mesh.begin(), mesh.end());
            return answer;
        },
        cParseTimeout, inSettings.mPath.string());
    if (bytes.HasError())
        return bytes.GetError();
    CarBody body;
    ffd::TriangleMesh& mesh = body.mMesh;
    ByteReader reader(bytes.Get());
    const std::uint32_t part_count = reader.ReadU32();
    for (std::uint32_t part = 0; part < part_count && !reader.Failed(); ++part)
    {
        const std::uint32_t begin = reader.ReadU32(), end = reader.ReadU32(), length = reader.ReadU32();
        // intent: a part no larger than the vertices the answer can still hold (24 bytes each), before any
        // allocation
        if (reader.Failed() || length > reader.Remaining() || begin > end || end - begin > reader.Remaining() / 24)
            return MakeError(EError::CorruptData, inSettings.mPath.string() + ": the parser's answer is corrupt");
        std::string name(length, '\0');
        for (char& c : name)
            c = static_cast<char>(reader.ReadU8());
        std::vector<std::uint32_t> vertices(end - begin);
        for (std::uint32_t v = begin; v < end; ++v)
            vertices[v - begin] = v;
        body.mRigidParts.push_back(std::move(vertices));
        body.mRigidPartNames.push_back(std::move(name));
    }
    const std::uint32_t unmatched_count = reader.ReadU32();
    // intent: at most the fragments asked about (each names itself), before any allocation
    if (!reader.Failed() && unmatched_count > inSettings.mRigidPartNames.size())
        return MakeError(EError::CorruptData, inSettings.mPath.string() + ": the parser's answer is corrupt");
    for (std::uint32_t f = 0; f < unmatched_count && !reader.Failed(); ++f)
    {
        const std::uint32_t length = reader.ReadU32();
        if (reader.Failed() || length > reader.Remaining())
            return MakeError(EError::CorruptData, inSettings.mPath.string() + ": the parser's answer is corrupt");
        std::string fragment(length, '\0');
        for (char& c : fragment)
            c = static_cast<char>(reader.ReadU8());
        body.mUnmatchedRigidPartNames.push_back(std::move(fragment));
    }
    if (reader.Failed())
        return MakeError(EError::CorruptData, inSettings.mPath.string() + ": the parser's answer is corrupt");
    const std::span<const std::byte> mesh_bytes = std::span<const std::byte>(bytes.Get()).subspan(bytes.Get().size() - reader.Remaining());
    if (Status decoded = DecodeMeshBytes(mesh_bytes, inSettings.mPath.string(), mesh.mPositions, mesh.mTriangles); !decoded)
        return decoded.GetError();
    for (const std::vector<std::uint32_t>& part : body.mRigidParts)
        if (!part.empty() && part.back() >= mesh.mPositions.size())
            return MakeError(EError::CorruptData, inSettings.mPath.string() + ": the parser's answer is corrupt");
    SplitPartsIntoPieces(mesh, body.mRigidParts, body.mRigidPartNames);
    if (mesh.mTriangles.empty())
        return MakeError(EError::DegenerateGeometry, inSettings.mPath.string() + " has no triangles");

    // intent: a coordinate the file spells as nan or inf is named here; past the centring every vertex
    // would be NaN and the first one blamed
    for (std::size_t v = 0; v < mesh.mPositions.size(); ++v)
        if (!IsFinite(mesh.mPositions[v]))
            return MakeError(
                EError::NonFinite,
                inSettings.mPath.string() + ": vertex " + std::to_string(v) +
                    " of the loaded mesh is not finite (counting from 0; nan or inf in the file)");

    // Centre on the bounding box and scale by the unit or to the wanted length.
    const ffd::AlignedBox bounds = ffd::BoundingBox(mesh.mPositions);
    const Vec3 lo = bounds.mMin, hi = bounds.mMax;
    // intent: a mesh flat along its forward axis cannot be scaled to a length (it divided by zero and was then
    // refused as "not finite")
    if (!(inSettings.mUnit > 0.0) && !(hi.x() - lo.x() > 0.0))
        return MakeError(EError::DegenerateGeometry, inSettings.mPath.string() +
                                                         " has no extent along its forward axis: it cannot be scaled to a length");
    const double scale = inSettings.mUnit > 0.0 ? inSettings.mUnit : inSettings.mLength / (hi.x() - lo.x());
    const Vec3 centre = 0.5 * (lo + hi);
    for (Vec3& p : mesh.mPositions)
        p = scale * (p - centre);
    if (Status valid = ffd::ValidateTriangleMesh(mesh); !valid)
        return MakeError(valid.GetError().mCode,
                         inSettings.mPath.string() + ": " + valid.GetError().mMessage);
    return body;
}

} // namespace crumple::samples
