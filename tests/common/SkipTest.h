// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>

namespace crumple::common
{

/// The exit code CTest reads as "skipped" for every test binary (SKIP_RETURN_CODE in tests/CMakeLists.txt).
constexpr int cSkipReturnCode = 77;

/// Ends the test process as skipped: a test that cannot run here (no EGL device) must show as skipped in
/// CTest, never as passed. CTest runs each Catch2 test case in its own process, so only that case ends; run
/// by hand, the binary stops at the first skip.
[[noreturn]] inline void SkipTest(const std::string& inWhy)
{
    std::printf("skipped: %s\n", inWhy.c_str());
    std::fflush(stdout);
    std::_Exit(cSkipReturnCode);
}

} // namespace crumple::common
