// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <string>

namespace crumple::fem
{

/// A double as printf's "%.17g" would print it (17 significant digits, so it reads back to the same bits),
/// but independent of the C locale: the decimal separator is always '.'. For text files other programs read
/// (OBJ surfaces, tetgen's OFF input) and for exact values in error messages.
/// @param[in] inValue  any double; non-finite values print as "inf", "-inf" or "nan"
CRUMPLE_API std::string ExactNumber(double inValue);

} // namespace crumple::fem
