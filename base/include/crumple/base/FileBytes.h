// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Result.h>

#include <cstddef>
#include <filesystem>
#include <span>
#include <string_view>
#include <vector>

namespace crumple
{

/// Reads a whole file (damage states, replays). A missing or unreadable file, or a path that is not a regular
/// file (a folder, a FIFO, a device), is EError::IoError.
CRUMPLE_API Result<std::vector<std::byte>> ReadFileBytes(const std::filesystem::path& inPath);

/// The name a file is written under until it is complete: "<inPath>.partial", beside inPath (same folder, so
/// the final rename stays within one file system).
CRUMPLE_API std::filesystem::path PartialFilePath(const std::filesystem::path& inPath);

/// Renames PartialFilePath(inPath) over inPath, replacing any old inPath in one step (atomic within one file
/// system): a reader sees either the old file or the complete new one. For writers that stream into the
/// partial file themselves (DamageRecorder); whole buffers go through WriteFileAtomically. On failure the
/// partial file is left where it is (the caller decides whether it is worth keeping) and the result is
/// EError::IoError naming both files and the system's reason, prefixed with inCaller.
CRUMPLE_API Status CommitPartialFile(const std::filesystem::path& inPath, std::string_view inCaller);

/// Writes inBytes to PartialFilePath(inPath), then renames it over inPath (CommitPartialFile), so that inPath
/// is either its old self or complete, never half written. On any failure the partial file is removed, inPath
/// is untouched and the result is EError::IoError naming the file and the system's reason (from errno or the
/// rename), prefixed with inCaller; an empty inPath is EError::InvalidArgument. Used by every whole-file
/// writer: surfaces (OBJ, PLY), PNG pictures, test OBJ dumps.
CRUMPLE_API Status WriteFileAtomically(const std::filesystem::path& inPath, std::span<const std::byte> inBytes,
                           std::string_view inCaller);

} // namespace crumple
