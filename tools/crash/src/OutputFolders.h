// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <span>
#include <vector>

namespace crumple::crash
{

/// The folders a run will make for its output folder inOut: inOut and each of its parents that does not
/// exist yet, innermost first, with the links in the part that exists resolved as create_directories
/// resolves them; empty when inOut exists.
std::vector<std::filesystem::path> FoldersToMake(const std::filesystem::path& inOut);

/// Takes back what a refused run made (FoldersToMake before it made them): the output folder with what the
/// run wrote in it, then each parent it made, innermost first, only while that parent is empty. Another
/// process may have written beside the output folder since (two runs into results/a and results/b, where
/// results did not exist): its files, and the folders that hold them, stay.
void RemoveMadeFolders(std::span<const std::filesystem::path> inMade);

} // namespace crumple::crash
