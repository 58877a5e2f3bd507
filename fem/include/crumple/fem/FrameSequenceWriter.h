// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Result.h>
#include <crumple/fem/ESurfaceFormat.h>
#include <crumple/fem/TetMesh.h>

#include <filesystem>
#include <span>
#include <string>

namespace crumple::fem
{

/// Where and how a FrameSequenceWriter writes.
struct CRUMPLE_API FrameSequenceSettings
{
    std::filesystem::path mDirectory; ///< Folder of the frames; created (with its parents) if missing
    std::string mBaseName = "frame";  ///< File name prefix: not empty, no '/', not "." or ".."
    ESurfaceFormat mFormat = ESurfaceFormat::Ply; ///< File format of every frame
};

/// Writes the deformed boundary of a tetrahedral body once per frame, for offline rendering:
/// <mDirectory>/<mBaseName>_000000.<ext>, <mBaseName>_000001.<ext>, ... (six digits, zero-padded; wider after
/// frame 999999). Each file holds the TetBoundary of the elements given to that frame and only the nodes it
/// uses, in increasing node index, reindexed from 0: frames of an unbroken body share their topology, and a
/// fracture that remaps element corners shows its crack faces from the frame it happens in. Single-threaded:
/// one writer per sequence.
class CRUMPLE_API FrameSequenceWriter
{
  public:
    /// Checks the settings and creates the folder. Refused: an empty folder path or a bad base name
    /// (EError::InvalidArgument), a folder that cannot be created or is a file (EError::IoError).
    static Result<FrameSequenceWriter> Create(const FrameSequenceSettings& inSettings);

    /// Writes the next frame (see SaveSurface: through "<file>.partial" and a rename). Refused with nothing
    /// written and the frame number kept: no element (EError::InvalidArgument), an element index outside [0,
    /// #N) (EError::OutOfRange), a non-finite position of any node (EError::NonFinite), a write error
    /// (EError::IoError, e.g. the folder was removed or is read-only).
    /// @param[in] inTets       #T elements, 4 node indices each, positively oriented (as TetMesh / the solver
    /// hold them)
    /// @param[in] inPositions  #N current node positions (m)
    Status Write(std::span<const TetIndices> inTets, std::span<const Vec3> inPositions);

    /// Number of frames written so far: the number the next Write gets
    int GetFrameCount() const { return mFrameCount; }
    /// Path of frame inFrame (>= 0), whether written yet or not
    std::filesystem::path GetFramePath(int inFrame) const;
    /// The settings this writer was created with
    const FrameSequenceSettings& GetSettings() const { return mSettings; }

  private:
    explicit FrameSequenceWriter(FrameSequenceSettings inSettings) : mSettings(std::move(inSettings)) {}

    FrameSequenceSettings mSettings;
    int mFrameCount = 0;
};

} // namespace crumple::fem
