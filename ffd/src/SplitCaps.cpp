// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "SplitAtFeet.h"

#include <crumple/ffd/SplitCaps.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <string>

namespace crumple::ffd
{

Result<RefinedMesh> SplitCaps(const TriangleMesh& inMesh, double inCapAngle)
{
    if (!(inCapAngle >= 0.5 * std::numbers::pi && inCapAngle <= std::numbers::pi))
        return MakeError(EError::InvalidArgument, "SplitCaps: the cap angle must be in [pi/2, pi] rad, not " +
                                                      std::to_string(inCapAngle));
    const double cos_cap = std::cos(inCapAngle);
    return SplitAtFeet(
        inMesh,
        [cos_cap](const FootOfLongestEdge& inFoot)
        {
            const Vec3& corner = inFoot.mCorners[inFoot.mCorner];
            const Vec3 u = inFoot.mCorners[(inFoot.mCorner + 1) % 3] - corner;
            const Vec3 v = inFoot.mCorners[(inFoot.mCorner + 2) % 3] - corner;
            const double norms = u.norm() * v.norm();
            // intent: every cap alike: an edge goes to the first cap on it in triangle order
            return norms > 0.0 && u.dot(v) / norms <= cos_cap ? std::optional<double>(0.0) : std::nullopt;
        },
        "SplitCaps");
}

} // namespace crumple::ffd
