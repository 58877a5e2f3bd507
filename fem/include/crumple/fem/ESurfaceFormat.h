// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <cstdint>

namespace crumple::fem
{

/// File format of an exported surface (SaveSurface, FrameSequenceWriter).
enum class ESurfaceFormat : std::uint8_t
{
    /// Wavefront OBJ, text: "v x y z" lines printed like "%.17g" (locale-independent, so doubles read back
    /// bit for bit), then "f a b c" lines with 1-based indices. Extension "obj".
    Obj,
    /// Stanford PLY, "format binary_little_endian 1.0": vertices as three "property double" x, y, z, faces as
    /// "property list uchar int vertex_indices" (count 3, then three 32-bit signed 0-based indices). About a
    /// third of the OBJ size and exact. Extension "ply".
    Ply,
};

/// Short name of an ESurfaceFormat, for messages.
CRUMPLE_API const char* ToString(ESurfaceFormat inFormat);

/// File name extension of an ESurfaceFormat, without the dot: "obj" or "ply".
CRUMPLE_API const char* SurfaceFileExtension(ESurfaceFormat inFormat);

} // namespace crumple::fem
