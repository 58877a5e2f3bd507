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
#include <span>
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

/// The grid step for a range shown in about inDivisions parts: 1, 2, 2.5 or 5 times a power of ten.
inline double NiceStep(double inRange, int inDivisions)
{
    return RoundUpToNiceNumber(std::max(inRange, 1e-12) / inDivisions);
}

/// A line chart of quantities against time on an 800 x 400 canvas: x from mX0 to mX1, y from mY0 to mY1
/// (widened to round grid steps), both axes titled with their units, series drawn as polylines and named
/// in a legend.
struct LineChart
{
    static constexpr int cWidth = 800, cHeight = 400, cLeft = 80, cBottom = 340, cRight = 770, cTop = 40;
    double mX0 = 0.0, mX1 = 1.0, mY0 = 0.0, mY1 = 1.0;
    std::string mXTitle, mYTitle;

    double X(double inX) const { return cLeft + (cRight - cLeft) * (inX - mX0) / (mX1 - mX0); }
    double Y(double inY) const { return cBottom - (cBottom - cTop) * (inY - mY0) / (mY1 - mY0); }

    /// Widens the y range to round steps (and to include 0), then draws the grid, ticks, titles and axes.
    PlotCanvas Draw()
    {
        mY0 = std::min(mY0, 0.0);
        mY1 = std::max(mY1, mY0 + 1e-9);
        mY1 += 0.2 * (mY1 - mY0); // headroom for the legend
        const double y_step = NiceStep(mY1 - mY0, 5), x_step = NiceStep(mX1 - mX0, 8);
        mY0 = std::floor(mY0 / y_step + 1e-9) * y_step;
        mY1 = std::ceil(mY1 / y_step - 1e-9) * y_step;
        PlotCanvas canvas(cWidth, cHeight);
        const std::array<std::uint8_t, 3> black{0, 0, 0}, grey{215, 215, 215}, label{60, 60, 60};
        char tick[32];
        for (double x = std::ceil(mX0 / x_step) * x_step; x <= mX1 + 1e-9 * x_step; x += x_step)
        {
            canvas.Line(X(x), cBottom, X(x), cTop, 1, grey);
            std::snprintf(tick, sizeof(tick), "%g", std::abs(x) < 1e-12 ? 0.0 : x);
            canvas.Text(static_cast<int>(X(x)) - render::TextWidth(tick, 2) / 2, cBottom + 8, tick, 2, label);
        }
        for (double y = mY0; y <= mY1 + 1e-9 * y_step; y += y_step)
        {
            canvas.Line(cLeft, Y(y), cRight, Y(y), 1, grey);
            std::snprintf(tick, sizeof(tick), "%g", std::abs(y) < 1e-12 * y_step ? 0.0 : y);
            canvas.Text(cLeft - 8 - render::TextWidth(tick, 2), static_cast<int>(Y(y)) - 6, tick, 2, label);
        }
        canvas.Text((cLeft + cRight) / 2 - render::TextWidth(mXTitle, 2) / 2, cBottom + 32, mXTitle, 2, label);
        canvas.Text(8, cTop - 30, mYTitle, 2, label);
        canvas.Line(cLeft, Y(0.0), cRight, Y(0.0), 2, black);
        canvas.Line(cLeft, cBottom, cLeft, cTop, 2, black);
        return canvas;
    }

    /// The series (inX[i], inY[i]) as a polyline, points outside the x range left out.
    void Series(PlotCanvas& ioCanvas, std::span<const double> inX, std::span<const double> inY, std::array<std::uint8_t, 3> inColour) const
    {
        for (std::size_t i = 1; i < std::min(inX.size(), inY.size()); ++i)
            if (inX[i - 1] >= mX0 && inX[i] <= mX1)
                ioCanvas.Line(X(inX[i - 1]), Y(inY[i - 1]), X(inX[i]), Y(inY[i]), 2, inColour);
    }

    /// Legend entry inRow at the chart's top right.
    static void AddLegend(PlotCanvas& ioCanvas, int inRow, std::array<std::uint8_t, 3> inColour, const std::string& inText)
    {
        const int x = cRight - 20 - render::TextWidth(inText, 2) - 30, y = cTop + 10 + 24 * inRow;
        for (int dy = 0; dy < 4; ++dy)
            ioCanvas.Line(x, y + 4 + dy, x + 20, y + 4 + dy, 1, inColour);
        ioCanvas.Text(x + 28, y - 1, inText, 2, {60, 60, 60});
    }
};

} // namespace crumple::crash
