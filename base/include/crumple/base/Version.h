// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

namespace crumple
{

/// The library version, "major.minor.patch".
const char* VersionString();

} // namespace crumple
