// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/base/Version.h>

namespace crumple
{

const char* VersionString()
{
    return CRUMPLE_VERSION_STRING;
}

} // namespace crumple
