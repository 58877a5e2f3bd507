// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "SurfaceFolds.h"

#include <array>
#include <cstdint>

namespace crumple::common
{

namespace
{

// Twice the triangle's area along its normal, (b - a) x (c - a).
Vec3 FaceNormal(std::span<const Vec3> inPositions, const std::array<std::uint32_t, 3>& inTriangle)
{
    const Vec3& a = inPositions[inTriangle[0]];
    return (inPositions[inTriangle[1]] - a).cross(inPositions[inTriangle[2]] - a);
}

// Per vertex: the sum of its triangles' area-weighted normals and of their lengths.
void SumFaceNormals(const ffd::TriangleMesh& inMesh, std::span<const Vec3> inPositions,
                    std::vector<Vec3>& outSum, std::vector<double>* outArea)
{
    outSum.assign(inPositions.size(), Vec3::Zero());
    if (outArea != nullptr)
        outArea->assign(inPositions.size(), 0.0);
    for (const auto& triangle : inMesh.mTriangles)
    {
        const Vec3 normal = FaceNormal(inPositions, triangle);
        const double area = outArea != nullptr ? normal.norm() : 0.0;
        for (std::uint32_t v : triangle)
        {
            outSum[v] += normal;
            if (outArea != nullptr)
                (*outArea)[v] += area;
        }
    }
}

bool IsSheetVertex(const Vec3& inSum, double inArea)
{
    return !(inSum.norm() > cSheetCancellation * inArea);
}

} // namespace

int FoldedVertices(const ffd::TriangleMesh& inRest, std::span<const Vec3> inPositions)
{
    if (inPositions.size() != inRest.mPositions.size())
        return 0;
    std::vector<Vec3> rest, now;
    std::vector<double> area;
    SumFaceNormals(inRest, inRest.mPositions, rest, &area);
    SumFaceNormals(inRest, inPositions, now, nullptr);
    int folded = 0;
    for (std::size_t vertex = 0; vertex < rest.size(); ++vertex)
        folded += !IsSheetVertex(rest[vertex], area[vertex]) && rest[vertex].dot(now[vertex]) < 0.0 ? 1 : 0;
    return folded;
}

int FoldedTriangles(const ffd::TriangleMesh& inRest, std::span<const Vec3> inPositions)
{
    int folded = 0;
    for (const auto& t : inRest.mTriangles)
    {
        const Vec3 rest = FaceNormal(inRest.mPositions, t);
        if (rest.isZero(0.0))
            continue;
        folded += rest.dot(FaceNormal(inPositions, t)) < 0.0 ? 1 : 0;
    }
    return folded;
}

} // namespace crumple::common
