// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/render/MeshRenderer.h>

#include "ColorMapTable.h"
#include "MeshShaderSource.h"
#include "RenderGlFunctions.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

namespace crumple::render
{

namespace
{

constexpr GLuint cPositionLocation = 0; ///< Vertex attribute: eye-relative position (vec3)
constexpr GLuint cNormalLocation = 1;   ///< Vertex attribute: normal (vec3)
constexpr GLuint cScalarLocation = 2;   ///< Vertex attribute: scalar mapped to [0, 1] (float)
constexpr int cMaxSamples = 16;         ///< Most multisamples RenderSettings may ask for

static_assert(sizeof(std::array<std::uint32_t, 3>) == 3 * sizeof(GLuint),
              "triangles upload as packed GLuints");
static_assert(sizeof(std::array<float, 3>) == 3 * sizeof(GLfloat), "colour tables upload as packed vec3s");

/// Name and hex value of a GL error, e.g. "GL_OUT_OF_MEMORY (0x0505)".
std::string GlErrorString(GLenum inError)
{
    const char* name = "unknown GL error";
    switch (inError)
    {
    case GL_INVALID_ENUM:
        name = "GL_INVALID_ENUM";
        break;
    case GL_INVALID_VALUE:
        name = "GL_INVALID_VALUE";
        break;
    case GL_INVALID_OPERATION:
        name = "GL_INVALID_OPERATION";
        break;
    case GL_INVALID_FRAMEBUFFER_OPERATION:
        name = "GL_INVALID_FRAMEBUFFER_OPERATION";
        break;
    case GL_OUT_OF_MEMORY:
        name = "GL_OUT_OF_MEMORY";
        break;
    default:
        break;
    }
    std::array<char, 16> hex{};
    std::snprintf(hex.data(), hex.size(), "0x%04X", inError);
    return std::string(name) + " (" + hex.data() + ")";
}

/// Checks the fields of RenderSettings; the message names the offending field.
Status ValidateSettings(const RenderSettings& inSettings)
{
    const auto in_unit = [](float inValue)
    { return std::isfinite(inValue) && inValue >= 0.0f && inValue <= 1.0f; };
    for (float value : inSettings.mBackgroundColor)
        if (!in_unit(value))
            return MakeError(EError::InvalidArgument, "RenderSettings.mBackgroundColor must be in [0, 1]");
    for (float value : inSettings.mBaseColor)
        if (!in_unit(value))
            return MakeError(EError::InvalidArgument, "RenderSettings.mBaseColor must be in [0, 1]");
    if (!IsFinite(inSettings.mKeyLightDirection) || inSettings.mKeyLightDirection.norm() <= 0.0)
        return MakeError(EError::InvalidArgument,
                         "RenderSettings.mKeyLightDirection must be finite and non-zero");
    for (float value : {inSettings.mAmbient, inSettings.mKeyIntensity, inSettings.mHeadlightIntensity})
        if (!std::isfinite(value) || value < 0.0f)
            return MakeError(EError::InvalidArgument,
                             "RenderSettings light intensities must be finite and >= 0");
    if (!IsFinite(inSettings.mScalarMin) || !IsFinite(inSettings.mScalarMax))
        return MakeError(EError::NonFinite, "RenderSettings.mScalarMin/mScalarMax must be finite");
    if (inSettings.mSampleCount < 1 || inSettings.mSampleCount > cMaxSamples)
        return MakeError(EError::InvalidArgument,
                         "RenderSettings.mSampleCount = " + std::to_string(inSettings.mSampleCount) +
                             " must be in 1..16");
    return Status::Ok();
}

/// Compiles one shader stage; the error carries the driver's log.
Result<GLuint> CompileShader(const RenderGlFunctions& inGl, GLenum inStage, const char* inSource)
{
    const GLuint shader = inGl.mCreateShader(inStage);
    inGl.mShaderSource(shader, 1, &inSource, nullptr);
    inGl.mCompileShader(shader);
    GLint compiled = GL_FALSE;
    inGl.mGetShaderiv(shader, GL_COMPILE_STATUS, &compiled);
    if (compiled == GL_TRUE)
        return shader;
    std::array<char, 2048> log{};
    inGl.mGetShaderInfoLog(shader, static_cast<GLsizei>(log.size()), nullptr, log.data());
    inGl.mDeleteShader(shader);
    return MakeError(EError::IoError, std::string("MeshRenderer: ") +
                                          (inStage == GL_VERTEX_SHADER ? "vertex" : "fragment") +
                                          " shader did not compile: " + log.data());
}

} // namespace

MeshRenderer::MeshRenderer(gpu::EglContext& ioContext, int inWidth, int inHeight)
    : mContext(ioContext), mWidth(inWidth), mHeight(inHeight)
{
}

MeshRenderer::~MeshRenderer()
{
    // GL objects belong to the context: make it current here to delete them.
    if (mGl == nullptr || !mContext.MakeCurrent())
        return;
    DeleteFramebuffers();
    mGl->mDeleteBuffers(static_cast<GLsizei>(mBuffers.size()), mBuffers.data());
    mGl->mDeleteVertexArrays(1, &mVertexArray);
    mGl->mDeleteProgram(mProgram);
}

Result<std::unique_ptr<MeshRenderer>> MeshRenderer::Create(gpu::EglContext& ioContext, int inWidth,
                                                           int inHeight, const RenderSettings& inSettings)
{
    // Arguments first, then the context.
    if (inWidth < 1 || inHeight < 1 || inWidth > cMaxSize || inHeight > cMaxSize)
        return MakeError(EError::InvalidArgument, "MeshRenderer::Create: size " + std::to_string(inWidth) +
                                                      " x " + std::to_string(inHeight) + " must be in 1.." +
                                                      std::to_string(cMaxSize) + " pixels");
    if (const Status valid = ValidateSettings(inSettings); !valid)
        return valid.GetError();
    if (const Status current = ioContext.MakeCurrent(); !current)
        return current.GetError();

    // Entry points; kept only when complete so the destructor never calls a null pointer.
    auto gl = std::make_unique<RenderGlFunctions>();
    if (const std::string missing = gl->Load(ioContext); !missing.empty())
        return MakeError(EError::IoError, "MeshRenderer::Create: the OpenGL driver lacks " + missing);
    GLint max_size = 0;
    gl->mGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size);
    if (inWidth > max_size || inHeight > max_size)
        return MakeError(EError::InvalidArgument, "MeshRenderer::Create: size " + std::to_string(inWidth) +
                                                      " x " + std::to_string(inHeight) +
                                                      " exceeds the driver's " + std::to_string(max_size) +
                                                      " pixels");

    std::unique_ptr<MeshRenderer> renderer(new MeshRenderer(ioContext, inWidth, inHeight));
    renderer->mGl = std::move(gl);
    renderer->mSettings = inSettings;
    if (const Status program = renderer->CreateProgram(); !program)
        return program.GetError();
    if (const Status framebuffers = renderer->CreateFramebuffers(inSettings.mSampleCount); !framebuffers)
        return framebuffers.GetError();
    return renderer;
}

Status MeshRenderer::CreateProgram()
{
    const RenderGlFunctions& gl = *mGl;

    // Compile and link.
    Result<GLuint> vertex = CompileShader(gl, GL_VERTEX_SHADER, cMeshVertexShader);
    if (!vertex)
        return vertex.GetError();
    Result<GLuint> fragment = CompileShader(gl, GL_FRAGMENT_SHADER, cMeshFragmentShader);
    if (!fragment)
    {
        gl.mDeleteShader(vertex.Get());
        return fragment.GetError();
    }
    mProgram = gl.mCreateProgram();
    gl.mAttachShader(mProgram, vertex.Get());
    gl.mAttachShader(mProgram, fragment.Get());
    gl.mLinkProgram(mProgram);
    gl.mDeleteShader(vertex.Get());
    gl.mDeleteShader(fragment.Get());
    GLint linked = GL_FALSE;
    gl.mGetProgramiv(mProgram, GL_LINK_STATUS, &linked);
    if (linked != GL_TRUE)
    {
        std::array<char, 2048> log{};
        gl.mGetProgramInfoLog(mProgram, static_cast<GLsizei>(log.size()), nullptr, log.data());
        return MakeError(EError::IoError,
                         std::string("MeshRenderer: shader program did not link: ") + log.data());
    }

    // Uniform locations.
    mUniforms.mViewProjection = gl.mGetUniformLocation(mProgram, "uViewProjection");
    mUniforms.mBaseColor = gl.mGetUniformLocation(mProgram, "uBaseColor");
    mUniforms.mKeyDirection = gl.mGetUniformLocation(mProgram, "uKeyDirection");
    mUniforms.mAmbient = gl.mGetUniformLocation(mProgram, "uAmbient");
    mUniforms.mKeyIntensity = gl.mGetUniformLocation(mProgram, "uKeyIntensity");
    mUniforms.mHeadlightIntensity = gl.mGetUniformLocation(mProgram, "uHeadlightIntensity");
    mUniforms.mUseScalars = gl.mGetUniformLocation(mProgram, "uUseScalars");
    mUniforms.mColorCount = gl.mGetUniformLocation(mProgram, "uColorCount");
    mUniforms.mColors = gl.mGetUniformLocation(mProgram, "uColors");

    // Vertex array: the attribute layout is recorded once; Render only refills the buffers.
    gl.mGenVertexArrays(1, &mVertexArray);
    gl.mGenBuffers(static_cast<GLsizei>(mBuffers.size()), mBuffers.data());
    gl.mBindVertexArray(mVertexArray);
    gl.mBindBuffer(GL_ARRAY_BUFFER, mBuffers[0]);
    gl.mVertexAttribPointer(cPositionLocation, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    gl.mEnableVertexAttribArray(cPositionLocation);
    gl.mBindBuffer(GL_ARRAY_BUFFER, mBuffers[1]);
    gl.mVertexAttribPointer(cNormalLocation, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    gl.mEnableVertexAttribArray(cNormalLocation);
    gl.mBindBuffer(GL_ARRAY_BUFFER, mBuffers[2]);
    gl.mVertexAttribPointer(cScalarLocation, 1, GL_FLOAT, GL_FALSE, 0, nullptr);
    gl.mBindBuffer(GL_ELEMENT_ARRAY_BUFFER, mBuffers[3]);
    gl.mBindVertexArray(0);
    gl.mBindBuffer(GL_ARRAY_BUFFER, 0);

    const GLenum error = gl.mGetError();
    if (error != GL_NO_ERROR)
        return MakeError(EError::IoError,
                         "MeshRenderer: setting up the program failed: " + GlErrorString(error));
    return Status::Ok();
}

Status MeshRenderer::CreateFramebuffers(int inSampleCount)
{
    const RenderGlFunctions& gl = *mGl;
    DeleteFramebuffers();

    // Samples within the driver's limit; 1 means a plain (non-multisampled) framebuffer.
    GLint max_samples = 1;
    gl.mGetIntegerv(GL_MAX_SAMPLES, &max_samples);
    const int samples = std::clamp(inSampleCount, 1, std::max(max_samples, 1));
    const GLsizei storage_samples = samples > 1 ? samples : 0;

    // Draw framebuffer: colour RGBA8 + depth 24.
    gl.mGenFramebuffers(1, &mDrawFramebuffer);
    gl.mGenRenderbuffers(static_cast<GLsizei>(mDrawRenderbuffers.size()), mDrawRenderbuffers.data());
    gl.mBindRenderbuffer(GL_RENDERBUFFER, mDrawRenderbuffers[0]);
    gl.mRenderbufferStorageMultisample(GL_RENDERBUFFER, storage_samples, GL_RGBA8, mWidth, mHeight);
    gl.mBindRenderbuffer(GL_RENDERBUFFER, mDrawRenderbuffers[1]);
    gl.mRenderbufferStorageMultisample(GL_RENDERBUFFER, storage_samples, GL_DEPTH_COMPONENT24, mWidth,
                                       mHeight);
    gl.mBindFramebuffer(GL_FRAMEBUFFER, mDrawFramebuffer);
    gl.mFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, mDrawRenderbuffers[0]);
    gl.mFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, mDrawRenderbuffers[1]);
    const GLenum draw_status = gl.mCheckFramebufferStatus(GL_FRAMEBUFFER);

    // Resolve framebuffer: single-sample colour that glReadPixels reads.
    gl.mGenFramebuffers(1, &mResolveFramebuffer);
    gl.mGenRenderbuffers(1, &mResolveRenderbuffer);
    gl.mBindRenderbuffer(GL_RENDERBUFFER, mResolveRenderbuffer);
    gl.mRenderbufferStorageMultisample(GL_RENDERBUFFER, 0, GL_RGBA8, mWidth, mHeight);
    gl.mBindFramebuffer(GL_FRAMEBUFFER, mResolveFramebuffer);
    gl.mFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, mResolveRenderbuffer);
    const GLenum resolve_status = gl.mCheckFramebufferStatus(GL_FRAMEBUFFER);
    gl.mBindFramebuffer(GL_FRAMEBUFFER, 0);
    gl.mBindRenderbuffer(GL_RENDERBUFFER, 0);

    const GLenum error = gl.mGetError();
    if (draw_status != GL_FRAMEBUFFER_COMPLETE || resolve_status != GL_FRAMEBUFFER_COMPLETE ||
        error != GL_NO_ERROR)
    {
        std::array<char, 96> detail{};
        std::snprintf(detail.data(), detail.size(), "draw status 0x%04X, resolve status 0x%04X, ",
                      draw_status, resolve_status);
        DeleteFramebuffers();
        return MakeError(EError::IoError, "MeshRenderer: framebuffer " + std::to_string(mWidth) + " x " +
                                              std::to_string(mHeight) + " with " + std::to_string(samples) +
                                              " samples is incomplete (" + detail.data() +
                                              GlErrorString(error) + ")");
    }
    mSampleCount = samples;
    return Status::Ok();
}

void MeshRenderer::DeleteFramebuffers()
{
    const RenderGlFunctions& gl = *mGl;
    gl.mDeleteFramebuffers(1, &mDrawFramebuffer);
    gl.mDeleteFramebuffers(1, &mResolveFramebuffer);
    gl.mDeleteRenderbuffers(static_cast<GLsizei>(mDrawRenderbuffers.size()), mDrawRenderbuffers.data());
    gl.mDeleteRenderbuffers(1, &mResolveRenderbuffer);
    mDrawFramebuffer = 0;
    mResolveFramebuffer = 0;
    mDrawRenderbuffers = {};
    mResolveRenderbuffer = 0;
}

Status MeshRenderer::SetSettings(const RenderSettings& inSettings)
{
    if (const Status valid = ValidateSettings(inSettings); !valid)
        return valid;
    if (inSettings.mSampleCount != mSettings.mSampleCount)
    {
        if (const Status current = mContext.MakeCurrent(); !current)
            return current;
        if (const Status framebuffers = CreateFramebuffers(inSettings.mSampleCount); !framebuffers)
        {
            // Restore the previous framebuffer so the renderer stays usable.
            (void)CreateFramebuffers(mSettings.mSampleCount);
            return framebuffers;
        }
    }
    mSettings = inSettings;
    return Status::Ok();
}

Status MeshRenderer::Render(std::span<const Vec3> inPositions, std::span<const Vec3> inNormals,
                            std::span<const std::array<std::uint32_t, 3>> inTriangles,
                            std::span<const double> inScalars, const Camera& inCamera,
                            std::vector<std::uint8_t>& outRgba)
{
    // Validate all input before touching GL.
    const std::size_t vertex_count = inPositions.size();
    if (inNormals.size() != vertex_count)
        return MakeError(EError::InvalidArgument,
                         "MeshRenderer::Render: " + std::to_string(inNormals.size()) + " normals for " +
                             std::to_string(vertex_count) + " positions");
    if (!inScalars.empty() && inScalars.size() != vertex_count)
        return MakeError(EError::InvalidArgument,
                         "MeshRenderer::Render: " + std::to_string(inScalars.size()) + " scalars for " +
                             std::to_string(vertex_count) + " positions (give one per vertex or none)");
    if (vertex_count > std::numeric_limits<std::uint32_t>::max() ||
        inTriangles.size() > static_cast<std::size_t>(std::numeric_limits<GLsizei>::max() / 3))
        return MakeError(EError::InvalidArgument, "MeshRenderer::Render: mesh too large for 32-bit indices");
    if (const Status camera = inCamera.Validate(); !camera)
        return camera;
    for (std::size_t i = 0; i < vertex_count; ++i)
        if (!IsFinite(inPositions[i]) || !IsFinite(inNormals[i]))
            return MakeError(EError::NonFinite, "MeshRenderer::Render: position or normal " +
                                                    std::to_string(i) + " is not finite");
    for (std::size_t i = 0; i < inScalars.size(); ++i)
        if (!IsFinite(inScalars[i]))
            return MakeError(EError::NonFinite,
                             "MeshRenderer::Render: scalar " + std::to_string(i) + " is not finite");
    for (std::size_t f = 0; f < inTriangles.size(); ++f)
        for (std::uint32_t index : inTriangles[f])
            if (index >= vertex_count)
                return MakeError(EError::OutOfRange, "MeshRenderer::Render: triangle " + std::to_string(f) +
                                                         " has vertex index " + std::to_string(index) +
                                                         " >= vertex count " + std::to_string(vertex_count));
    if (const Status current = mContext.MakeCurrent(); !current)
        return current;
    const RenderGlFunctions& gl = *mGl;
    while (gl.mGetError() != GL_NO_ERROR)
    {
        // Drop errors left by other users of the context, so any error below is ours.
    }

    // Positions relative to the eye in double, then float: precision stays where the camera looks.
    std::vector<float> positions(3 * vertex_count);
    std::vector<float> normals(3 * vertex_count);
    for (std::size_t i = 0; i < vertex_count; ++i)
    {
        const Vec3 relative = inPositions[i] - inCamera.mEye;
        for (int k = 0; k < 3; ++k)
        {
            positions[3 * i + static_cast<std::size_t>(k)] = static_cast<float>(relative[k]);
            normals[3 * i + static_cast<std::size_t>(k)] = static_cast<float>(inNormals[i][k]);
        }
    }

    // Scalars mapped to [0, 1] through the settings' range, or the data's range when that is empty.
    std::vector<float> scalars;
    if (!inScalars.empty())
    {
        double low = mSettings.mScalarMin;
        double high = mSettings.mScalarMax;
        if (!(high > low))
        {
            const auto [min_it, max_it] = std::minmax_element(inScalars.begin(), inScalars.end());
            low = *min_it;
            high = *max_it;
        }
        scalars.resize(vertex_count);
        for (std::size_t i = 0; i < vertex_count; ++i)
            scalars[i] = high > low
                             ? static_cast<float>(std::clamp((inScalars[i] - low) / (high - low), 0.0, 1.0))
                             : 0.0f;
    }

    // Upload into the vertex array's buffers.
    const auto bytes = [](std::size_t inCount, std::size_t inSize)
    { return static_cast<GLsizeiptr>(inCount * inSize); };
    gl.mBindVertexArray(mVertexArray);
    gl.mBindBuffer(GL_ARRAY_BUFFER, mBuffers[0]);
    gl.mBufferData(GL_ARRAY_BUFFER, bytes(positions.size(), sizeof(float)), positions.data(), GL_STREAM_DRAW);
    gl.mBindBuffer(GL_ARRAY_BUFFER, mBuffers[1]);
    gl.mBufferData(GL_ARRAY_BUFFER, bytes(normals.size(), sizeof(float)), normals.data(), GL_STREAM_DRAW);
    if (scalars.empty())
    {
        gl.mDisableVertexAttribArray(cScalarLocation);
        gl.mVertexAttrib1f(cScalarLocation, 0.0f);
    }
    else
    {
        gl.mBindBuffer(GL_ARRAY_BUFFER, mBuffers[2]);
        gl.mBufferData(GL_ARRAY_BUFFER, bytes(scalars.size(), sizeof(float)), scalars.data(), GL_STREAM_DRAW);
        gl.mEnableVertexAttribArray(cScalarLocation);
    }
    gl.mBufferData(GL_ELEMENT_ARRAY_BUFFER, bytes(inTriangles.size(), sizeof(std::array<std::uint32_t, 3>)),
                   inTriangles.data(), GL_STREAM_DRAW);

    // Uniforms: projection * view rotation (the eye is the origin of the uploaded positions).
    Eigen::Matrix4d view = Eigen::Matrix4d::Identity();
    view.topLeftCorner<3, 3>() = inCamera.GetViewRotation();
    const double aspect = static_cast<double>(mWidth) / static_cast<double>(mHeight);
    const Eigen::Matrix4f view_projection = (inCamera.GetProjectionMatrix(aspect) * view).cast<float>();
    const Eigen::Vector3f key_direction = mSettings.mKeyLightDirection.normalized().cast<float>();
    const std::span<const std::array<float, 3>> table = ColorMapTable(mSettings.mColorMap);
    gl.mUseProgram(mProgram);
    gl.mUniformMatrix4fv(mUniforms.mViewProjection, 1, GL_FALSE, view_projection.data());
    gl.mUniform3f(mUniforms.mBaseColor, mSettings.mBaseColor[0], mSettings.mBaseColor[1],
                  mSettings.mBaseColor[2]);
    gl.mUniform3f(mUniforms.mKeyDirection, key_direction.x(), key_direction.y(), key_direction.z());
    gl.mUniform1f(mUniforms.mAmbient, mSettings.mAmbient);
    gl.mUniform1f(mUniforms.mKeyIntensity, mSettings.mKeyIntensity);
    gl.mUniform1f(mUniforms.mHeadlightIntensity, mSettings.mHeadlightIntensity);
    gl.mUniform1i(mUniforms.mUseScalars, scalars.empty() ? 0 : 1);
    gl.mUniform1i(mUniforms.mColorCount, static_cast<GLint>(table.size()));
    gl.mUniform3fv(mUniforms.mColors, static_cast<GLsizei>(table.size()), table.front().data());

    // Draw over the flat background.
    gl.mBindFramebuffer(GL_FRAMEBUFFER, mDrawFramebuffer);
    gl.mViewport(0, 0, mWidth, mHeight);
    gl.mEnable(GL_DEPTH_TEST);
    gl.mDepthFunc(GL_LESS);
    gl.mDisable(GL_CULL_FACE);
    const std::array<float, 4>& background = mSettings.mBackgroundColor;
    gl.mClearColor(background[0], background[1], background[2], background[3]);
    gl.mClearDepth(1.0);
    gl.mClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (!inTriangles.empty())
        gl.mDrawElements(GL_TRIANGLES, static_cast<GLsizei>(3 * inTriangles.size()), GL_UNSIGNED_INT,
                         nullptr);
    gl.mBindVertexArray(0);

    // Resolve the samples and read back (GL's first row is the bottom of the image).
    gl.mBindFramebuffer(GL_READ_FRAMEBUFFER, mDrawFramebuffer);
    gl.mBindFramebuffer(GL_DRAW_FRAMEBUFFER, mResolveFramebuffer);
    gl.mBlitFramebuffer(0, 0, mWidth, mHeight, 0, 0, mWidth, mHeight, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    gl.mBindFramebuffer(GL_READ_FRAMEBUFFER, mResolveFramebuffer);
    gl.mReadBuffer(GL_COLOR_ATTACHMENT0);
    gl.mPixelStorei(GL_PACK_ALIGNMENT, 1);
    const std::size_t row_bytes = 4 * static_cast<std::size_t>(mWidth);
    outRgba.resize(row_bytes * static_cast<std::size_t>(mHeight));
    gl.mReadPixels(0, 0, mWidth, mHeight, GL_RGBA, GL_UNSIGNED_BYTE, outRgba.data());
    gl.mBindFramebuffer(GL_FRAMEBUFFER, 0);
    const GLenum error = gl.mGetError();
    if (error != GL_NO_ERROR)
        return MakeError(EError::IoError, "MeshRenderer::Render: OpenGL error " + GlErrorString(error));

    // Flip rows so the first row is the top of the image.
    for (std::size_t top = 0, bottom = static_cast<std::size_t>(mHeight) - 1; top < bottom; ++top, --bottom)
        std::swap_ranges(outRgba.begin() + static_cast<std::ptrdiff_t>(top * row_bytes),
                         outRgba.begin() + static_cast<std::ptrdiff_t>((top + 1) * row_bytes),
                         outRgba.begin() + static_cast<std::ptrdiff_t>(bottom * row_bytes));
    return Status::Ok();
}

} // namespace crumple::render
