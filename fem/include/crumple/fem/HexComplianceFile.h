// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Result.h>
#include <crumple/fem/HexCompliance.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string_view>
#include <vector>

namespace crumple::fem
{

/// Current compliance file format version. Readers refuse other versions.
constexpr std::uint32_t cHexComplianceVersion = 1;

/// The 8-byte magic that opens a compliance file.
constexpr std::string_view cHexComplianceMagic = "CRUMPHEX";

/// Encodes a compliance, all little-endian, IEEE-754 doubles (ByteWriter):
/// "CRUMPHEX" magic, u32 version, u32 node count, u32 source CRC, u32 #load, u32 #output,
/// #load u32 load nodes, #output u32 output nodes, then the 3 #output x 3 #load matrix as doubles in column-major
/// order (column 3 l + a after column 3 l + a - 1), and a CRC-32 of everything before it.
/// Size: 28 + 4 (#load + #output) + 72 #load #output bytes.
/// @param[in] inCompliance  a consistent compliance (matrix size matching the node lists)
/// @return the bytes; EError::InvalidArgument for an inconsistent compliance (sizes, node indices out of range
///         or repeated: what DecodeHexCompliance refuses), EError::NonFinite for a non-finite entry
CRUMPLE_API Result<std::vector<std::byte>> EncodeHexCompliance(const HexCompliance& inCompliance);

/// Decodes and checks a compliance: magic, version (EError::VersionMismatch), checksum, counts against the length,
/// node indices in range and unique, finite entries (EError::CorruptData otherwise). Nothing is returned unless
/// everything checks out.
CRUMPLE_API Result<HexCompliance> DecodeHexCompliance(std::span<const std::byte> inBytes);

/// Writes EncodeHexCompliance to a file through a temporary beside it and a rename, so that a failed write leaves
/// any existing file as it was (EError::IoError); a compliance EncodeHexCompliance refuses writes nothing (its
/// error).
CRUMPLE_API Status SaveHexCompliance(const std::filesystem::path& inPath, const HexCompliance& inCompliance);

/// Reads and decodes a file written by SaveHexCompliance (EError::IoError when unreadable; decode errors as above,
/// their message prefixed with the path).
CRUMPLE_API Result<HexCompliance> LoadHexCompliance(const std::filesystem::path& inPath);

} // namespace crumple::fem
