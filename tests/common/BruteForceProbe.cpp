// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "BruteForceProbe.h"

#include <algorithm>
#include <limits>
#include <vector>

namespace crumple::common
{

namespace
{

// A point projected on the probe's axes.
struct Corner
{
    double mSide, mThird, mDepth;
};

std::vector<Corner> Clip(const std::vector<Corner>& inPolygon, double Corner::*inCoordinate, double inLimit,
                         double inSign)
{
    std::vector<Corner> out;
    for (std::size_t i = 0; i < inPolygon.size(); ++i)
    {
        const Corner& a = inPolygon[i];
        const Corner& b = inPolygon[(i + 1) % inPolygon.size()];
        const double da = inSign * (a.*inCoordinate - inLimit), db = inSign * (b.*inCoordinate - inLimit);
        if (da <= 0.0)
            out.push_back(a);
        if ((da < 0.0 && db > 0.0) || (da > 0.0 && db < 0.0))
        {
            const double t = da / (da - db);
            out.push_back({a.mSide + t * (b.mSide - a.mSide), a.mThird + t * (b.mThird - a.mThird),
                           a.mDepth + t * (b.mDepth - a.mDepth)});
        }
    }
    return out;
}

} // namespace

ffd::SurfaceProbeResult BruteForceProbe(const ffd::FfdDeformer& inDeformer, const ffd::SurfaceProbe& inProbe)
{
    const std::vector<Vec3>& positions = inDeformer.GetCurrentPositions();
    const std::vector<Vec3>& rest = inDeformer.GetRestMesh().mPositions;
    auto project = [&](const Vec3& inPoint) {
        return Corner{inProbe.mSide.dot(inPoint), inProbe.mThird.dot(inPoint),
                      inProbe.mDirection.dot(inPoint)};
    };
    auto outside = [&](const Corner& inCorner)
    {
        return (inCorner.mSide < inProbe.mSideMin ? 1 : 0) | (inCorner.mSide > inProbe.mSideMax ? 2 : 0) |
               (inCorner.mThird < inProbe.mThirdMin ? 4 : 0) | (inCorner.mThird > inProbe.mThirdMax ? 8 : 0);
    };
    double front = std::numeric_limits<double>::infinity(), inside_move = 0.0, across_move = 0.0;
    bool inside = false;
    for (std::size_t v = 0; v < positions.size(); ++v)
        if (const Corner c = project(positions[v]); outside(c) == 0)
        {
            front = std::min(front, c.mDepth);
            inside_move = std::max(inside_move, inProbe.mDirection.dot(positions[v] - rest[v]));
            inside = true;
        }
    for (const auto& triangle : inDeformer.GetRestMesh().mTriangles)
    {
        std::vector<Corner> polygon;
        int all = 15, any = 0;
        for (std::uint32_t v : triangle)
        {
            polygon.push_back(project(positions[v]));
            all &= outside(polygon.back());
            any |= outside(polygon.back());
        }
        if (all != 0 || any == 0)
            continue;
        polygon = Clip(polygon, &Corner::mSide, inProbe.mSideMin, -1.0);
        polygon = Clip(polygon, &Corner::mSide, inProbe.mSideMax, 1.0);
        polygon = Clip(polygon, &Corner::mThird, inProbe.mThirdMin, -1.0);
        polygon = Clip(polygon, &Corner::mThird, inProbe.mThirdMax, 1.0);
        if (polygon.empty())
            continue;
        for (const Corner& c : polygon)
            front = std::min(front, c.mDepth);
        for (std::uint32_t v : triangle)
            across_move = std::max(across_move, inProbe.mDirection.dot(positions[v] - rest[v]));
    }
    return {front, inside, inside ? inside_move : across_move};
}

} // namespace crumple::common
