// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>

namespace crumple::common
{

/// A temporary folder of this process (crumple-test-<pid> in the system's temporary folder, TMPDIR, made on
/// each call if missing), so that tests running at the same time, from one build or several, never write the
/// same files. It is removed with everything in it when the process exits normally, unless the environment
/// has CRUMPLE_KEEP_SCRATCH (to look at what a failed test wrote).
std::filesystem::path ScratchDirectory();

} // namespace crumple::common
