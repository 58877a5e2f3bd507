// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>

namespace crumple::common
{

/// A temporary folder of this process (/tmp/crumple-test-<pid>, made on each call if missing), so that tests
/// running at the same time, from one build or several, never write the same files. It is removed with
/// everything in it when the process exits normally.
std::filesystem::path ScratchDirectory();

} // namespace crumple::common
