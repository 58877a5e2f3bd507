// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "OutputFolders.h"

#include <system_error>

namespace crumple::crash
{

std::vector<std::filesystem::path> FoldersToMake(const std::filesystem::path& inOut)
{
    std::vector<std::filesystem::path> made;
    std::error_code error;
    // intent: weakly_canonical resolves the links in the part that exists, as create_directories will
    for (std::filesystem::path folder = std::filesystem::weakly_canonical(std::filesystem::absolute(inOut, error), error);
         !error && !folder.empty() && !std::filesystem::exists(folder, error); folder = folder.parent_path())
    {
        made.push_back(folder);
        if (folder == folder.parent_path())
            break;
    }
    return error ? std::vector<std::filesystem::path>{} : made;
}

void RemoveMadeFolders(std::span<const std::filesystem::path> inMade)
{
    std::error_code error;
    if (inMade.empty())
        return;
    std::filesystem::remove_all(inMade.front(), error);
    // intent: remove() takes only an empty folder, so a parent another process wrote into stays
    for (std::size_t index = 1; index < inMade.size(); ++index)
        if (!std::filesystem::remove(inMade[index], error))
            return;
}

} // namespace crumple::crash
