// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "ScenePainter.h"
#include "BoxMesh.h"

#include <crumple/render/Annotate.h>
#include <crumple/render/WritePng.h>

#include <cmath>

namespace crumple::samples
{

Result<std::unique_ptr<ScenePainter>> ScenePainter::Create(int inWidth, int inHeight, double inScalarMax)
{
    std::unique_ptr<ScenePainter> painter(new ScenePainter());
    Result<std::unique_ptr<gpu::EglContext>> context = gpu::EglContext::Create({});
    if (!context)
        return context.GetError();
    painter->mContext = std::move(context).Get();
    render::RenderSettings settings;
    // Diverging map centred on zero: undamaged surfaces stay grey, dents turn red as they deepen.
    settings.mColorMap = render::EColorMap::CoolWarm;
    settings.mScalarMin = -inScalarMax;
    settings.mScalarMax = inScalarMax;
    Result<std::unique_ptr<render::MeshRenderer>> renderer =
        render::MeshRenderer::Create(*painter->mContext, inWidth, inHeight, settings);
    if (!renderer)
        return renderer.GetError();
    painter->mRenderer = std::move(renderer).Get();
    painter->mWidth = inWidth;
    painter->mHeight = inHeight;
    if (Status scale = painter->SetScalarMax(inScalarMax); !scale)
        return scale.GetError();
    return painter;
}

Status ScenePainter::SetScalarMax(double inScalarMax)
{
    if (!std::isfinite(inScalarMax) || !(inScalarMax > 0.0))
        return MakeError(EError::InvalidArgument, "ScenePainter: the colour scale's top must be finite and > 0 m");
    render::RenderSettings settings = mRenderer->GetSettings();
    settings.mScalarMin = -inScalarMax;
    settings.mScalarMax = inScalarMax;
    if (Status set = mRenderer->SetSettings(settings); !set)
        return set;
    mScalarMax = inScalarMax;
    return Status::Ok();
}

double DentColorScale(double inDeepest)
{
    return RoundUpToNiceNumber(std::isfinite(inDeepest) ? std::max(inDeepest, 0.01) : 0.01);
}

void ScenePainter::Clear()
{
    mPositions.clear();
    mNormals.clear();
    mTriangles.clear();
    mScalars.clear();
}

void ScenePainter::Add(std::span<const Vec3> inPositions, std::span<const Vec3> inNormals,
                       std::span<const std::array<std::uint32_t, 3>> inTriangles, std::span<const double> inScalars,
                       const Transform& inTransform)
{
    const auto base = static_cast<std::uint32_t>(mPositions.size());
    for (std::size_t v = 0; v < inPositions.size(); ++v)
    {
        mPositions.push_back(inTransform.ToWorld(inPositions[v]));
        mNormals.push_back(v < inNormals.size() ? Vec3(inTransform.mRotation * inNormals[v]) : Vec3::Zero());
        mScalars.push_back(v < inScalars.size() ? inScalars[v] : 0.0);
    }
    for (const auto& t : inTriangles)
        mTriangles.push_back({base + t[0], base + t[1], base + t[2]});
}

void ScenePainter::AddBox(const Vec3& inHalfExtents, const Transform& inTransform)
{
    // Flat faces: three vertices of its own per triangle, with the face normal.
    const ffd::TriangleMesh box = common::MakeBoxMesh(inHalfExtents, {1, 1, 1});
    std::vector<Vec3> positions, normals;
    std::vector<std::array<std::uint32_t, 3>> triangles;
    for (const auto& t : box.mTriangles)
    {
        const Vec3 normal = (box.mPositions[t[1]] - box.mPositions[t[0]]).cross(box.mPositions[t[2]] - box.mPositions[t[0]]);
        const auto base = static_cast<std::uint32_t>(positions.size());
        for (std::uint32_t corner : t)
        {
            positions.push_back(box.mPositions[corner]);
            normals.push_back(normal.normalized());
        }
        triangles.push_back({base, base + 1, base + 2});
    }
    Add(positions, normals, triangles, {}, inTransform);
}

Status ScenePainter::Paint(const render::Camera& inCamera, const std::filesystem::path& inPath)
{
    if (Status rendered = mRenderer->Render(mPositions, mNormals, mTriangles, mScalars, inCamera, mPixels); !rendered)
        return rendered;
    // The diverging map is centred on zero; depths are >= 0, so the legend shows its upper half.
    render::ColorLegend legend;
    legend.mMap = render::EColorMap::CoolWarm;
    legend.mMapMin = -mScalarMax;
    legend.mMapMax = mScalarMax;
    legend.mShownMin = 0.0;
    legend.mShownMax = mScalarMax;
    legend.mTitle = "dent depth (m)";
    render::DrawColorLegend({mPixels, mWidth, mHeight}, legend);
    return render::WritePng(inPath, mWidth, mHeight, mPixels);
}

std::vector<double> DentDepths(std::span<const Vec3> inDeformed, std::span<const Vec3> inRest)
{
    std::vector<double> depths(inDeformed.size());
    for (std::size_t v = 0; v < inDeformed.size(); ++v)
        depths[v] = (inDeformed[v] - inRest[v]).norm();
    return depths;
}

} // namespace crumple::samples
