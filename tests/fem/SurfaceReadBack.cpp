// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "SurfaceReadBack.h"

#include <crumple/base/ByteReader.h>
#include <crumple/base/FileBytes.h>

#include <cstdlib>
#include <sstream>
#include <string>

namespace crumple::fem::test
{

Result<SurfaceMesh> ReadBackObj(const std::filesystem::path& inPath)
{
    Result<std::vector<std::byte>> bytes = ReadFileBytes(inPath);
    if (bytes.HasError())
        return bytes.GetError();
    const std::string text(reinterpret_cast<const char*>(bytes.Get().data()), bytes.Get().size());
    std::istringstream lines(text);
    SurfaceMesh mesh;
    std::string line;
    while (std::getline(lines, line))
    {
        // strtod reads "%.17g" back to the same double.
        if (line.rfind("v ", 0) == 0)
        {
            const char* cursor = line.c_str() + 2;
            Vec3 position;
            for (int axis = 0; axis < 3; ++axis)
            {
                char* end = nullptr;
                position[axis] = std::strtod(cursor, &end);
                if (end == cursor)
                    return MakeError(EError::CorruptData, "bad v line: " + line);
                cursor = end;
            }
            if (*cursor != '\0')
                return MakeError(EError::CorruptData, "trailing text on v line: " + line);
            mesh.mPositions.push_back(position);
        }
        else if (line.rfind("f ", 0) == 0)
        {
            std::istringstream fields(line.substr(2));
            TriangleIndices triangle{};
            std::string rest;
            if (!(fields >> triangle[0] >> triangle[1] >> triangle[2]) || (fields >> rest))
                return MakeError(EError::CorruptData, "bad f line: " + line);
            for (int& index : triangle)
                index -= 1;
            mesh.mTriangles.push_back(triangle);
        }
        else if (!line.empty() && line[0] != '#')
            return MakeError(EError::CorruptData, "unexpected line: " + line);
    }
    return mesh;
}

Result<SurfaceMesh> ReadBackPly(const std::filesystem::path& inPath)
{
    Result<std::vector<std::byte>> bytes = ReadFileBytes(inPath);
    if (bytes.HasError())
        return bytes.GetError();
    const std::string_view all(reinterpret_cast<const char*>(bytes.Get().data()), bytes.Get().size());
    const std::string_view end_marker = "end_header\n";
    const std::size_t header_end = all.find(end_marker);
    if (header_end == std::string_view::npos)
        return MakeError(EError::CorruptData, "no end_header");
    const std::string header(all.substr(0, header_end + end_marker.size()));

    // The header, line by line, with the two counts.
    std::istringstream lines(header);
    std::string line;
    std::vector<std::string> expected = {"ply",
                                         "format binary_little_endian 1.0",
                                         "",
                                         "",
                                         "property double x",
                                         "property double y",
                                         "property double z",
                                         "",
                                         "property list uchar int vertex_indices",
                                         "end_header"};
    long long vertex_count = -1;
    long long face_count = -1;
    for (std::size_t row = 0; row < expected.size(); ++row)
    {
        if (!std::getline(lines, line))
            return MakeError(EError::CorruptData, "header too short");
        if (row == 2)
        {
            if (line.rfind("comment ", 0) != 0)
                return MakeError(EError::CorruptData, "expected a comment, got: " + line);
        }
        else if (row == 3 || row == 7)
        {
            const std::string prefix = row == 3 ? "element vertex " : "element face ";
            if (line.rfind(prefix, 0) != 0)
                return MakeError(EError::CorruptData, "expected '" + prefix + "', got: " + line);
            (row == 3 ? vertex_count : face_count) = std::stoll(line.substr(prefix.size()));
        }
        else if (line != expected[row])
            return MakeError(EError::CorruptData, "expected '" + expected[row] + "', got: " + line);
    }

    // The payload: doubles, then (3, i, j, k) per face, and nothing after.
    ByteReader reader(std::span<const std::byte>(bytes.Get()).subspan(header.size()));
    SurfaceMesh mesh;
    for (long long vertex = 0; vertex < vertex_count; ++vertex)
        mesh.mPositions.push_back(reader.ReadVec3());
    for (long long face = 0; face < face_count; ++face)
    {
        if (reader.ReadU8() != 3)
            return MakeError(EError::CorruptData, "face " + std::to_string(face) + " is not a triangle");
        TriangleIndices triangle{};
        for (int& index : triangle)
            index = static_cast<int>(reader.ReadU32());
        mesh.mTriangles.push_back(triangle);
    }
    if (reader.Failed() || reader.Remaining() != 0)
        return MakeError(EError::CorruptData, "payload length does not match the header counts");
    return mesh;
}

} // namespace crumple::fem::test
