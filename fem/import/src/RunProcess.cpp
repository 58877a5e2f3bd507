// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "RunProcess.h"

#include <crumple/base/FileBytes.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace crumple::fem
{

namespace
{

// A regular file the process may execute.
bool IsExecutableFile(const std::filesystem::path& inPath)
{
    struct stat info
    {
    };
    return ::stat(inPath.c_str(), &info) == 0 && S_ISREG(info.st_mode) && ::access(inPath.c_str(), X_OK) == 0;
}

} // namespace

Result<std::filesystem::path> FindExecutable(const std::string& inName)
{
    if (inName.empty())
        return MakeError(EError::InvalidArgument, "empty program name");
    if (inName.find('/') != std::string::npos)
    {
        if (IsExecutableFile(inName))
            return std::filesystem::path(inName);
        return MakeError(EError::IoError, "'" + inName + "' is not an executable file");
    }

    // The PATH folders in order, as execvp searches them.
    const char* variable = std::getenv("PATH");
    const std::string path = variable != nullptr ? variable : "/bin:/usr/bin";
    std::size_t first = 0;
    while (true)
    {
        const std::size_t colon = path.find(':', first);
        const std::string folder =
            path.substr(first, colon == std::string::npos ? std::string::npos : colon - first);
        const std::filesystem::path candidate =
            std::filesystem::path(folder.empty() ? std::string(".") : folder) / inName;
        if (IsExecutableFile(candidate))
            return candidate;
        if (colon == std::string::npos)
            break;
        first = colon + 1;
    }
    return MakeError(EError::IoError, "'" + inName + "' not found on PATH (" + path + ")");
}

Result<ProcessOutcome> RunProcess(const std::filesystem::path& inExecutable,
                                  const std::vector<std::string>& inArguments,
                                  const std::filesystem::path& inLogFile)
{
    // argv: the program, then the arguments, as one null-terminated array of C strings.
    std::vector<std::string> storage;
    storage.push_back(inExecutable.string());
    storage.insert(storage.end(), inArguments.begin(), inArguments.end());
    std::vector<char*> argv;
    for (std::string& argument : storage)
        argv.push_back(argument.data());
    argv.push_back(nullptr);

    // Standard input from /dev/null, standard output and error into the log file.
    posix_spawn_file_actions_t actions;
    if (posix_spawn_file_actions_init(&actions) != 0)
        return MakeError(EError::IoError, "cannot prepare to run " + inExecutable.string());
    const bool prepared =
        posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0) == 0 &&
        posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, inLogFile.c_str(),
                                         O_WRONLY | O_CREAT | O_TRUNC, 0600) == 0 &&
        posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO) == 0;
    if (!prepared)
    {
        posix_spawn_file_actions_destroy(&actions);
        return MakeError(EError::IoError, "cannot prepare to run " + inExecutable.string());
    }
    pid_t child = -1;
    const int spawn_error =
        posix_spawn(&child, inExecutable.c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawn_error != 0)
        return MakeError(EError::IoError,
                         "cannot run " + inExecutable.string() + ": " + std::strerror(spawn_error));

    // Wait for it, through interruptions by signals.
    int status = 0;
    pid_t waited = -1;
    do
        waited = ::waitpid(child, &status, 0);
    while (waited == -1 && errno == EINTR);
    if (waited != child)
        return MakeError(EError::IoError,
                         "lost track of " + inExecutable.string() + ": " + std::strerror(errno));

    ProcessOutcome outcome;
    if (WIFEXITED(status))
        outcome.mExitCode = WEXITSTATUS(status);
    else if (WIFSIGNALED(status))
        outcome.mSignal = WTERMSIG(status);
    if (Result<std::vector<std::byte>> log = ReadFileBytes(inLogFile); log.IsValid())
        outcome.mOutput.assign(reinterpret_cast<const char*>(log.Get().data()), log.Get().size());
    return outcome;
}

} // namespace crumple::fem
