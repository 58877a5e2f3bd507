// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

namespace crumple
{

/// The library version, "major.minor.patch".
CRUMPLE_API const char* VersionString();

} // namespace crumple
