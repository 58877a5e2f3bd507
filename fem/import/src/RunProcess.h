// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Result.h>

#include <filesystem>
#include <string>
#include <vector>

namespace crumple::fem
{

/// How a child process ended and what it printed.
struct ProcessOutcome
{
    int mExitCode = -1;  ///< exit status when it exited normally, else -1
    int mSignal = 0;     ///< the signal that ended it (e.g. SIGABRT), else 0
    std::string mOutput; ///< its standard output and standard error, interleaved
};

/// Resolves a program name like execvp would: a name containing '/' is taken as a path, a bare name is looked
/// up in the PATH folders (an empty entry is the current folder; no PATH: /bin:/usr/bin). The file must be a
/// regular executable file. EError::IoError when not found, naming the folders searched.
Result<std::filesystem::path> FindExecutable(const std::string& inName);

/// Runs inExecutable with inArguments (argv[1..], no shell, the parent's environment), standard input from
/// /dev/null and standard output and error into inLogFile, and waits for it. EError::IoError when it cannot
/// be started.
Result<ProcessOutcome> RunProcess(const std::filesystem::path& inExecutable,
                                  const std::vector<std::string>& inArguments,
                                  const std::filesystem::path& inLogFile);

} // namespace crumple::fem
