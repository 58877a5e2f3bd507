// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Result.h>
#include <crumple/fem/HexCompliance.h>

#include <filesystem>

namespace crumple::fem
{

/// Writes a compliance as CSV for tools (spreadsheets, Houdini, Python; the seed paper, section 3.2.1, exports
/// its inverse stiffness matrices as CSV too), one entry per line after the header
///   output_node,output_axis,load_node,load_axis,compliance_m_per_n
/// where the nodes are mesh node indices, the axes are x, y or z, and compliance_m_per_n is the displacement (m)
/// of output_node along output_axis per newton on load_node along load_axis ("%.17g", so it reads back exactly).
/// Lines run column by column of HexCompliance::mMatrix (load node, then load axis, then output node, then
/// output axis), 9 #load #output lines (about 40 bytes each). Written through a temporary file and a rename, so
/// a failed write leaves any existing file as it was.
/// @return EError::InvalidArgument for an inconsistent compliance or an empty path, EError::IoError when the file
///         cannot be written
CRUMPLE_API Status WriteHexComplianceCsv(const std::filesystem::path& inPath, const HexCompliance& inCompliance);

} // namespace crumple::fem
