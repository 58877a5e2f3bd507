// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "TetSurface.h"

#include <crumple/fem/TetBoundary.h>

namespace crumple::common
{

TetSurface MakeTetSurface(std::span<const Vec3> inPositions, std::span<const fem::TetIndices> inElements,
                          std::span<const std::uint8_t> inLeftOut)
{
    std::vector<fem::TetIndices> kept;
    if (!inLeftOut.empty())
    {
        kept.reserve(inElements.size());
        for (std::size_t e = 0; e < inElements.size(); ++e)
            if (inLeftOut[e] == 0)
                kept.push_back(inElements[e]);
    }
    const std::vector<fem::TriangleIndices> boundary = fem::TetBoundary(inLeftOut.empty() ? inElements : std::span<const fem::TetIndices>(kept));
    TetSurface surface;
    surface.mNormals.assign(inPositions.size(), Vec3::Zero());
    surface.mTriangles.reserve(boundary.size());
    for (const fem::TriangleIndices& triangle : boundary)
    {
        const Vec3& a = inPositions[static_cast<std::size_t>(triangle[0])];
        const Vec3 area = (inPositions[static_cast<std::size_t>(triangle[1])] - a).cross(inPositions[static_cast<std::size_t>(triangle[2])] - a);
        for (int corner : triangle)
            surface.mNormals[static_cast<std::size_t>(corner)] += area;
        surface.mTriangles.push_back({static_cast<std::uint32_t>(triangle[0]), static_cast<std::uint32_t>(triangle[1]),
                                      static_cast<std::uint32_t>(triangle[2])});
    }
    for (Vec3& normal : surface.mNormals)
        normal = normal.norm() > 0.0 ? Vec3(normal.normalized()) : Vec3::UnitZ();
    return surface;
}

} // namespace crumple::common
