// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/plugin/CampbellCrush.h>

#include <algorithm>
#include <array>
#include <limits>

namespace crumple::plugin
{

BodyLength MeasureBodyLength(std::span<const Vec3> inRestPositions, const Vec3& inUp)
{
    BodyLength length;
    if (inRestPositions.empty())
        return length;
    const Vec3 up = inUp.normalized();
    Eigen::Index least = 0;
    up.cwiseAbs().minCoeff(&least);
    const Vec3 first = (Vec3::Unit(least) - up.dot(Vec3::Unit(least)) * up).normalized();
    const Vec3 second = up.cross(first);
    constexpr double cInf = std::numeric_limits<double>::infinity();
    std::array<double, 2> low{cInf, cInf}, high{-cInf, -cInf};
    for (const Vec3& p : inRestPositions)
    {
        const std::array<double, 2> along{first.dot(p), second.dot(p)};
        for (std::size_t k = 0; k < 2; ++k)
        {
            low[k] = std::min(low[k], along[k]);
            high[k] = std::max(high[k], along[k]);
        }
    }
    const std::size_t k = high[1] - low[1] > high[0] - low[0] ? 1 : 0;
    length.mAxis = k == 0 ? first : second;
    length.mMin = low[k];
    length.mMax = high[k];
    return length;
}

CrushBody MeasureCrushBody(const ffd::FfdDeformer& inDeformer, const Vec3& inUp)
{
    CrushBody body;
    const ffd::TriangleMesh& rest = inDeformer.GetRestMesh();
    body.mLength = MeasureBodyLength(rest.mPositions, inUp);
    if (!rest.mPositions.empty())
    {
        body.mRestMin = body.mRestMax = rest.mPositions.front();
        for (const Vec3& p : rest.mPositions)
        {
            body.mRestMin = body.mRestMin.cwiseMin(p);
            body.mRestMax = body.mRestMax.cwiseMax(p);
        }
    }
    const double large = 0.5 * inDeformer.GetMinSpacing();
    const double large2 = large * large;
    for (std::uint32_t t = 0; t < rest.mTriangles.size(); ++t)
    {
        const std::array<std::uint32_t, 3>& v = rest.mTriangles[t];
        const Vec3& a = rest.mPositions[v[0]];
        const Vec3& b = rest.mPositions[v[1]];
        const Vec3& c = rest.mPositions[v[2]];
        if ((b - a).squaredNorm() > large2 || (c - b).squaredNorm() > large2 || (a - c).squaredNorm() > large2)
            body.mLargeTriangles.push_back(t);
    }
    return body;
}

} // namespace crumple::plugin
