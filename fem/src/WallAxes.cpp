// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/WallAxes.h>

#include <algorithm>

namespace crumple::fem
{

std::array<int, 3> WallAxes(const Vec3& inSize)
{
    // Stable sort by decreasing extent: equal extents keep x before y before z.
    std::array<int, 3> axes{{0, 1, 2}};
    std::stable_sort(axes.begin(), axes.end(),
                     [&inSize](int inA, int inB) { return inSize[inA] > inSize[inB]; });
    return axes;
}

} // namespace crumple::fem
