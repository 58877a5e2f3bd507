// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "ObjWriter.h"

#include <cstdio>
#include <fstream>

namespace crumple::common
{

Status WriteObj(const std::filesystem::path& inPath, std::span<const Vec3> inPositions, std::span<const Vec3> inNormals,
                std::span<const std::array<std::uint32_t, 3>> inTriangles)
{
    const std::filesystem::path temporary = inPath.string() + ".tmp";
    {
        std::ofstream out(temporary);
        if (!out)
            return MakeError(EError::IoError, "cannot write " + temporary.string());
        char line[160];
        for (const Vec3& p : inPositions)
        {
            std::snprintf(line, sizeof(line), "v %.9g %.9g %.9g\n", p.x(), p.y(), p.z());
            out << line;
        }
        for (const Vec3& n : inNormals)
        {
            std::snprintf(line, sizeof(line), "vn %.6f %.6f %.6f\n", n.x(), n.y(), n.z());
            out << line;
        }
        const bool has_normals = inNormals.size() == inPositions.size();
        for (const auto& t : inTriangles)
        {
            if (has_normals)
                out << "f " << t[0] + 1 << "//" << t[0] + 1 << ' ' << t[1] + 1 << "//" << t[1] + 1 << ' ' << t[2] + 1
                    << "//" << t[2] + 1 << '\n';
            else
                out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
        }
        if (!out.flush())
            return MakeError(EError::IoError, "write failed: " + temporary.string());
    }
    std::error_code error;
    std::filesystem::rename(temporary, inPath, error);
    if (error)
        return MakeError(EError::IoError, "cannot rename to " + inPath.string() + ": " + error.message());
    return Status::Ok();
}

} // namespace crumple::common
