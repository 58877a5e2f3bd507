// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Result.h>
#include <crumple/render/WritePng.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
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
    /// Writes inText (digits, '.', '-', '/', 'k', 'm', 'h', ' ') at (inX, inY) top-left, 3 x 5 glyphs scaled by
    /// inScale: enough for tick labels and units without a font library.
    void Text(int inX, int inY, const std::string& inText, int inScale, std::array<std::uint8_t, 3> inColour)
    {
        for (char character : inText)
        {
            const std::uint16_t glyph = Glyph(character);
            for (int row = 0; row < 5; ++row)
                for (int column = 0; column < 3; ++column)
                    if ((glyph >> (14 - 3 * row - column)) & 1u)
                        for (int dy = 0; dy < inScale; ++dy)
                            for (int dx = 0; dx < inScale; ++dx)
                                Dot(inX + column * inScale + dx, inY + row * inScale + dy, inColour);
            inX += 4 * inScale;
        }
    }
    Status Save(const std::filesystem::path& inPath) const { return render::WritePng(inPath, mWidth, mHeight, mPixels); }

private:
    // 15-bit 3 x 5 glyphs, rows top to bottom, most significant bit first.
    static std::uint16_t Glyph(char inCharacter)
    {
        switch (inCharacter)
        {
        case '0': return 0b111101101101111;
        case '1': return 0b010110010010111;
        case '2': return 0b111001111100111;
        case '3': return 0b111001111001111;
        case '4': return 0b101101111001001;
        case '5': return 0b111100111001111;
        case '6': return 0b111100111101111;
        case '7': return 0b111001001001001;
        case '8': return 0b111101111101111;
        case '9': return 0b111101111001111;
        case '.': return 0b000000000000010;
        case '-': return 0b000000111000000;
        case '/': return 0b001001010100100;
        case 'k': return 0b100101110101101;
        case 'm': return 0b000111111101101;
        case 'h': return 0b100100111101101;
        default: return 0;
        }
    }

    int mWidth, mHeight;
    std::vector<std::uint8_t> mPixels;
};


/// A residual-crush-against-impact-speed chart on an 800 x 500 canvas: speed 0 to mRightKmh (grid and labels
/// every 10 km/h), crush 0 to mTop (every 0.1 m).
struct CrushSpeedChart
{
    static constexpr int cWidth = 800, cHeight = 500, cLeft = 60, cBottom = 440, cRight = 770, cTop = 30;
    double mRightKmh = 70.0; ///< km/h
    double mTop = 0.1;       ///< m

    double X(double inKmh) const { return cLeft + (cRight - cLeft) * inKmh / mRightKmh; }
    double Y(double inCrush) const { return cBottom - (cBottom - cTop) * inCrush / mTop; }

    /// A canvas with the grid, tick labels, units and axes drawn.
    PlotCanvas Draw() const
    {
        PlotCanvas canvas(cWidth, cHeight);
        const std::array<std::uint8_t, 3> black{0, 0, 0}, grey{200, 200, 200}, label{60, 60, 60};
        for (double kmh = 0.0; kmh <= mRightKmh; kmh += 10.0)
            canvas.Text(static_cast<int>(X(kmh)) - 6, cBottom + 8, std::to_string(static_cast<int>(kmh)), 2, label);
        canvas.Text(cRight - 40, cBottom + 28, "km/h", 2, label);
        for (double crush = 0.0; crush <= mTop + 1e-9; crush += 0.1)
        {
            char tick[16];
            std::snprintf(tick, sizeof(tick), "%.1f", crush);
            canvas.Text(cLeft - 40, static_cast<int>(Y(crush)) - 5, tick, 2, label);
        }
        canvas.Text(cLeft - 40, cTop - 24, "m", 2, label);
        for (double kmh = 10.0; kmh <= mRightKmh; kmh += 10.0)
            canvas.Line(X(kmh), cBottom, X(kmh), cTop, 1, grey);
        for (double crush = 0.1; crush <= mTop + 1e-9; crush += 0.1)
            canvas.Line(cLeft, Y(crush), cRight, Y(crush), 1, grey);
        canvas.Line(cLeft, cBottom, cRight, cBottom, 2, black);
        canvas.Line(cLeft, cBottom, cLeft, cTop, 2, black);
        return canvas;
    }
};

} // namespace crumple::crash
