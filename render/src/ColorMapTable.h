// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/render/EColorMap.h>

#include <array>
#include <span>

namespace crumple::render
{

/// Most entries of a colour map table (the shader's uniform array size).
constexpr int cMaxColorMapEntries = 16;

/// Evenly spaced RGB samples of a colour map from t = 0 to t = 1, to be interpolated linearly.
/// Viridis: 11 samples of matplotlib's table (van der Walt and Smith 2015, CC0).
/// CoolWarm: 9 samples of Moreland's smooth cool-warm map ("Diverging Color Maps for Scientific
/// Visualization", ISVC 2009).
std::span<const std::array<float, 3>> ColorMapTable(EColorMap inMap);

} // namespace crumple::render
