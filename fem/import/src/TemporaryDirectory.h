// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Result.h>

#include <filesystem>
#include <string>

namespace crumple::fem
{

/// A fresh folder (mkdtemp: unique, mode 0700) that is removed with its contents when this object is
/// destroyed, on every path out of the function that owns it.
class TemporaryDirectory
{
  public:
    /// Creates <inParent>/<inPrefix>XXXXXX; inParent empty = std::filesystem::temp_directory_path().
    /// EError::IoError when the parent is missing or not writable.
    static Result<TemporaryDirectory> Create(const std::filesystem::path& inParent,
                                             const std::string& inPrefix);

    TemporaryDirectory(TemporaryDirectory&& ioOther) noexcept : mPath(std::move(ioOther.mPath))
    {
        ioOther.mPath.clear();
    }
    TemporaryDirectory& operator=(TemporaryDirectory&&) = delete;
    TemporaryDirectory(const TemporaryDirectory&) = delete;
    TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;
    ~TemporaryDirectory();

    /// The folder
    const std::filesystem::path& GetPath() const { return mPath; }

  private:
    explicit TemporaryDirectory(std::filesystem::path inPath) : mPath(std::move(inPath)) {}

    std::filesystem::path mPath;
};

} // namespace crumple::fem
