// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "ColorMapTable.h"

namespace crumple::render
{

namespace
{

/// matplotlib viridis at t = 0, 0.1, ..., 1 (entries 0, 25, 51, ..., 255 of its 256-entry table).
constexpr std::array<std::array<float, 3>, 11> cViridis{{
    {0.267004f, 0.004874f, 0.329415f},
    {0.282623f, 0.140926f, 0.457517f},
    {0.253935f, 0.265254f, 0.529983f},
    {0.206756f, 0.371758f, 0.553117f},
    {0.163625f, 0.471133f, 0.558148f},
    {0.127568f, 0.566949f, 0.550556f},
    {0.134692f, 0.658636f, 0.517649f},
    {0.266941f, 0.748751f, 0.440573f},
    {0.477504f, 0.821444f, 0.318195f},
    {0.741388f, 0.873449f, 0.149561f},
    {0.993248f, 0.906157f, 0.143936f},
}};

/// Moreland's cool-warm at t = 0, 0.125, ..., 1 (every fourth entry of CoolWarmFloat33).
constexpr std::array<std::array<float, 3>, 9> cCoolWarm{{
    {0.229806f, 0.298718f, 0.753683f},
    {0.383013f, 0.509419f, 0.917388f},
    {0.552953f, 0.688929f, 0.995376f},
    {0.722193f, 0.813953f, 0.976575f},
    {0.865395f, 0.865410f, 0.865396f},
    {0.958853f, 0.769768f, 0.678008f},
    {0.958003f, 0.602842f, 0.481776f},
    {0.869187f, 0.378313f, 0.300267f},
    {0.705673f, 0.015556f, 0.150233f},
}};

static_assert(cViridis.size() <= cMaxColorMapEntries && cCoolWarm.size() <= cMaxColorMapEntries);

} // namespace

std::span<const std::array<float, 3>> ColorMapTable(EColorMap inMap)
{
    switch (inMap)
    {
    case EColorMap::Viridis:
        return cViridis;
    case EColorMap::CoolWarm:
        return cCoolWarm;
    }
    return cViridis;
}

} // namespace crumple::render
