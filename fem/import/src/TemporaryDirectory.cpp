// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "TemporaryDirectory.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace crumple::fem
{

Result<TemporaryDirectory> TemporaryDirectory::Create(const std::filesystem::path& inParent,
                                                      const std::string& inPrefix)
{
    std::error_code error;
    const std::filesystem::path parent =
        inParent.empty() ? std::filesystem::temp_directory_path(error) : inParent;
    if (error)
        return MakeError(EError::IoError, "no temporary folder: " + error.message());

    // mkdtemp replaces the trailing XXXXXX in place.
    const std::string pattern = (parent / (inPrefix + "XXXXXX")).string();
    std::vector<char> name(pattern.begin(), pattern.end());
    name.push_back('\0');
    if (::mkdtemp(name.data()) == nullptr)
        return MakeError(EError::IoError,
                         "cannot create a temporary folder " + pattern + ": " + std::strerror(errno));
    return TemporaryDirectory(std::filesystem::path(name.data()));
}

TemporaryDirectory::~TemporaryDirectory()
{
    // Best effort: a destructor cannot report, and nothing else can be done about a failure here.
    if (!mPath.empty())
    {
        std::error_code ignored;
        std::filesystem::remove_all(mPath, ignored);
    }
}

} // namespace crumple::fem
