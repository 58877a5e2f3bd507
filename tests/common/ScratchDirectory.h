// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>

namespace crumple::common
{

/// A temporary folder of this process (created on first use), so that tests running at the same time,
/// from one build or several, never write the same files.
std::filesystem::path ScratchDirectory();

} // namespace crumple::common
