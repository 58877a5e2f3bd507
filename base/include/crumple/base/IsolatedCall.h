// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Result.h>

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace crumple
{

/// The longest timeout RunIsolated takes (s): eleven days, and an integer CPU limit holds it exactly.
constexpr double cMaxIsolatedTimeout = 1.0e6;

/// Runs inWork in a child process and returns the bytes it produced, or its error: a third-party parser
/// that crashes, aborts or hangs on an untrusted file (assimp does, on some malformed OBJ, PLY, OFF and glTF
/// files: scripts/fuzz.sh found them) then fails the call with a message instead of taking the caller down.
///
/// POSIX fork without exec: the child is a copy of the caller that runs only inWork, sends its result
/// through a pipe and exits; the caller's memory, file descriptors and other threads are untouched. In the
/// child fatal signals take their default action (the caller's crash handlers do not run there) and its
/// standard output and error go to /dev/null; it is killed when the caller dies (Linux) and by a CPU limit of
/// the timeout. Only the
/// calling thread exists in the child, so inWork must not wait on a lock another thread of the caller may
/// hold (glibc's malloc is safe). Costs a fork (page tables of the caller's memory: about 1 ms per GB).
/// Elsewhere than POSIX inWork runs in the caller, unprotected.
/// @param[in] inWork    what to run; its bytes or error come back
/// @param[in] inTimeout seconds before the child is killed, in (0, cMaxIsolatedTimeout]
/// @param[in] inWhat    names the work in messages (e.g. the file's path)
/// @return inWork's bytes or error; EError::CorruptData when the child died by a signal or took longer than
///         inTimeout; EError::IoError when no child could be started; EError::InvalidArgument (nothing run) for a
///         timeout outside (0, cMaxIsolatedTimeout]
CRUMPLE_API Result<std::vector<std::byte>> RunIsolated(const std::function<Result<std::vector<std::byte>>()>& inWork,
                                           double inTimeout, const std::string& inWhat);

} // namespace crumple
