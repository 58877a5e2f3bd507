// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/ExactNumber.h>

#include <charconv>

namespace crumple::fem
{

std::string ExactNumber(double inValue)
{
    // to_chars never consults the locale; 32 characters hold any 17-digit "%g" form.
    char buffer[32];
    const std::to_chars_result result =
        std::to_chars(buffer, buffer + sizeof(buffer), inValue, std::chars_format::general, 17);
    return std::string(buffer, result.ptr);
}

} // namespace crumple::fem
