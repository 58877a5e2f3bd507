// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

namespace crumple::render
{

/// How a per-vertex scalar (e.g. displacement magnitude in m) becomes a surface colour.
enum class EColorMap
{
    Viridis,  ///< Sequential, perceptually uniform, dark purple (low) to yellow (high): magnitudes >= 0
    CoolWarm, ///< Diverging blue (low), grey (middle), red (high) (Moreland 2009): signed values
};

} // namespace crumple::render
