// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "ScratchDirectory.h"

#include <cstdlib>
#include <string>
#include <system_error>

#include <unistd.h>

namespace crumple::common
{

namespace
{

// The folder, made on construction and removed with everything in it when the process that made it exits:
// a test run leaves nothing behind in the temporary folder (each test process made one of its own, and
// thousands of them piled up). A forked child that exits normally leaves it to its parent.
class ProcessFolder
{
  public:
    explicit ProcessFolder(std::filesystem::path inPath) : mPath(std::move(inPath)), mOwner(::getpid())
    {
        std::filesystem::create_directories(mPath);
    }
    ProcessFolder(const ProcessFolder&) = delete;
    ProcessFolder& operator=(const ProcessFolder&) = delete;
    ~ProcessFolder()
    {
        // intent: CRUMPLE_KEEP_SCRATCH keeps what a failed test wrote (recordings, meshes) to look at
        if (::getpid() != mOwner || std::getenv("CRUMPLE_KEEP_SCRATCH") != nullptr)
            return;
        std::error_code ignored; // nothing to report to at exit; a folder left behind is harmless
        std::filesystem::remove_all(mPath, ignored);
    }

    const std::filesystem::path& GetPath() const { return mPath; }

  private:
    std::filesystem::path mPath;
    pid_t mOwner;
};

} // namespace

std::filesystem::path ScratchDirectory()
{
    static const ProcessFolder folder(std::filesystem::temp_directory_path() /
                                      ("crumple-test-" + std::to_string(static_cast<long>(::getpid()))));
    // intent: made again if a test removed it (ScratchDirectory was "created on first use" per call before)
    std::filesystem::create_directories(folder.GetPath());
    return folder.GetPath();
}

} // namespace crumple::common
