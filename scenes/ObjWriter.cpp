// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "ObjWriter.h"

#include <crumple/base/FileBytes.h>

#include <cstdio>
#include <string>

namespace crumple::common
{

Status WriteObj(const std::filesystem::path& inPath, std::span<const Vec3> inPositions, std::span<const Vec3> inNormals,
                std::span<const std::array<std::uint32_t, 3>> inTriangles)
{
    // The whole file as text: "v", "vn", then "f" lines with 1-based indices.
    std::string text;
    char line[160];
    for (const Vec3& p : inPositions)
    {
        std::snprintf(line, sizeof(line), "v %.9g %.9g %.9g\n", p.x(), p.y(), p.z());
        text += line;
    }
    for (const Vec3& n : inNormals)
    {
        std::snprintf(line, sizeof(line), "vn %.6f %.6f %.6f\n", n.x(), n.y(), n.z());
        text += line;
    }
    const bool has_normals = inNormals.size() == inPositions.size();
    for (const auto& t : inTriangles)
    {
        const std::string a = std::to_string(t[0] + 1), b = std::to_string(t[1] + 1),
                          c = std::to_string(t[2] + 1);
        if (has_normals)
            text += "f " + a + "//" + a + ' ' + b + "//" + b + ' ' + c + "//" + c + '\n';
        else
            text += "f " + a + ' ' + b + ' ' + c + '\n';
    }

    // Through "<inPath>.partial" and a rename, so a failed write leaves no partial file.
    return WriteFileAtomically(inPath, std::as_bytes(std::span(text)), "WriteObj");
}

} // namespace crumple::common
