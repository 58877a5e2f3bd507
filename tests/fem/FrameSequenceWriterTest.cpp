// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "ScratchDirectory.h"
#include "SurfaceReadBack.h"

#include <crumple/fem/FrameSequenceWriter.h>
#include <crumple/fem/TetBoundary.h>
#include <crumple/fem/TetGrid.h>

#include <catch2/catch.hpp>

#include <fstream>
#include <limits>

using namespace crumple;
using namespace crumple::fem;

namespace
{

std::filesystem::path Fresh(const std::string& inName)
{
    const std::filesystem::path path = common::ScratchDirectory() / inName;
    std::filesystem::remove_all(path);
    return path;
}

// Number of plain files in a folder.
int FileCount(const std::filesystem::path& inFolder)
{
    int count = 0;
    for (const auto& entry : std::filesystem::directory_iterator(inFolder))
        count += entry.is_regular_file() ? 1 : 0;
    return count;
}

// The positions of frame inFrame: the rest shape sheared and lifted, so each frame differs.
std::vector<Vec3> Deformed(const TetMesh& inMesh, int inFrame)
{
    std::vector<Vec3> positions = inMesh.GetRestPositions();
    for (Vec3& x : positions)
        x += Vec3(0.01 * inFrame * x.z(), 0.0, 0.1 * inFrame + 1.0 / 3.0);
    return positions;
}

} // namespace

TEST_CASE("FrameSequenceWriter writes numbered frames of the boundary nodes only", "[fem]")
{
    // A 2 x 2 x 2 box: 27 nodes, the centre one interior.
    TetGridSettings grid;
    grid.mCellCount = {2, 2, 2};
    const TetMesh mesh = TetGrid(grid).Get();
    const std::vector<TriangleIndices> boundary = TetBoundary(mesh.GetTets());
    const int centre = TetGridNode(grid.mCellCount, 1, 1, 1);

    for (const ESurfaceFormat format : {ESurfaceFormat::Obj, ESurfaceFormat::Ply})
    {
        INFO(ToString(format));
        FrameSequenceSettings settings;
        settings.mDirectory = Fresh(std::string("frames-") + ToString(format)) / "nested";
        settings.mBaseName = "box";
        settings.mFormat = format;
        Result<FrameSequenceWriter> created = FrameSequenceWriter::Create(settings);
        REQUIRE(created.IsValid());
        FrameSequenceWriter& writer = created.Get();

        for (int frame = 0; frame < 3; ++frame)
        {
            const std::vector<Vec3> positions = Deformed(mesh, frame);
            REQUIRE(writer.Write(mesh.GetTets(), positions).IsValid());
            CHECK(writer.GetFrameCount() == frame + 1);
            const std::filesystem::path path = writer.GetFramePath(frame);
            CHECK(path.filename().string() ==
                  "box_00000" + std::to_string(frame) + "." + SurfaceFileExtension(format));

            // Only the 26 boundary nodes, in node order, and the boundary triangles renumbered to them.
            Result<SurfaceMesh> read =
                format == ESurfaceFormat::Obj ? test::ReadBackObj(path) : test::ReadBackPly(path);
            REQUIRE(read.IsValid());
            const SurfaceMesh& surface = read.Get();
            REQUIRE(surface.mPositions.size() == 26);
            std::vector<int> kept;
            for (int node = 0; node < mesh.GetNodeCount(); ++node)
                if (node != centre)
                    kept.push_back(node);
            for (std::size_t vertex = 0; vertex < kept.size(); ++vertex)
                CHECK(surface.mPositions[vertex] == positions[kept[vertex]]);
            REQUIRE(surface.mTriangles.size() == boundary.size());
            for (std::size_t triangle = 0; triangle < boundary.size(); ++triangle)
                for (int corner = 0; corner < 3; ++corner)
                    CHECK(kept[surface.mTriangles[triangle][corner]] == boundary[triangle][corner]);
        }
        CHECK(FileCount(settings.mDirectory) == 3);
    }
}

TEST_CASE("FrameSequenceWriter refuses bad frames without writing or counting them", "[fem]")
{
    const TetMesh mesh = TetGrid({}).Get();
    FrameSequenceSettings settings;
    settings.mDirectory = Fresh("frames-refused");
    FrameSequenceWriter writer = FrameSequenceWriter::Create(settings).Get();

    std::vector<Vec3> nan = mesh.GetRestPositions();
    nan[5].z() = std::numeric_limits<double>::quiet_NaN();
    Status status = writer.Write(mesh.GetTets(), nan);
    REQUIRE(status.HasError());
    CHECK(status.GetError().mCode == EError::NonFinite);
    CHECK(status.GetError().mMessage.find("node 5") != std::string::npos);

    std::vector<TetIndices> bad_index = mesh.GetTets();
    bad_index[2][3] = mesh.GetNodeCount();
    status = writer.Write(bad_index, mesh.GetRestPositions());
    REQUIRE(status.HasError());
    CHECK(status.GetError().mCode == EError::OutOfRange);
    CHECK(status.GetError().mMessage.find("element 2") != std::string::npos);
    bad_index[2][3] = -1;
    CHECK(writer.Write(bad_index, mesh.GetRestPositions()).GetError().mCode == EError::OutOfRange);
    CHECK(writer.Write({}, mesh.GetRestPositions()).GetError().mCode == EError::InvalidArgument);

    CHECK(writer.GetFrameCount() == 0);
    CHECK(FileCount(settings.mDirectory) == 0);

    // The next good frame is still frame 0.
    REQUIRE(writer.Write(mesh.GetTets(), mesh.GetRestPositions()).IsValid());
    CHECK(std::filesystem::exists(settings.mDirectory / "frame_000000.ply"));
    CHECK(FileCount(settings.mDirectory) == 1);
}

TEST_CASE("FrameSequenceWriter refuses bad settings and reports a folder that went away", "[fem]")
{
    FrameSequenceSettings settings;
    settings.mDirectory = Fresh("frames-settings");
    for (const char* bad : {"", ".", "..", "sub/frame"})
    {
        settings.mBaseName = bad;
        CHECK(FrameSequenceWriter::Create(settings).GetError().mCode == EError::InvalidArgument);
    }
    settings.mBaseName = "frame";
    settings.mDirectory.clear();
    CHECK(FrameSequenceWriter::Create(settings).GetError().mCode == EError::InvalidArgument);

    // A file where the folder should be.
    const std::filesystem::path blocker = Fresh("frames-blocker");
    std::ofstream(blocker) << "x";
    settings.mDirectory = blocker;
    CHECK(FrameSequenceWriter::Create(settings).GetError().mCode == EError::IoError);
    settings.mDirectory = blocker / "below";
    CHECK(FrameSequenceWriter::Create(settings).GetError().mCode == EError::IoError);

    // The folder removed after Create: a clear write error, no frame counted.
    settings.mDirectory = Fresh("frames-vanished");
    FrameSequenceWriter writer = FrameSequenceWriter::Create(settings).Get();
    std::filesystem::remove_all(settings.mDirectory);
    const TetMesh mesh = TetGrid({}).Get();
    const Status status = writer.Write(mesh.GetTets(), mesh.GetRestPositions());
    REQUIRE(status.HasError());
    CHECK(status.GetError().mCode == EError::IoError);
    CHECK(status.GetError().mMessage.find("frame_000000.ply.partial") != std::string::npos);
    CHECK(writer.GetFrameCount() == 0);
}
