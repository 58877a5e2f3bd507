// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Result.h>
#include <crumple/crash/CrashScenario.h>

#include <filesystem>
#include <string_view>

namespace crumple::crash
{

/// Parses and validates a scenario (JSON text; the schema is in docs/scenarios.md). Every refusal names the
/// place as a JSON pointer ("/vehicle/mass_kg: must be > 0, got -5"): an unknown key (with the known keys of
/// that object, and a hint for a unit suffix it does not accept, e.g. speed_mph), a wrong type, a missing
/// required key, a non-finite or out-of-range number, a mesh file that does not exist. Relative mesh paths
/// are resolved against inBaseFolder. Text that is not JSON is EError::CorruptData "line L, column C: ...",
/// a missing mesh EError::IoError, everything else (a key given twice included) EError::InvalidArgument.
/// Never throws.
Result<CrashScenario> ParseCrashScenario(std::string_view inJson, const std::filesystem::path& inBaseFolder);

/// Reads and parses a scenario file (its folder is the base for relative paths). An unreadable file is
/// EError::IoError naming it; an empty file or one that is not JSON is EError::CorruptData "line L, column C:
/// ..."; every message of a file that was read starts with inPath ("<path>: /vehicle/mass_kg: required").
Result<CrashScenario> LoadCrashScenario(const std::filesystem::path& inPath);

} // namespace crumple::crash
