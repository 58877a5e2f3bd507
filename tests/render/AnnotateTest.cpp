// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// Text and colour legends drawn into pictures (no GL: plain pixels).

#include <crumple/render/Annotate.h>

#include <catch2/catch.hpp>

#include <cstdint>
#include <vector>

using namespace crumple;
using namespace crumple::render;

namespace
{

struct Canvas
{
    int mWidth, mHeight;
    std::vector<std::uint8_t> mPixels;
    Canvas(int inWidth, int inHeight) : mWidth(inWidth), mHeight(inHeight), mPixels(4 * inWidth * inHeight, 255) {}
    RgbaImage Image() { return {mPixels, mWidth, mHeight}; }
    Rgb At(int inX, int inY) const
    {
        const std::uint8_t* p = &mPixels[4 * (inY * mWidth + inX)];
        return {p[0], p[1], p[2]};
    }
    int Inked(int inX0, int inY0, int inX1, int inY1) const
    {
        int count = 0;
        for (int y = inY0; y < inY1; ++y)
            for (int x = inX0; x < inX1; ++x)
                count += At(x, y) != Rgb{255, 255, 255} ? 1 : 0;
        return count;
    }
};

} // namespace

TEST_CASE("DrawText inks the text's box only, as wide as TextWidth says, and clips at the edges", "[render]")
{
    Canvas canvas(200, 60);
    const int width = DrawText(canvas.Image(), 10, 10, "dent depth (m)", 2, {0, 0, 0});
    CHECK(width == TextWidth("dent depth (m)", 2));
    CHECK(width > 100);
    CHECK(canvas.Inked(10, 10, 10 + width, 30) > 50);
    CHECK(canvas.Inked(0, 0, 200, 60) == canvas.Inked(10, 10, 10 + width, 30)); // nothing outside
    // Half outside the picture: no write past its edges (the vector's size is the check under ASan).
    DrawText(canvas.Image(), 190, 55, "0.375", 3, {0, 0, 0});
    DrawText(canvas.Image(), -20, -5, "0.375", 3, {0, 0, 0});
    CHECK(canvas.mPixels.size() == 4u * 200u * 60u);
}

TEST_CASE("A colour legend's bar has the renderer's colours from the shown bottom to top, and labels", "[render]")
{
    Canvas canvas(800, 600);
    ColorLegend legend;
    legend.mMap = EColorMap::CoolWarm;
    legend.mMapMin = -0.5;
    legend.mMapMax = 0.5;
    legend.mShownMin = 0.0;
    legend.mShownMax = 0.5;
    legend.mTitle = "dent depth (m)";
    DrawColorLegend(canvas.Image(), legend);
    // Find the bar: the column of the right half whose middle row has the colour of 0.25.
    const Rgb middle = MapColor(EColorMap::CoolWarm, -0.5, 0.5, 0.25);
    int bar_x = -1;
    for (int x = 400; x < 800 && bar_x < 0; ++x)
        if (canvas.At(x, 300) == middle || canvas.At(x, 299) == middle)
            bar_x = x;
    REQUIRE(bar_x >= 0);
    // Its top is the top of the range, its bottom the bottom (the map's middle: CoolWarm's grey).
    const int top = (600 - 300) / 2, bottom = top + 300 - 1;
    CHECK(canvas.At(bar_x + 2, top) == MapColor(EColorMap::CoolWarm, -0.5, 0.5, 0.5));
    CHECK(canvas.At(bar_x + 2, bottom) == MapColor(EColorMap::CoolWarm, -0.5, 0.5, 0.0));
    // The map saturates at its end, Moreland's cool-warm red (0.705673, 0.015556, 0.150233).
    const Rgb warm = MapColor(EColorMap::CoolWarm, -0.5, 0.5, 9.0);
    CHECK(warm == MapColor(EColorMap::CoolWarm, -0.5, 0.5, 0.5));
    CHECK(warm[0] == std::lround(255.0 * 0.705673));
    CHECK(warm[1] == std::lround(255.0 * 0.015556));
    CHECK(warm[2] == std::lround(255.0 * 0.150233));
    // Title above the bar and tick labels to its right are inked.
    CHECK(canvas.Inked(500, top - 30, 800, top - 2) > 50);
    CHECK(canvas.Inked(bar_x + 30, top - 8, 800, bottom + 8) > 100);
}
