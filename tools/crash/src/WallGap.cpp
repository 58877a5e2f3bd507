// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/crash/WallGap.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <utility>

namespace crumple::crash
{

WallGap MeasureWallGap(const ffd::TriangleMesh& inRest, std::span<const Vec3> inRestNormals,
                       std::span<const Vec3> inPositions, const Vec3& inIntoWall, const WallReach* inReach)
{
    constexpr double cMoved2 = 0.01 * 0.01;         // m^2: a move shallower than 1 cm is not the wall's
    constexpr double cSquare = 0.1;                 // m: the squares across the wall
    constexpr double cFacing = 0.25881904510252074; // cos 75 degrees
    // intent: arrays of different lengths measure nothing (NaN), rather than read past one of them
    if (inRestNormals.size() != inPositions.size() || inRest.mPositions.size() != inPositions.size())
        return {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN(), 0};
    // The wall's vertices: moved more than 1 cm, and within the wall's reach.
    auto moved = [&](std::size_t inVertex)
    {
        return (inPositions[inVertex] - inRest.mPositions[inVertex]).squaredNorm() > cMoved2 &&
               (inReach == nullptr || inReach->mAcross.dot(inRest.mPositions[inVertex]) >= inReach->mFrom);
    };
    // intent: the wall's final plane, the foremost moved point
    double plane = -std::numeric_limits<double>::infinity();
    for (std::size_t vertex = 0; vertex < inPositions.size(); ++vertex)
        if (moved(vertex))
            plane = std::max(plane, inIntoWall.dot(inPositions[vertex]));
    // intent: each square's foremost final position of the facing surface that lay ahead of the plane
    const Vec3 side = inIntoWall.unitOrthogonal(), third = inIntoWall.cross(side);
    std::map<std::pair<std::int64_t, std::int64_t>, double> foremost;
    for (std::size_t vertex = 0; vertex < inPositions.size(); ++vertex)
    {
        const Vec3& now = inPositions[vertex];
        if (!moved(vertex) || !(inIntoWall.dot(inRest.mPositions[vertex]) > plane) ||
            !(std::abs(inIntoWall.dot(inRestNormals[vertex])) >= cFacing))
            continue;
        // The square where the vertex crosses the wall now (a crush moves it along the wall's normal).
        const std::pair<std::int64_t, std::int64_t> square{
            static_cast<std::int64_t>(std::floor(side.dot(now) / cSquare)),
            static_cast<std::int64_t>(std::floor(third.dot(now) / cSquare))};
        const auto [place, added] = foremost.try_emplace(square, inIntoWall.dot(now));
        if (!added)
            place->second = std::max(place->second, inIntoWall.dot(now));
    }
    WallGap gap;
    for (const auto& [square, ahead] : foremost)
    {
        gap.mMean += plane - ahead;
        gap.mLargest = std::max(gap.mLargest, plane - ahead);
    }
    gap.mSquares = static_cast<int>(foremost.size());
    if (gap.mSquares > 0)
        gap.mMean /= gap.mSquares;
    return gap;
}

} // namespace crumple::crash
