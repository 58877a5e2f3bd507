// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/render/EColorMap.h>

#include <array>
#include <cstdint>
#include <span>
#include <string_view>

namespace crumple::render
{

/// An RGBA picture in memory, rows top to bottom (MeshRenderer::Render's and WritePng's layout).
struct CRUMPLE_API RgbaImage
{
    std::span<std::uint8_t> mPixels; ///< mWidth * mHeight * 4 bytes
    int mWidth = 0;
    int mHeight = 0;
};

using Rgb = std::array<std::uint8_t, 3>;

/// Writes inText (printable ASCII; others are skipped) with its top-left corner at (inX, inY) pixels, in
/// stb_easy_font's segment font scaled by inScale (>= 1; at 1 a capital is 7 pixels tall). Pixels outside
/// the image are left out. @return the text's width in pixels
CRUMPLE_API int DrawText(RgbaImage ioImage, int inX, int inY, std::string_view inText, int inScale, Rgb inColour);

/// The width in pixels DrawText takes for inText at inScale.
CRUMPLE_API int TextWidth(std::string_view inText, int inScale);

/// What a colour legend shows: the map and the scalar range the picture was rendered with
/// (RenderSettings::mColorMap, mScalarMin, mScalarMax), the part of it to show (e.g. 0 to max of a
/// diverging map used for magnitudes) and the quantity with its unit.
struct CRUMPLE_API ColorLegend
{
    EColorMap mMap = EColorMap::Viridis;
    double mMapMin = 0.0;        ///< Scalar at the map's low end
    double mMapMax = 1.0;        ///< Scalar at its high end (> mMapMin)
    double mShownMin = 0.0;      ///< Scalar at the bar's bottom, within [mMapMin, mMapMax]
    double mShownMax = 1.0;      ///< At its top (> mShownMin)
    std::string_view mTitle;     ///< The quantity and its unit, e.g. "dent depth (m)"
};

/// Draws a vertical colour bar at the image's right edge, its colours those the renderer gives the scalars
/// it spans, with five labelled ticks and the title above it; values past the top end are the top colour
/// (the renderer clamps them).
CRUMPLE_API void DrawColorLegend(RgbaImage ioImage, const ColorLegend& inLegend);

/// The colour the renderer gives scalar inValue (clamped to [inMapMin, inMapMax]) before shading.
CRUMPLE_API Rgb MapColor(EColorMap inMap, double inMapMin, double inMapMax, double inValue);

} // namespace crumple::render
