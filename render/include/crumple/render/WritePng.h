// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Result.h>

#include <cstdint>
#include <filesystem>
#include <span>

namespace crumple::render
{

/// Writes an 8-bit RGBA image as a PNG file. The file is written beside inPath as "<inPath>.partial" and
/// renamed over inPath only when complete (WriteFileAtomically), so inPath never holds a partial picture; on
/// failure the partial file is removed and inPath is untouched. Fails with EError::InvalidArgument for a size
/// mismatch and EError::IoError when the directory is missing or not writable.
/// @param[in] inPath   destination file, its directory must exist
/// @param[in] inWidth  image width (pixels), > 0
/// @param[in] inHeight image height (pixels), > 0
/// @param[in] inRgba   inWidth * inHeight * 4 bytes, rows top to bottom (as MeshRenderer::Render gives them)
CRUMPLE_API Status WritePng(const std::filesystem::path& inPath, int inWidth, int inHeight,
                std::span<const std::uint8_t> inRgba);

} // namespace crumple::render
