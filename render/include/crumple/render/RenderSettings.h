// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Math.h>
#include <crumple/render/EColorMap.h>

#include <array>

namespace crumple::render
{

/// Look of a MeshRenderer's pictures. Shading per pixel is
///   colour = albedo * (mAmbient + mKeyIntensity * max(n.l, 0) + mHeadlightIntensity * max(n.v, 0)),
/// clamped to 1, with n the interpolated vertex normal (flipped towards the eye, so open panels are lit on
/// both sides), l the key light direction and v the direction to the eye. Colours are RGB(A) in [0, 1].
struct CRUMPLE_API RenderSettings
{
    /// Flat background RGBA; alpha 0 gives a transparent PNG
    std::array<float, 4> mBackgroundColor{1.0f, 1.0f, 1.0f, 1.0f};
    /// Albedo RGB when Render gets no scalars (light steel grey)
    std::array<float, 3> mBaseColor{0.72f, 0.74f, 0.78f};
    /// Towards the key light, world frame (normalised when used), != 0; default: above, right and ahead
    Vec3 mKeyLightDirection{0.3, -0.5, 1.0};
    float mAmbient = 0.15f;                   ///< Light everywhere, >= 0
    float mKeyIntensity = 0.55f;              ///< Key (directional) light, >= 0
    float mHeadlightIntensity = 0.35f;        ///< Light from the eye, >= 0
    EColorMap mColorMap = EColorMap::Viridis; ///< Scalar to albedo, used when Render gets scalars
    /// Scalar at the map's low end (scalar units, e.g. m for displacement); values outside are clamped
    double mScalarMin = 0.0;
    /// Scalar at the map's high end; when <= mScalarMin each Render uses its data's range instead
    double mScalarMax = 0.0;
    /// Multisample anti-aliasing samples per pixel, 1 (off) to 16; capped by the driver's GL_MAX_SAMPLES
    int mSampleCount = 4;
};

} // namespace crumple::render
