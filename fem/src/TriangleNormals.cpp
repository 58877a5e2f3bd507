// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/TriangleNormals.h>

#include <string>

namespace crumple::fem
{

Status TriangleNormals(std::span<const Vec3> inPositions, std::span<const TriangleIndices> inTriangles,
                       std::vector<Vec3>& outNormals)
{
    outNormals.clear();

    // Indices in range before anything is written.
    for (std::size_t triangle = 0; triangle < inTriangles.size(); ++triangle)
        for (const int corner : inTriangles[triangle])
            if (corner < 0 || static_cast<std::size_t>(corner) >= inPositions.size())
                return MakeError(EError::OutOfRange, "TriangleNormals: triangle " + std::to_string(triangle) +
                                                         " names vertex " + std::to_string(corner) +
                                                         ", outside [0, " +
                                                         std::to_string(inPositions.size()) + ")");

    // Normalised cross product of two edges; zero-area triangles keep the zero vector.
    outNormals.resize(inTriangles.size(), Vec3::Zero());
    for (std::size_t triangle = 0; triangle < inTriangles.size(); ++triangle)
    {
        const TriangleIndices& corners = inTriangles[triangle];
        const Vec3& a = inPositions[corners[0]];
        const Vec3 normal = (inPositions[corners[1]] - a).cross(inPositions[corners[2]] - a);
        const double length = normal.norm();
        if (length > 0.0)
            outNormals[triangle] = normal / length;
    }
    return Status::Ok();
}

} // namespace crumple::fem
