// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "ColorMapTable.h"

#include <crumple/render/Annotate.h>

#include <stb/stb_easy_font.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace crumple::render
{

namespace
{

void FillRect(RgbaImage ioImage, int inX0, int inY0, int inX1, int inY1, Rgb inColour)
{
    for (int y = std::max(inY0, 0); y < std::min(inY1, ioImage.mHeight); ++y)
        for (int x = std::max(inX0, 0); x < std::min(inX1, ioImage.mWidth); ++x)
        {
            std::uint8_t* pixel = &ioImage.mPixels[4 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(ioImage.mWidth) + static_cast<std::size_t>(x))];
            pixel[0] = inColour[0];
            pixel[1] = inColour[1];
            pixel[2] = inColour[2];
            pixel[3] = 255;
        }
}

// stb_easy_font reads a mutable, zero-terminated string of printable characters.
std::vector<char> Printable(std::string_view inText)
{
    std::vector<char> text;
    for (char c : inText)
        if (c >= 32 && c < 127)
            text.push_back(c);
    text.push_back('\0');
    return text;
}

} // namespace

int TextWidth(std::string_view inText, int inScale)
{
    std::vector<char> text = Printable(inText);
    return stb_easy_font_width(text.data()) * std::max(inScale, 1);
}

int DrawText(RgbaImage ioImage, int inX, int inY, std::string_view inText, int inScale, Rgb inColour)
{
    const int scale = std::max(inScale, 1);
    std::vector<char> text = Printable(inText);
    // Each quad: four vertices of x, y, z (floats) and an RGBA colour; about 270 bytes per character.
    std::vector<char> quads(300 * text.size() + 1000);
    const int count = stb_easy_font_print(0.0f, 0.0f, text.data(), nullptr, quads.data(), static_cast<int>(quads.size()));
    for (int quad = 0; quad < count; ++quad)
    {
        // intent: the quad's opposite corners (vertices 0 and 2), scaled, as a filled rectangle
        const auto* vertex = reinterpret_cast<const float*>(quads.data() + static_cast<std::size_t>(quad) * 64);
        const float* corner = reinterpret_cast<const float*>(quads.data() + static_cast<std::size_t>(quad) * 64 + 32);
        FillRect(ioImage, inX + static_cast<int>(vertex[0]) * scale, inY + static_cast<int>(vertex[1]) * scale,
                 inX + static_cast<int>(corner[0]) * scale, inY + static_cast<int>(corner[1]) * scale, inColour);
    }
    return stb_easy_font_width(text.data()) * scale;
}

Rgb MapColor(EColorMap inMap, double inMapMin, double inMapMax, double inValue)
{
    const std::span<const std::array<float, 3>> table = ColorMapTable(inMap);
    const double t = std::clamp((inValue - inMapMin) / (inMapMax - inMapMin), 0.0, 1.0) * static_cast<double>(table.size() - 1);
    const auto low = std::min(static_cast<std::size_t>(t), table.size() - 2);
    const double f = t - static_cast<double>(low);
    Rgb colour{};
    for (std::size_t c = 0; c < 3; ++c)
        colour[c] = static_cast<std::uint8_t>(std::lround(255.0 * ((1.0 - f) * table[low][c] + f * table[low + 1][c])));
    return colour;
}

void DrawColorLegend(RgbaImage ioImage, const ColorLegend& inLegend)
{
    const int scale = ioImage.mHeight >= 400 ? 2 : 1;
    const int bar_width = 14 * scale, bar_height = ioImage.mHeight / 2;
    char label[32];
    int label_width = 0;
    for (int tick = 0; tick <= 4; ++tick)
    {
        std::snprintf(label, sizeof(label), "%.3g", inLegend.mShownMin + (inLegend.mShownMax - inLegend.mShownMin) * tick / 4.0);
        label_width = std::max(label_width, TextWidth(label, scale));
    }
    const int right = ioImage.mWidth - 8 * scale;
    const int bar_x = right - label_width - 4 * scale - bar_width;
    const int top = (ioImage.mHeight - bar_height) / 2;
    const Rgb ink{40, 40, 40};
    // Title above the bar, kept inside the picture.
    const int title_width = TextWidth(inLegend.mTitle, scale);
    DrawText(ioImage, std::min(bar_x, ioImage.mWidth - title_width - 4 * scale), top - 14 * scale, inLegend.mTitle, scale, ink);
    // The bar, top row the top of the range, framed.
    for (int row = 0; row < bar_height; ++row)
    {
        const double value = inLegend.mShownMax - (inLegend.mShownMax - inLegend.mShownMin) * row / std::max(bar_height - 1, 1);
        FillRect(ioImage, bar_x, top + row, bar_x + bar_width, top + row + 1,
                 MapColor(inLegend.mMap, inLegend.mMapMin, inLegend.mMapMax, value));
    }
    FillRect(ioImage, bar_x - 1, top - 1, bar_x + bar_width + 1, top, ink);
    FillRect(ioImage, bar_x - 1, top + bar_height, bar_x + bar_width + 1, top + bar_height + 1, ink);
    FillRect(ioImage, bar_x - 1, top, bar_x, top + bar_height, ink);
    FillRect(ioImage, bar_x + bar_width, top, bar_x + bar_width + 1, top + bar_height, ink);
    for (int tick = 0; tick <= 4; ++tick)
    {
        const int y = top + (bar_height - 1) * (4 - tick) / 4;
        std::snprintf(label, sizeof(label), "%.3g", inLegend.mShownMin + (inLegend.mShownMax - inLegend.mShownMin) * tick / 4.0);
        FillRect(ioImage, bar_x + bar_width, y, bar_x + bar_width + 3 * scale, y + 1, ink);
        DrawText(ioImage, bar_x + bar_width + 4 * scale, y - 3 * scale, label, scale, ink);
    }
}

} // namespace crumple::render
