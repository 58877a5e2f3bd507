// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "ScratchDirectory.h"
#include "SurfaceReadBack.h"

#include <crumple/base/FileBytes.h>
#include <crumple/fem/SurfaceFile.h>

#include <catch2/catch.hpp>

#include <cstring>
#include <fstream>
#include <limits>

using namespace crumple;
using namespace crumple::fem;

namespace
{

// A tetrahedron's surface with awkward doubles: thirds, tiny, huge, subnormal and negative zero.
SurfaceMesh AwkwardSurface()
{
    SurfaceMesh mesh;
    mesh.mPositions = {Vec3(0.1, 1.0 / 3.0, -2.0 / 7.0), Vec3(1.0e-300, -1.0e300, 4.9406564584124654e-324),
                       Vec3(-0.0, 123456789.123456789, 1.0 - 1.0e-16), Vec3(-7.5, 0.0, 6.02214076e23)};
    mesh.mTriangles = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
    return mesh;
}

// Bit-for-bit equality of positions (so -0.0 and 0.0 differ).
bool SameBits(const std::vector<Vec3>& inA, const std::vector<Vec3>& inB)
{
    return inA.size() == inB.size() && std::memcmp(inA.data(), inB.data(), sizeof(Vec3) * inA.size()) == 0;
}

std::filesystem::path Fresh(const std::string& inName)
{
    const std::filesystem::path path = common::ScratchDirectory() / inName;
    std::filesystem::remove_all(path);
    return path;
}

} // namespace

TEST_CASE("SaveSurface OBJ and PLY read back to exactly the positions and triangles", "[fem]")
{
    const SurfaceMesh mesh = AwkwardSurface();
    const std::filesystem::path obj = Fresh("awkward.obj");
    const std::filesystem::path ply = Fresh("awkward.ply");
    REQUIRE(SaveSurface(obj, mesh.mPositions, mesh.mTriangles, ESurfaceFormat::Obj).IsValid());
    REQUIRE(SaveSurface(ply, mesh.mPositions, mesh.mTriangles, ESurfaceFormat::Ply).IsValid());

    Result<SurfaceMesh> from_obj = test::ReadBackObj(obj);
    REQUIRE(from_obj.IsValid());
    CHECK(SameBits(from_obj.Get().mPositions, mesh.mPositions));
    CHECK(from_obj.Get().mTriangles == mesh.mTriangles);

    Result<SurfaceMesh> from_ply = test::ReadBackPly(ply);
    INFO((from_ply.HasError() ? from_ply.GetError().mMessage : std::string()));
    REQUIRE(from_ply.IsValid());
    CHECK(SameBits(from_ply.Get().mPositions, mesh.mPositions));
    CHECK(from_ply.Get().mTriangles == mesh.mTriangles);

    // No partial file is left beside a written one; the PLY is header + 24 bytes a vertex + 13 a face.
    CHECK(!std::filesystem::exists(obj.string() + ".partial"));
    CHECK(!std::filesystem::exists(ply.string() + ".partial"));
    const std::vector<std::byte> bytes = ReadFileBytes(ply).Get();
    const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    CHECK(bytes.size() == text.find("end_header\n") + 11 + 24 * 4 + 13 * 4);
}

TEST_CASE("SaveSurface refuses bad input and writes nothing", "[fem]")
{
    const SurfaceMesh good = AwkwardSurface();
    for (const ESurfaceFormat format : {ESurfaceFormat::Obj, ESurfaceFormat::Ply})
    {
        INFO(ToString(format));
        const std::filesystem::path path = Fresh(std::string("refused.") + SurfaceFileExtension(format));

        SurfaceMesh nan = good;
        nan.mPositions[2].y() = std::numeric_limits<double>::quiet_NaN();
        Status status = SaveSurface(path, nan.mPositions, nan.mTriangles, format);
        REQUIRE(status.HasError());
        CHECK(status.GetError().mCode == EError::NonFinite);

        SurfaceMesh infinite = good;
        infinite.mPositions[0].x() = -std::numeric_limits<double>::infinity();
        CHECK(SaveSurface(path, infinite.mPositions, infinite.mTriangles, format).GetError().mCode ==
              EError::NonFinite);

        for (const int bad : {4, -1})
        {
            SurfaceMesh out_of_range = good;
            out_of_range.mTriangles[3][1] = bad;
            status = SaveSurface(path, out_of_range.mPositions, out_of_range.mTriangles, format);
            REQUIRE(status.HasError());
            CHECK(status.GetError().mCode == EError::OutOfRange);
            CHECK(status.GetError().mMessage.find("triangle 3") != std::string::npos);
        }
        status = SaveSurface(path, good.mPositions, std::span<const TriangleIndices>(), format);
        CHECK(status.GetError().mCode == EError::InvalidArgument);

        CHECK(!std::filesystem::exists(path));
        CHECK(!std::filesystem::exists(path.string() + ".partial"));

        // A refused write leaves an existing file as it was.
        REQUIRE(SaveSurface(path, good.mPositions, good.mTriangles, format).IsValid());
        const std::vector<std::byte> before = ReadFileBytes(path).Get();
        CHECK(SaveSurface(path, nan.mPositions, nan.mTriangles, format).HasError());
        CHECK(ReadFileBytes(path).Get() == before);
    }
}

TEST_CASE("SaveSurface reports an unwritable folder", "[fem]")
{
    // A regular file where the folder should be: refused even for root, with the system's reason.
    const SurfaceMesh good = AwkwardSurface();
    const std::filesystem::path blocker = Fresh("not-a-folder");
    std::ofstream(blocker) << "x";
    const std::filesystem::path path = blocker / "surface.obj";
    const Status status = SaveSurfaceObj(path, good.mPositions, good.mTriangles);
    REQUIRE(status.HasError());
    CHECK(status.GetError().mCode == EError::IoError);
    CHECK(status.GetError().mMessage.find("surface.obj.partial") != std::string::npos);
    CHECK(status.GetError().mMessage.find("Not a directory") != std::string::npos);
    CHECK(SaveSurfacePly(Fresh("missing-folder") / "x.ply", good.mPositions, good.mTriangles)
              .GetError()
              .mCode == EError::IoError);
}
