// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Result.h>
#include <crumple/ffd/TriangleMesh.h>
#include <crumple/render/Camera.h>
#include <crumple/render/MeshRenderer.h>

#include <filesystem>
#include <memory>
#include <span>
#include <vector>

namespace crumple::samples
{

/// Paints pictures of a scene made of several meshes (cars, barriers, the ground) with the headless
/// renderer: meshes are placed in the world, merged, coloured by a per-vertex scalar (dent depth) and
/// written as PNG with a colour legend (the dent depth from 0 to the scale's top, in metres). Holds the EGL
/// context, so create one painter per program, and only when pictures are wanted (a scene without pictures
/// pays for no EGL context).
class ScenePainter
{
public:
    /// @param inScalarMax  the colour scale's top (m, > 0): deeper dents take its colour (DentColorScale)
    static Result<std::unique_ptr<ScenePainter>> Create(int inWidth, int inHeight, double inScalarMax);
    /// Sets the colour scale's top (m, > 0) for the next pictures.
    Status SetScalarMax(double inScalarMax);

    /// Starts a new picture.
    void Clear();
    /// Adds a mesh placed by inTransform (body to world); inScalars may be empty (uncoloured).
    void Add(std::span<const Vec3> inPositions, std::span<const Vec3> inNormals,
             std::span<const std::array<std::uint32_t, 3>> inTriangles, std::span<const double> inScalars,
             const Transform& inTransform);
    /// Adds a box (half extents) placed by inTransform.
    void AddBox(const Vec3& inHalfExtents, const Transform& inTransform);
    /// Renders what was added and writes a PNG.
    Status Paint(const render::Camera& inCamera, const std::filesystem::path& inPath);

    int GetWidth() const { return mWidth; }
    int GetHeight() const { return mHeight; }

private:
    ScenePainter() = default;

    std::unique_ptr<gpu::EglContext> mContext;
    std::unique_ptr<render::MeshRenderer> mRenderer;
    int mWidth = 0, mHeight = 0;
    double mScalarMax = 0.0;
    std::vector<Vec3> mPositions, mNormals;
    std::vector<std::array<std::uint32_t, 3>> mTriangles;
    std::vector<double> mScalars;
    std::vector<std::uint8_t> mPixels;
};

/// The top of the dent colour scale both crumple-crash and crumple-replay use unless told one
/// (--colour-max): the deepest dent rounded up to 1, 2, 2.5 or 5 times a power of ten, at least 1 cm, so
/// that the same damage gets the same colours in both tools and the legend's ticks are round numbers.
double DentColorScale(double inDeepest);

/// Per-vertex dent depth |deformed - rest| (m), for colouring.
std::vector<double> DentDepths(std::span<const Vec3> inDeformed, std::span<const Vec3> inRest);

} // namespace crumple::samples
