// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Result.h>
#include <crumple/render/WritePng.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <vector>

namespace crumple::crash
{

// A white RGBA canvas with the few drawing operations a plot needs.
class PlotCanvas
{
public:
    PlotCanvas(int inWidth, int inHeight) : mWidth(inWidth), mHeight(inHeight), mPixels(4 * inWidth * inHeight, 255) {}

    void Dot(int inX, int inY, std::array<std::uint8_t, 3> inColour)
    {
        if (inX < 0 || inY < 0 || inX >= mWidth || inY >= mHeight)
            return;
        std::uint8_t* pixel = &mPixels[4 * (inY * mWidth + inX)];
        pixel[0] = inColour[0];
        pixel[1] = inColour[1];
        pixel[2] = inColour[2];
    }
    void Line(double inX0, double inY0, double inX1, double inY1, int inThickness, std::array<std::uint8_t, 3> inColour)
    {
        const int steps = static_cast<int>(std::max(std::abs(inX1 - inX0), std::abs(inY1 - inY0))) + 1;
        for (int step = 0; step <= steps; ++step)
        {
            const double t = step / static_cast<double>(steps);
            Disc(inX0 + t * (inX1 - inX0), inY0 + t * (inY1 - inY0), 0.5 * inThickness, inColour);
        }
    }
    void Disc(double inX, double inY, double inRadius, std::array<std::uint8_t, 3> inColour)
    {
        for (int y = static_cast<int>(inY - inRadius); y <= static_cast<int>(inY + inRadius); ++y)
            for (int x = static_cast<int>(inX - inRadius); x <= static_cast<int>(inX + inRadius); ++x)
                if ((x - inX) * (x - inX) + (y - inY) * (y - inY) <= inRadius * inRadius + 0.25)
                    Dot(x, y, inColour);
    }
    Status Save(const std::filesystem::path& inPath) const { return render::WritePng(inPath, mWidth, mHeight, mPixels); }

private:
    int mWidth, mHeight;
    std::vector<std::uint8_t> mPixels;
};


} // namespace crumple::crash
