// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/base/ByteWriter.h>
#include <crumple/base/FileBytes.h>
#include <crumple/fem/ExactNumber.h>
#include <crumple/fem/SurfaceFile.h>

#include <limits>
#include <string>

namespace crumple::fem
{

namespace
{

// Refuses what a reader could not use: empty, non-finite, out-of-range indices.
Status CheckSurface(std::span<const Vec3> inPositions, std::span<const TriangleIndices> inTriangles,
                    const char* inCaller)
{
    if (inPositions.empty() || inTriangles.empty())
        return MakeError(EError::InvalidArgument, std::string(inCaller) + ": " +
                                                      std::to_string(inPositions.size()) + " vertices and " +
                                                      std::to_string(inTriangles.size()) +
                                                      " triangles; needs at least one of each");
    if (inPositions.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()) ||
        inTriangles.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
        return MakeError(EError::InvalidArgument,
                         std::string(inCaller) + ": more than 2^31 - 1 vertices or triangles");
    for (std::size_t vertex = 0; vertex < inPositions.size(); ++vertex)
        if (!IsFinite(inPositions[vertex]))
            return MakeError(EError::NonFinite, std::string(inCaller) + ": vertex " + std::to_string(vertex) +
                                                    " has a non-finite position");
    const int vertex_count = static_cast<int>(inPositions.size());
    for (std::size_t triangle = 0; triangle < inTriangles.size(); ++triangle)
        for (int index : inTriangles[triangle])
            if (index < 0 || index >= vertex_count)
                return MakeError(EError::OutOfRange, std::string(inCaller) + ": triangle " +
                                                         std::to_string(triangle) + " names vertex " +
                                                         std::to_string(index) + ", outside [0, " +
                                                         std::to_string(vertex_count) + ")");
    return Status::Ok();
}

// Appends text to a byte buffer.
void Append(std::vector<std::byte>& ioBytes, std::string_view inText)
{
    const auto* first = reinterpret_cast<const std::byte*>(inText.data());
    ioBytes.insert(ioBytes.end(), first, first + inText.size());
}

} // namespace

Status SaveSurfaceObj(const std::filesystem::path& inPath, std::span<const Vec3> inPositions,
                      std::span<const TriangleIndices> inTriangles)
{
    if (Status valid = CheckSurface(inPositions, inTriangles, "SaveSurfaceObj"); !valid)
        return valid;

    // Header comment, "v x y z" lines, then "f a b c" with 1-based indices.
    std::vector<std::byte> bytes;
    Append(bytes, "# Crumple surface: " + std::to_string(inPositions.size()) + " vertices, " +
                      std::to_string(inTriangles.size()) + " triangles, positions in m\n");
    for (const Vec3& position : inPositions)
    {
        Append(bytes, "v ");
        Append(bytes, ExactNumber(position.x()));
        Append(bytes, " ");
        Append(bytes, ExactNumber(position.y()));
        Append(bytes, " ");
        Append(bytes, ExactNumber(position.z()));
        Append(bytes, "\n");
    }
    for (const TriangleIndices& triangle : inTriangles)
        Append(bytes, "f " + std::to_string(triangle[0] + 1) + " " + std::to_string(triangle[1] + 1) + " " +
                          std::to_string(triangle[2] + 1) + "\n");
    return WriteFileAtomically(inPath, bytes, "SaveSurfaceObj");
}

Status SaveSurfacePly(const std::filesystem::path& inPath, std::span<const Vec3> inPositions,
                      std::span<const TriangleIndices> inTriangles)
{
    if (Status valid = CheckSurface(inPositions, inTriangles, "SaveSurfacePly"); !valid)
        return valid;

    // ASCII header, then little-endian doubles and (uchar 3, int, int, int) faces.
    const std::string header = "ply\n"
                               "format binary_little_endian 1.0\n"
                               "comment Crumple surface, positions in m\n"
                               "element vertex " +
                               std::to_string(inPositions.size()) +
                               "\n"
                               "property double x\n"
                               "property double y\n"
                               "property double z\n"
                               "element face " +
                               std::to_string(inTriangles.size()) +
                               "\n"
                               "property list uchar int vertex_indices\n"
                               "end_header\n";
    ByteWriter writer;
    writer.WriteTag(header);
    for (const Vec3& position : inPositions)
        writer.WriteVec3(position);
    for (const TriangleIndices& triangle : inTriangles)
    {
        writer.WriteU8(3);
        for (int index : triangle)
            writer.WriteU32(static_cast<std::uint32_t>(index));
    }
    return WriteFileAtomically(inPath, writer.GetBytes(), "SaveSurfacePly");
}

Status SaveSurface(const std::filesystem::path& inPath, std::span<const Vec3> inPositions,
                   std::span<const TriangleIndices> inTriangles, ESurfaceFormat inFormat)
{
    switch (inFormat)
    {
    case ESurfaceFormat::Obj:
        return SaveSurfaceObj(inPath, inPositions, inTriangles);
    case ESurfaceFormat::Ply:
        return SaveSurfacePly(inPath, inPositions, inTriangles);
    }
    return MakeError(EError::InvalidArgument,
                     "SaveSurface: unknown format " + std::to_string(static_cast<int>(inFormat)));
}

} // namespace crumple::fem
