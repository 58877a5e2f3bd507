// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// Fuzz target: a crash scenario file (crumple-crash's input), parsed as LoadCrashScenario does. Relative
// mesh and preset paths resolve in the current folder.
#include <crumple/crash/ScenarioFile.h>

#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* inData, std::size_t inSize)
{
    const std::string_view json(reinterpret_cast<const char*>(inData), inSize);
    (void)crumple::crash::ParseCrashScenario(json, ".");
    return 0;
}
