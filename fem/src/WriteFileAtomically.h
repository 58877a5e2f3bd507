// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Result.h>

#include <cstddef>
#include <filesystem>
#include <span>
#include <string_view>

namespace crumple::fem
{

/// Writes inBytes to "<inPath>.partial", then renames it to inPath, so that inPath is either its old self or
/// complete. On failure the partial file is removed and EError::IoError names the file and the system's
/// reason, prefixed with inCaller.
Status WriteFileAtomically(const std::filesystem::path& inPath, std::span<const std::byte> inBytes,
                           std::string_view inCaller);

} // namespace crumple::fem
