// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Result.h>
#include <crumple/crash/Calibration.h>
#include <crumple/render/Annotate.h>
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
    /// Writes inText (printable ASCII) at (inX, inY) top-left, stb_easy_font scaled by inScale.
    void Text(int inX, int inY, const std::string& inText, int inScale, std::array<std::uint8_t, 3> inColour)
    {
        render::DrawText(Image(), inX, inY, inText, inScale, inColour);
    }
    /// Fills the quadrilateral with corners inCorners (x, y), in order around it, with inColour.
    void Fill(const std::array<std::array<double, 2>, 4>& inCorners, std::array<std::uint8_t, 3> inColour)
    {
        double top = inCorners[0][1], bottom = top;
        for (const auto& corner : inCorners)
        {
            top = std::min(top, corner[1]);
            bottom = std::max(bottom, corner[1]);
        }
        for (int y = static_cast<int>(std::ceil(top)); y <= static_cast<int>(bottom); ++y)
        {
            // intent: the span of the row inside the (convex) quadrilateral, from its edges' crossings
            double left = 1e30, right = -1e30;
            for (std::size_t i = 0; i < 4; ++i)
            {
                const auto& p = inCorners[i];
                const auto& q = inCorners[(i + 1) % 4];
                if ((p[1] - y) * (q[1] - y) > 0.0 || p[1] == q[1])
                    continue;
                const double x = p[0] + (q[0] - p[0]) * (y - p[1]) / (q[1] - p[1]);
                left = std::min(left, x);
                right = std::max(right, x);
            }
            for (int x = static_cast<int>(std::ceil(left)); x <= static_cast<int>(right); ++x)
                Dot(x, y, inColour);
        }
    }
    Status Save(const std::filesystem::path& inPath) const { return render::WritePng(inPath, mWidth, mHeight, mPixels); }

private:
    render::RgbaImage Image() { return {mPixels, mWidth, mHeight}; }

    int mWidth, mHeight;
    std::vector<std::uint8_t> mPixels;
};


/// A residual-crush-against-impact-speed chart on an 800 x 500 canvas: speed 0 to mRightKmh (grid and labels
/// every 10 km/h), crush 0 to mTop (every 0.1 m), axis titles, and Campbell's band of the crash data
/// (CampbellBand) shaded under the grid, named in the legend with what the caller draws (AddLegend).
struct CrushSpeedChart
{
    static constexpr int cWidth = 800, cHeight = 500, cLeft = 70, cBottom = 430, cRight = 770, cTop = 40;
    double mRightKmh = 70.0; ///< km/h
    double mTop = 0.1;       ///< m

    double X(double inKmh) const { return cLeft + (cRight - cLeft) * inKmh / mRightKmh; }
    double Y(double inCrush) const { return cBottom - (cBottom - cTop) * inCrush / mTop; }

    /// A canvas with the band, grid, tick labels, axis titles and axes drawn.
    PlotCanvas Draw() const
    {
        PlotCanvas canvas(cWidth, cHeight);
        const std::array<std::uint8_t, 3> black{0, 0, 0}, grey{200, 200, 200}, label{60, 60, 60};
        // Campbell's band, clipped to the chart: between its two lines from 0 to the right edge (crush 0 below b0).
        const CampbellBand band;
        auto y_in = [&](const CampbellLine& inLine, double inKmh) { return Y(std::min(inLine.Crush(inKmh / 3.6), mTop)); };
        for (double kmh = 0.0; kmh < mRightKmh; kmh += 0.5)
        {
            const double next = std::min(kmh + 0.5, mRightKmh);
            canvas.Fill({{{X(kmh), y_in(band.mLeast, kmh)}, {X(next), y_in(band.mLeast, next)}, {X(next), y_in(band.mMost, next)},
                          {X(kmh), y_in(band.mMost, kmh)}}},
                        cBand);
        }
        for (double kmh = 0.0; kmh <= mRightKmh; kmh += 10.0)
            canvas.Text(static_cast<int>(X(kmh)) - 6, cBottom + 8, std::to_string(static_cast<int>(kmh)), 2, label);
        canvas.Text((cLeft + cRight) / 2 - 110, cBottom + 34, "impact speed (km/h)", 2, label);
        for (double crush = 0.0; crush <= mTop + 1e-9; crush += 0.1)
        {
            char tick[16];
            std::snprintf(tick, sizeof(tick), "%.1f", crush);
            canvas.Text(cLeft - 44, static_cast<int>(Y(crush)) - 6, tick, 2, label);
        }
        canvas.Text(cLeft - 44, cTop - 30, "residual front crush (m)", 2, label);
        for (double kmh = 10.0; kmh <= mRightKmh; kmh += 10.0)
            canvas.Line(X(kmh), cBottom, X(kmh), cTop, 1, grey);
        for (double crush = 0.1; crush <= mTop + 1e-9; crush += 0.1)
            canvas.Line(cLeft, Y(crush), cRight, Y(crush), 1, grey);
        canvas.Line(cLeft, cBottom, cRight, cBottom, 2, black);
        canvas.Line(cLeft, cBottom, cLeft, cTop, 2, black);
        AddLegend(canvas, 0, cBand, "Campbell band (crash data, 16-56 km/h)");
        return canvas;
    }

    /// Legend entry inRow (0 is the band's) at the chart's top left: a swatch of inColour and inText.
    static void AddLegend(PlotCanvas& ioCanvas, int inRow, std::array<std::uint8_t, 3> inColour, const std::string& inText)
    {
        const int y = cTop + 10 + 24 * inRow;
        for (int dy = 0; dy < 12; ++dy)
            ioCanvas.Line(cLeft + 14, y + dy, cLeft + 34, y + dy, 1, inColour);
        ioCanvas.Text(cLeft + 42, y - 1, inText, 2, {60, 60, 60});
    }

    static constexpr std::array<std::uint8_t, 3> cBand{198, 232, 198};
};

} // namespace crumple::crash
