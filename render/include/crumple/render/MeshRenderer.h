// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>
#include <crumple/base/Math.h>
#include <crumple/base/Result.h>
#include <crumple/gpu/EglContext.h>
#include <crumple/render/Camera.h>
#include <crumple/render/RenderSettings.h>

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace crumple::render
{

struct RenderGlFunctions;

/// Draws triangle meshes into an offscreen framebuffer (RGBA8 colour, 24-bit depth, optional multisampling)
/// of a headless EglContext and reads the picture back, upright (first row is the top of the image).
///
/// The renderer keeps a reference to the context: the context must outlive it. Each call makes the context
/// current on the calling thread; use a renderer from one thread at a time. Positions are converted to float
/// relative to the eye, so meshes far from the world origin keep their precision.
class CRUMPLE_API MeshRenderer
{
public:
    /// Largest width or height accepted (pixels); the driver's renderbuffer limit may be lower.
    static constexpr int cMaxSize = 16384;

    /// Compiles the shaders and makes the framebuffer. Fails with EError::InvalidArgument for a size outside
    /// 1..cMaxSize (or the driver's limit) or bad settings, and EError::IoError when the driver refuses
    /// (shader log or framebuffer status in the message).
    /// @param[in] inWidth  image width (pixels)
    /// @param[in] inHeight image height (pixels)
    static Result<std::unique_ptr<MeshRenderer>> Create(gpu::EglContext& ioContext, int inWidth, int inHeight,
                                                        const RenderSettings& inSettings = {});

    /// Deletes the GL objects (makes the context current on this thread to do so).
    ~MeshRenderer();

    MeshRenderer(const MeshRenderer&) = delete;
    MeshRenderer& operator=(const MeshRenderer&) = delete;

    /// Replaces the settings; remakes the framebuffer when the sample count changes. Refused (nothing
    /// changed) for negative intensities, non-finite values or a zero key light direction.
    Status SetSettings(const RenderSettings& inSettings);
    const RenderSettings& GetSettings() const { return mSettings; }

    /// Image width (pixels)
    int GetWidth() const { return mWidth; }
    /// Image height (pixels)
    int GetHeight() const { return mHeight; }

    /// Draws one mesh over the background and returns the picture. Refused (EError::InvalidArgument,
    /// EError::NonFinite, EError::OutOfRange) for mismatched sizes, non-finite values, indices out of range
    /// or an invalid camera; an empty mesh gives the background.
    /// @param[in]  inPositions #V vertex positions, world frame (m)
    /// @param[in]  inNormals   #V vertex normals, world frame (need not be unit; zero means "face the eye")
    /// @param[in]  inTriangles #F vertex index triples (either winding; both sides are lit)
    /// @param[in]  inScalars   #V per-vertex scalars coloured through RenderSettings::mColorMap between
    ///                         mScalarMin and mScalarMax (e.g. displacement magnitude, m), or empty for the
    ///                         base colour
    /// @param[in]  inCamera    the view; the image aspect is GetWidth() / GetHeight()
    /// @param[out] outRgba     GetWidth() * GetHeight() * 4 bytes, RGBA, rows top to bottom
    Status Render(std::span<const Vec3> inPositions, std::span<const Vec3> inNormals,
                  std::span<const std::array<std::uint32_t, 3>> inTriangles,
                  std::span<const double> inScalars, const Camera& inCamera,
                  std::vector<std::uint8_t>& outRgba);

private:
    MeshRenderer(gpu::EglContext& ioContext, int inWidth, int inHeight);

    /// Compiles and links the program, looks up its uniforms, makes the vertex arrays.
    Status CreateProgram();
    /// (Re)makes the multisampled draw framebuffer and the single-sample resolve framebuffer.
    Status CreateFramebuffers(int inSampleCount);
    /// Deletes the framebuffers and their renderbuffers.
    void DeleteFramebuffers();

    gpu::EglContext& mContext;              ///< Not owned; outlives the renderer
    std::unique_ptr<RenderGlFunctions> mGl; ///< GL entry points, loaded from mContext
    RenderSettings mSettings;               ///< Current look
    int mWidth = 0;                         ///< Image width (pixels)
    int mHeight = 0;                        ///< Image height (pixels)
    int mSampleCount = 0;                   ///< Samples of the draw framebuffer in use

    unsigned int mProgram = 0;                        ///< Shader program
    unsigned int mVertexArray = 0;                    ///< Vertex array object
    std::array<unsigned int, 4> mBuffers{};           ///< Position, normal, scalar and index buffers
    unsigned int mDrawFramebuffer = 0;                ///< Multisampled colour + depth
    std::array<unsigned int, 2> mDrawRenderbuffers{}; ///< Colour, depth of the draw framebuffer
    unsigned int mResolveFramebuffer = 0;             ///< Single-sample colour, read back
    unsigned int mResolveRenderbuffer = 0;            ///< Colour of the resolve framebuffer

    /// Uniform locations of the program (-1: not used by the driver's compiled program)
    struct Uniforms
    {
        int mViewProjection = -1;     ///< mat4 projection * view rotation
        int mBaseColor = -1;          ///< vec3 albedo without scalars
        int mKeyDirection = -1;       ///< vec3 unit direction towards the key light, world frame
        int mAmbient = -1;            ///< float ambient intensity
        int mKeyIntensity = -1;       ///< float key light intensity
        int mHeadlightIntensity = -1; ///< float headlight intensity
        int mUseScalars = -1;         ///< int, 1 when scalars colour the mesh
        int mColorCount = -1;         ///< int entries of the colour table
        int mColors = -1;             ///< vec3[16] colour table
    } mUniforms;
};

} // namespace crumple::render
