// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

// Private: number formatting for error messages (std::to_string prints 1e-9 as 0.000000).

#include <cstdio>
#include <string>

namespace crumple::fem
{

/// Formats a double with 6 significant digits ("%.6g").
inline std::string HexFormat(double inValue)
{
    char text[32];
    std::snprintf(text, sizeof(text), "%.6g", inValue);
    return text;
}

} // namespace crumple::fem
