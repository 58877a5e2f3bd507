// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/FrameSequenceWriter.h>
#include <crumple/fem/SurfaceFile.h>
#include <crumple/fem/TetBoundary.h>

#include <cstdio>
#include <limits>

namespace crumple::fem
{

Result<FrameSequenceWriter> FrameSequenceWriter::Create(const FrameSequenceSettings& inSettings)
{
    // A plain file name prefix, so every frame lands in mDirectory.
    const std::string& base = inSettings.mBaseName;
    if (base.empty() || base == "." || base == ".." || base.find('/') != std::string::npos ||
        base.find('\0') != std::string::npos)
        return MakeError(EError::InvalidArgument, "FrameSequenceSettings.mBaseName = '" + base +
                                                      "' must be a non-empty file name without '/'");
    if (inSettings.mDirectory.empty())
        return MakeError(EError::InvalidArgument, "FrameSequenceSettings.mDirectory is empty");
    if (inSettings.mFormat != ESurfaceFormat::Obj && inSettings.mFormat != ESurfaceFormat::Ply)
        return MakeError(EError::InvalidArgument, "FrameSequenceSettings.mFormat is not an ESurfaceFormat");

    // The folder, created if missing.
    std::error_code error;
    std::filesystem::create_directories(inSettings.mDirectory, error);
    if (error)
        return MakeError(EError::IoError, "FrameSequenceWriter: cannot create folder " +
                                              inSettings.mDirectory.string() + ": " + error.message());
    if (!std::filesystem::is_directory(inSettings.mDirectory, error))
        return MakeError(EError::IoError,
                         "FrameSequenceWriter: " + inSettings.mDirectory.string() + " is not a folder");
    return FrameSequenceWriter(inSettings);
}

std::filesystem::path FrameSequenceWriter::GetFramePath(int inFrame) const
{
    char number[16];
    std::snprintf(number, sizeof(number), "_%06d.", inFrame);
    return mSettings.mDirectory / (mSettings.mBaseName + number + SurfaceFileExtension(mSettings.mFormat));
}

Status FrameSequenceWriter::Write(std::span<const TetIndices> inTets, std::span<const Vec3> inPositions)
{
    // Inputs first, so that a refused frame writes nothing.
    if (inTets.empty())
        return MakeError(EError::InvalidArgument, "FrameSequenceWriter::Write: no elements");
    if (inPositions.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
        return MakeError(EError::InvalidArgument, "FrameSequenceWriter::Write: more than 2^31 - 1 nodes");
    if (mFrameCount == std::numeric_limits<int>::max())
        return MakeError(EError::OutOfRange, "FrameSequenceWriter::Write: frame counter exhausted");
    const int node_count = static_cast<int>(inPositions.size());
    for (std::size_t tet = 0; tet < inTets.size(); ++tet)
        for (int node : inTets[tet])
            if (node < 0 || node >= node_count)
                return MakeError(EError::OutOfRange, "FrameSequenceWriter::Write: element " +
                                                         std::to_string(tet) + " names node " +
                                                         std::to_string(node) + ", outside [0, " +
                                                         std::to_string(node_count) + ")");
    for (int node = 0; node < node_count; ++node)
        if (!IsFinite(inPositions[node]))
            return MakeError(EError::NonFinite, "FrameSequenceWriter::Write: node " + std::to_string(node) +
                                                    " has a non-finite position");

    // The boundary, its nodes renumbered in increasing node order.
    std::vector<TriangleIndices> triangles = TetBoundary(inTets);
    std::vector<int> new_index(inPositions.size(), -1);
    for (const TriangleIndices& triangle : triangles)
        for (int node : triangle)
            new_index[node] = 0;
    std::vector<Vec3> positions;
    for (int node = 0; node < node_count; ++node)
        if (new_index[node] == 0)
        {
            new_index[node] = static_cast<int>(positions.size());
            positions.push_back(inPositions[node]);
        }
    for (TriangleIndices& triangle : triangles)
        for (int& node : triangle)
            node = new_index[node];

    // The frame; the counter moves only when it is on disk.
    if (Status saved = SaveSurface(GetFramePath(mFrameCount), positions, triangles, mSettings.mFormat);
        !saved)
        return saved;
    ++mFrameCount;
    return Status::Ok();
}

} // namespace crumple::fem
