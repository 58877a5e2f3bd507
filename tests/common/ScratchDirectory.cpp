// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "ScratchDirectory.h"

#include <string>

#include <unistd.h>

namespace crumple::common
{

std::filesystem::path ScratchDirectory()
{
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("crumple-test-" + std::to_string(static_cast<long>(::getpid())));
    std::filesystem::create_directories(dir);
    return dir;
}

} // namespace crumple::common
