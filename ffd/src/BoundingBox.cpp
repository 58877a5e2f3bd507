// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/ffd/BoundingBox.h>

namespace crumple::ffd
{

AlignedBox BoundingBox(std::span<const Vec3> inPoints)
{
    if (inPoints.empty())
        return {};
    AlignedBox box{inPoints[0], inPoints[0]};
    for (const Vec3& p : inPoints)
    {
        box.mMin = box.mMin.cwiseMin(p);
        box.mMax = box.mMax.cwiseMax(p);
    }
    return box;
}

} // namespace crumple::ffd
