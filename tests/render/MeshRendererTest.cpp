// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "SkipTest.h"

#include <crumple/gpu/EglContext.h>
#include <crumple/render/Camera.h>
#include <crumple/render/MeshRenderer.h>
#include <crumple/render/RenderSettings.h>
#include <crumple/render/WritePng.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <iterator>
#include <limits>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <vector>

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>

using namespace crumple;
using namespace crumple::render;

namespace
{

constexpr int cWidth = 160;  ///< Test image width (pixels)
constexpr int cHeight = 120; ///< Test image height (pixels)

/// A mesh with per-vertex normals, as MeshRenderer takes it.
struct TestMesh
{
    std::vector<Vec3> mPositions;
    std::vector<Vec3> mNormals;
    std::vector<std::array<std::uint32_t, 3>> mTriangles;
};

/// The cube [-0.5, 0.5]^3 (m) with flat faces: 4 vertices per face carrying the face normal,
/// counter-clockwise seen from outside.
TestMesh MakeUnitCube()
{
    TestMesh mesh;
    for (int axis = 0; axis < 3; ++axis)
        for (double sign : {1.0, -1.0})
        {
            const Vec3 normal = sign * Vec3::Unit(axis);
            const Vec3 u = Vec3::Unit((axis + 1) % 3);
            const Vec3 v = Vec3::Unit((axis + 2) % 3);
            const auto first = static_cast<std::uint32_t>(mesh.mPositions.size());
            std::array<Vec3, 4> corners{-u - v, u - v, u + v, -u + v};
            if (sign < 0.0)
                std::swap(corners[1], corners[3]);
            for (const Vec3& corner : corners)
            {
                mesh.mPositions.push_back(0.5 * (normal + corner));
                mesh.mNormals.push_back(normal);
            }
            mesh.mTriangles.push_back({first, first + 1, first + 2});
            mesh.mTriangles.push_back({first, first + 2, first + 3});
        }
    return mesh;
}

/// A context for a test. Without one (no usable EGL here) the test process ends as skipped (SkipTest: CTest
/// shows it skipped, not passed).
std::unique_ptr<gpu::EglContext> TryCreateContext(int inMajor = 3, int inMinor = 3)
{
    gpu::EglContextSettings settings;
    settings.mMajorVersion = inMajor;
    settings.mMinorVersion = inMinor;
    Result<std::unique_ptr<gpu::EglContext>> context = gpu::EglContext::Create(settings);
    if (!context)
    {
        common::SkipTest("no usable EGL context: " + context.GetError().mMessage);
    }
    return std::move(context).Get();
}

/// Sets an environment variable for one scope and restores it afterwards.
class ScopedEnvironment
{
public:
    ScopedEnvironment(const char* inName, const char* inValue) : mName(inName)
    {
        if (const char* old = std::getenv(inName))
            mOld = old;
        setenv(inName, inValue, 1);
    }
    ~ScopedEnvironment()
    {
        if (mOld)
            setenv(mName.c_str(), mOld->c_str(), 1);
        else
            unsetenv(mName.c_str());
    }
    ScopedEnvironment(const ScopedEnvironment&) = delete;
    ScopedEnvironment& operator=(const ScopedEnvironment&) = delete;

private:
    std::string mName;
    std::optional<std::string> mOld;
};

/// RGBA of pixel (x, y), y down from the top row.
std::array<int, 4> PixelAt(const std::vector<std::uint8_t>& inRgba, int inX, int inY)
{
    const std::size_t offset = 4 * (static_cast<std::size_t>(inY) * cWidth + static_cast<std::size_t>(inX));
    return {inRgba[offset], inRgba[offset + 1], inRgba[offset + 2], inRgba[offset + 3]};
}

/// Rec. 709 luma of a pixel (0..255).
double Luma(const std::array<int, 4>& inPixel)
{
    return 0.2126 * inPixel[0] + 0.7152 * inPixel[1] + 0.0722 * inPixel[2];
}

/// The pixel (column, row from the top) a world point lands on.
std::array<int, 2> ProjectToPixel(const Camera& inCamera, const Vec3& inPoint)
{
    const Eigen::Vector4d clip = inCamera.GetProjectionMatrix(double(cWidth) / cHeight) *
                                 inCamera.GetViewMatrix() *
                                 Eigen::Vector4d(inPoint.x(), inPoint.y(), inPoint.z(), 1.0);
    const double x = 0.5 * (clip.x() / clip.w() + 1.0) * cWidth;
    const double y = 0.5 * (1.0 - clip.y() / clip.w()) * cHeight;
    return {static_cast<int>(x), static_cast<int>(y)};
}

/// A renderer on inContext with inSettings; REQUIREs success.
std::unique_ptr<MeshRenderer> MakeRenderer(gpu::EglContext& ioContext, const RenderSettings& inSettings = {})
{
    Result<std::unique_ptr<MeshRenderer>> renderer =
        MeshRenderer::Create(ioContext, cWidth, cHeight, inSettings);
    INFO((renderer ? std::string() : renderer.GetError().mMessage));
    REQUIRE(renderer.IsValid());
    return std::move(renderer).Get();
}

/// A fresh, empty directory under the system's temporary directory.
std::filesystem::path MakeScratchDirectory()
{
    std::random_device random;
    const std::filesystem::path directory =
        std::filesystem::temp_directory_path() / ("crumple_render_test_" + std::to_string(random()));
    std::filesystem::create_directories(directory);
    return directory;
}

} // namespace

TEST_CASE("EglContext makes a headless core context of at least the requested version", "[render]")
{
    std::unique_ptr<gpu::EglContext> context = TryCreateContext(4, 3);
    CHECK_FALSE(context->GetRendererString().empty());
    const gpu::GlVersion version = context->GetVersion();
    CHECK(version.mMajor * 10 + version.mMinor >= 43);
    CHECK(context->GetPlatform() != gpu::EEglPlatform::Any);
    CHECK(context->MakeCurrent().IsValid());
    CHECK(context->GetProcAddress("glDispatchCompute") != nullptr);
}

TEST_CASE("EglContext works on either platform and with two contexts alive", "[render]")
{
    std::unique_ptr<gpu::EglContext> first = TryCreateContext();

    // Mesa's surfaceless platform on its own (the fallback when no EGL device works).
    gpu::EglContextSettings surfaceless;
    surfaceless.mMajorVersion = 3;
    surfaceless.mMinorVersion = 3;
    surfaceless.mPlatform = gpu::EEglPlatform::Surfaceless;
    Result<std::unique_ptr<gpu::EglContext>> second = gpu::EglContext::Create(surfaceless);
    if (second)
        CHECK(second.Get()->GetPlatform() == gpu::EEglPlatform::Surfaceless);
    else
        WARN("surfaceless platform unavailable: " << second.GetError().mMessage);

    // A second context on the first one's display; destroying it leaves the first usable.
    std::unique_ptr<gpu::EglContext> third = TryCreateContext();
    REQUIRE(third != nullptr);
    third.reset();
    REQUIRE(first->MakeCurrent().IsValid());
    std::unique_ptr<MeshRenderer> renderer = MakeRenderer(*first);
    const TestMesh cube = MakeUnitCube();
    std::vector<std::uint8_t> rgba;
    CHECK(renderer->Render(cube.mPositions, cube.mNormals, cube.mTriangles, {}, Camera(), rgba).IsValid());
}

TEST_CASE("EglContext refuses versions without a core profile", "[render]")
{
    for (const auto& [major, minor] : {std::pair{2, 1}, std::pair{3, 1}, std::pair{4, 7}, std::pair{5, 0}})
    {
        gpu::EglContextSettings settings;
        settings.mMajorVersion = major;
        settings.mMinorVersion = minor;
        Result<std::unique_ptr<gpu::EglContext>> context = gpu::EglContext::Create(settings);
        REQUIRE(context.HasError());
        CHECK(context.GetError().mCode == EError::InvalidArgument);
    }
}

TEST_CASE("CRUMPLE_DISABLE_EGL=1 makes EglContext::Create fail cleanly", "[render]")
{
    ScopedEnvironment disable("CRUMPLE_DISABLE_EGL", "1");
    Result<std::unique_ptr<gpu::EglContext>> context = gpu::EglContext::Create();
    REQUIRE(context.HasError());
    CHECK(context.GetError().mCode == EError::IoError);
    CHECK_THAT(context.GetError().mMessage, Catch::Contains("CRUMPLE_DISABLE_EGL"));
}

TEST_CASE("MeshRenderer draws a cube over the background", "[render]")
{
    std::unique_ptr<gpu::EglContext> context = TryCreateContext();
    std::unique_ptr<MeshRenderer> renderer = MakeRenderer(*context);
    const TestMesh cube = MakeUnitCube();
    const Camera camera = Camera::LookAtBounds(Vec3::Constant(-0.5), Vec3::Constant(0.5), EView::Iso,
                                               Vec3::UnitZ(), Vec3::UnitX(), 30.0, double(cWidth) / cHeight);

    std::vector<std::uint8_t> rgba;
    const Status status = renderer->Render(cube.mPositions, cube.mNormals, cube.mTriangles, {}, camera, rgba);
    INFO((status ? std::string() : status.GetError().mMessage));
    REQUIRE(status.IsValid());
    REQUIRE(rgba.size() == std::size_t(4) * cWidth * cHeight);

    // Corners show the white background, the centre shows the shaded grey cube.
    const std::array<int, 4> background{255, 255, 255, 255};
    CHECK(PixelAt(rgba, 0, 0) == background);
    CHECK(PixelAt(rgba, cWidth - 1, cHeight - 1) == background);
    const std::array<int, 4> centre = PixelAt(rgba, cWidth / 2, cHeight / 2);
    CHECK(centre != background);
    CHECK(centre[3] == 255);
    CHECK(Luma(centre) > 20.0);
    CHECK(Luma(centre) < 250.0);
}

TEST_CASE("MeshRenderer lights the face towards the key light more than an oblique one", "[render]")
{
    std::unique_ptr<gpu::EglContext> context = TryCreateContext();
    RenderSettings settings;
    settings.mKeyLightDirection = Vec3::UnitZ();
    std::unique_ptr<MeshRenderer> renderer = MakeRenderer(*context, settings);
    const TestMesh cube = MakeUnitCube();
    const Camera camera = Camera::LookAtBounds(Vec3::Constant(-0.5), Vec3::Constant(0.5), EView::Iso,
                                               Vec3::UnitZ(), Vec3::UnitX(), 30.0, double(cWidth) / cHeight);
    std::vector<std::uint8_t> rgba;
    REQUIRE(renderer->Render(cube.mPositions, cube.mNormals, cube.mTriangles, {}, camera, rgba).IsValid());

    // The iso view sees +z, +x and -y at the same angle, so only the key light (straight down) differs.
    const std::array<int, 2> top = ProjectToPixel(camera, Vec3(0.0, 0.0, 0.5));
    const std::array<int, 2> front = ProjectToPixel(camera, Vec3(0.5, 0.0, 0.0));
    const std::array<int, 2> side = ProjectToPixel(camera, Vec3(0.0, -0.5, 0.0));
    const double top_luma = Luma(PixelAt(rgba, top[0], top[1]));
    const double front_luma = Luma(PixelAt(rgba, front[0], front[1]));
    const double side_luma = Luma(PixelAt(rgba, side[0], side[1]));
    CHECK(top_luma > front_luma + 40.0);
    CHECK(top_luma > side_luma + 40.0);
    CHECK(front_luma == Approx(side_luma).margin(3.0));
}

TEST_CASE("MeshRenderer colours scalars and keeps the picture upright and unmirrored", "[render]")
{
    std::unique_ptr<gpu::EglContext> context = TryCreateContext();
    RenderSettings settings;
    settings.mScalarMin = -0.5;
    settings.mScalarMax = 0.5;
    std::unique_ptr<MeshRenderer> renderer = MakeRenderer(*context, settings);
    const TestMesh cube = MakeUnitCube();
    // Front view: the eye on +x, z up, so +y (the vehicle's left) is on the image's right.
    const Camera camera = Camera::LookAtBounds(Vec3::Constant(-0.5), Vec3::Constant(0.5), EView::Front,
                                               Vec3::UnitZ(), Vec3::UnitX(), 30.0, double(cWidth) / cHeight);
    const std::array<int, 2> high = ProjectToPixel(camera, Vec3(0.5, 0.0, 0.4));
    const std::array<int, 2> low = ProjectToPixel(camera, Vec3(0.5, 0.0, -0.4));
    const std::array<int, 2> left = ProjectToPixel(camera, Vec3(0.5, -0.4, 0.0));
    const std::array<int, 2> right = ProjectToPixel(camera, Vec3(0.5, 0.4, 0.0));
    REQUIRE(high[1] < low[1]);
    REQUIRE(left[0] < right[0]);

    // Without scalars the cube is grey.
    std::vector<std::uint8_t> plain;
    REQUIRE(renderer->Render(cube.mPositions, cube.mNormals, cube.mTriangles, {}, camera, plain).IsValid());
    const std::array<int, 4> grey = PixelAt(plain, high[0], high[1]);
    CHECK(std::abs(grey[0] - grey[2]) < 20);

    // Height as the scalar: viridis is yellow-green (G > B) at the top, purple (B > G) at the bottom.
    std::vector<double> height;
    std::vector<double> lateral;
    for (const Vec3& position : cube.mPositions)
    {
        height.push_back(position.z());
        lateral.push_back(position.y());
    }
    std::vector<std::uint8_t> by_height;
    REQUIRE(renderer->Render(cube.mPositions, cube.mNormals, cube.mTriangles, height, camera, by_height)
                .IsValid());
    const std::array<int, 4> top_pixel = PixelAt(by_height, high[0], high[1]);
    const std::array<int, 4> bottom_pixel = PixelAt(by_height, low[0], low[1]);
    CHECK(top_pixel != grey);
    CHECK(top_pixel[1] > top_pixel[2] + 40);
    CHECK(bottom_pixel[2] > bottom_pixel[1] + 20);

    // Lateral position as the scalar: +y, high end, on the right.
    std::vector<std::uint8_t> by_side;
    REQUIRE(renderer->Render(cube.mPositions, cube.mNormals, cube.mTriangles, lateral, camera, by_side)
                .IsValid());
    const std::array<int, 4> right_pixel = PixelAt(by_side, right[0], right[1]);
    const std::array<int, 4> left_pixel = PixelAt(by_side, left[0], left[1]);
    CHECK(right_pixel[1] > right_pixel[2] + 40);
    CHECK(left_pixel[2] > left_pixel[1] + 20);

    // The diverging map makes the high end red.
    settings.mColorMap = EColorMap::CoolWarm;
    REQUIRE(renderer->SetSettings(settings).IsValid());
    std::vector<std::uint8_t> cool_warm;
    REQUIRE(renderer->Render(cube.mPositions, cube.mNormals, cube.mTriangles, height, camera, cool_warm)
                .IsValid());
    const std::array<int, 4> warm = PixelAt(cool_warm, high[0], high[1]);
    const std::array<int, 4> cool = PixelAt(cool_warm, low[0], low[1]);
    CHECK(warm[0] > warm[2] + 40);
    CHECK(cool[2] > cool[0] + 40);
}

TEST_CASE("MeshRenderer refuses bad input", "[render]")
{
    std::unique_ptr<gpu::EglContext> context = TryCreateContext();
    CHECK(MeshRenderer::Create(*context, 0, cHeight).GetError().mCode == EError::InvalidArgument);
    RenderSettings bad_settings;
    bad_settings.mAmbient = -1.0f;
    CHECK(MeshRenderer::Create(*context, cWidth, cHeight, bad_settings).GetError().mCode ==
          EError::InvalidArgument);

    std::unique_ptr<MeshRenderer> renderer = MakeRenderer(*context);
    TestMesh cube = MakeUnitCube();
    const Camera camera;
    std::vector<std::uint8_t> rgba;
    const std::vector<Vec3> too_few_normals(cube.mNormals.begin(), cube.mNormals.end() - 1);
    CHECK(renderer->Render(cube.mPositions, too_few_normals, cube.mTriangles, {}, camera, rgba)
              .GetError()
              .mCode == EError::InvalidArgument);
    const std::vector<double> too_few_scalars(3, 0.0);
    CHECK(renderer->Render(cube.mPositions, cube.mNormals, cube.mTriangles, too_few_scalars, camera, rgba)
              .GetError()
              .mCode == EError::InvalidArgument);
    Camera inside_out = camera;
    inside_out.mTarget = inside_out.mEye;
    CHECK(renderer->Render(cube.mPositions, cube.mNormals, cube.mTriangles, {}, inside_out, rgba).HasError());
    TestMesh bad_index = cube;
    bad_index.mTriangles[3][1] = 24;
    CHECK(renderer->Render(bad_index.mPositions, bad_index.mNormals, bad_index.mTriangles, {}, camera, rgba)
              .GetError()
              .mCode == EError::OutOfRange);
    TestMesh not_finite = cube;
    not_finite.mPositions[5].x() = std::numeric_limits<double>::quiet_NaN();
    CHECK(
        renderer->Render(not_finite.mPositions, not_finite.mNormals, not_finite.mTriangles, {}, camera, rgba)
            .GetError()
            .mCode == EError::NonFinite);
    CHECK(rgba.empty());

    // Still usable after the refusals.
    CHECK(renderer->Render(cube.mPositions, cube.mNormals, cube.mTriangles, {}, camera, rgba).IsValid());
}

TEST_CASE("WritePng writes a file that reads back with the same size and pixels", "[render]")
{
    const std::filesystem::path directory = MakeScratchDirectory();
    const std::filesystem::path path = directory / "gradient.png";

    // A gradient with transparency; needs no EGL.
    std::vector<std::uint8_t> rgba(std::size_t(4) * cWidth * cHeight);
    for (int y = 0; y < cHeight; ++y)
        for (int x = 0; x < cWidth; ++x)
        {
            const std::size_t offset =
                4 * (static_cast<std::size_t>(y) * cWidth + static_cast<std::size_t>(x));
            rgba[offset] = static_cast<std::uint8_t>(x);
            rgba[offset + 1] = static_cast<std::uint8_t>(y);
            rgba[offset + 2] = 200;
            rgba[offset + 3] = static_cast<std::uint8_t>(255 - x);
        }
    const Status written = WritePng(path, cWidth, cHeight, rgba);
    INFO((written ? std::string() : written.GetError().mMessage));
    REQUIRE(written.IsValid());

    int width = 0;
    int height = 0;
    int channels = 0;
    stbi_uc* pixels = stbi_load(path.string().c_str(), &width, &height, &channels, 4);
    REQUIRE(pixels != nullptr);
    CHECK(width == cWidth);
    CHECK(height == cHeight);
    CHECK(channels == 4);
    CHECK(std::equal(rgba.begin(), rgba.end(), pixels));
    stbi_image_free(pixels);

    // Only the picture is left: no temporary file.
    CHECK(std::distance(std::filesystem::directory_iterator(directory),
                        std::filesystem::directory_iterator()) == 1);

    // Refusals leave no file behind.
    CHECK(WritePng(directory / "short.png", cWidth, cHeight, std::span(rgba).first(16)).GetError().mCode ==
          EError::InvalidArgument);
    CHECK(WritePng(directory / "missing" / "x.png", cWidth, cHeight, rgba).GetError().mCode ==
          EError::IoError);
    CHECK(std::distance(std::filesystem::directory_iterator(directory),
                        std::filesystem::directory_iterator()) == 1);
    std::filesystem::remove_all(directory);
}

TEST_CASE("A rendered cube round-trips through WritePng", "[render]")
{
    std::unique_ptr<gpu::EglContext> context = TryCreateContext();
    std::unique_ptr<MeshRenderer> renderer = MakeRenderer(*context);
    const TestMesh cube = MakeUnitCube();
    const Camera camera = Camera::LookAtBounds(Vec3::Constant(-0.5), Vec3::Constant(0.5), EView::Iso,
                                               Vec3::UnitZ(), Vec3::UnitX(), 30.0, double(cWidth) / cHeight);
    std::vector<std::uint8_t> rgba;
    REQUIRE(renderer->Render(cube.mPositions, cube.mNormals, cube.mTriangles, {}, camera, rgba).IsValid());

    const std::filesystem::path directory = MakeScratchDirectory();
    const std::filesystem::path path = directory / "cube.png";
    REQUIRE(WritePng(path, renderer->GetWidth(), renderer->GetHeight(), rgba).IsValid());
    int width = 0;
    int height = 0;
    int channels = 0;
    stbi_uc* pixels = stbi_load(path.string().c_str(), &width, &height, &channels, 4);
    REQUIRE(pixels != nullptr);
    CHECK(width == cWidth);
    CHECK(height == cHeight);
    CHECK(std::equal(rgba.begin(), rgba.end(), pixels));
    stbi_image_free(pixels);
    std::filesystem::remove_all(directory);
}
