// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Result.h>

#include <cstddef>
#include <filesystem>
#include <vector>

namespace crumple
{

/// Reads a whole file (damage states, replays). A missing or unreadable file is EError::IoError.
Result<std::vector<std::byte>> ReadFileBytes(const std::filesystem::path& inPath);

} // namespace crumple
