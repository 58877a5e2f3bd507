// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "SplitAtFeet.h"

#include <crumple/ffd/SplitFlipProneTriangles.h>

#include <cmath>
#include <optional>
#include <string>

namespace crumple::ffd
{

Result<RefinedMesh> SplitFlipProneTriangles(const TriangleMesh& inMesh, double inBendCurvature)
{
    if (!(std::isfinite(inBendCurvature) && inBendCurvature > 0.0))
        return MakeError(std::isfinite(inBendCurvature) ? EError::InvalidArgument : EError::NonFinite,
                         "SplitFlipProneTriangles: the bend curvature must be finite and > 0 (1/m), not " +
                             std::to_string(inBendCurvature));
    return SplitAtFeet(
        inMesh,
        [inBendCurvature](const FootOfLongestEdge& inFoot)
        {
            // h < kappa L^2 s (1 - s) / 2: the field's departure from the edge's line passes the far corner.
            // The most urgent has the lowest bend limit: an edge two such triangles share is split at the
            // foot of the one a gentler bend turns over (the other's pieces are looked at in the next pass).
            const double s = inFoot.mFraction;
            const double departure = 0.5 * inFoot.mLength * inFoot.mLength * s * (1.0 - s);
            if (!(inFoot.mHeight < inBendCurvature * departure))
                return std::optional<double>();
            return std::optional<double>(departure / inFoot.mHeight);
        },
        "SplitFlipProneTriangles");
}

} // namespace crumple::ffd
