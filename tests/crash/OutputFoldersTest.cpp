// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// What a refused crumple-crash run takes back: the folders it made, never what another process wrote beside.
#include "OutputFolders.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

using namespace crumple::crash;

namespace
{

// A fresh scratch folder of this test, made empty.
std::filesystem::path Scratch(const char* inName)
{
    const std::filesystem::path folder =
        std::filesystem::temp_directory_path() / ("crumple-output-folders-" + std::to_string(::getpid())) / inName;
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    return folder;
}

} // namespace

TEST_CASE("Output folders: a refused run removes the folders it made, innermost first", "[crash]")
{
    const std::filesystem::path root = Scratch("own");
    const std::filesystem::path out = root / "a" / "b" / "c";
    const std::vector<std::filesystem::path> made = FoldersToMake(out);
    REQUIRE(made.size() == 3);
    CHECK(made.front() == std::filesystem::weakly_canonical(out));
    CHECK(made.back() == std::filesystem::weakly_canonical(root / "a"));
    std::filesystem::create_directories(out);
    std::ofstream(out / "report.json") << "{}";
    RemoveMadeFolders(made);
    CHECK_FALSE(std::filesystem::exists(root / "a"));
    CHECK(std::filesystem::exists(root));

    // An output folder that exists was not made by the run: nothing to take back.
    std::filesystem::create_directories(out);
    CHECK(FoldersToMake(out).empty());
    std::filesystem::remove_all(root.parent_path());
}

TEST_CASE("Output folders: what another run wrote beside a refused run's output stays", "[crash]")
{
    // Two runs into results/one and results/two where results did not exist: both count results as theirs.
    const std::filesystem::path root = Scratch("shared");
    const std::vector<std::filesystem::path> made = FoldersToMake(root / "results" / "one");
    REQUIRE(made.size() == 2);
    std::filesystem::create_directories(root / "results" / "one");
    std::filesystem::create_directories(root / "results" / "two");
    std::ofstream(root / "results" / "two" / "report.json") << "{}";
    RemoveMadeFolders(made);
    CHECK_FALSE(std::filesystem::exists(root / "results" / "one"));
    CHECK(std::filesystem::exists(root / "results" / "two" / "report.json"));
    std::filesystem::remove_all(root.parent_path());
}
