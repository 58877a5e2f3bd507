// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "RemoveCaps.h"

#include "CarMesh.h"

#include <crumple/ffd/FlipFlatEdges.h>
#include <crumple/ffd/SplitCaps.h>
#include <crumple/ffd/SplitFlipProneTriangles.h>

#include <cmath>
#include <numbers>
#include <string>
#include <utility>

namespace crumple::samples
{

namespace
{

// Every triangle the Toy Car's pole, offset and 30-degree hits turned over had a corner over 150 degrees
// (460 of 467 over 170). Flipping every nearly flat edge instead retriangulated the whole body (155,108 flips)
// and, across the split vertices of hard edges, mixed the two sides' normals: the trims' shading turned
// speckled in the pictures.
constexpr double cCapAngle = 150.0 * std::numbers::pi / 180.0;

// Rounds of splits and flips: on the re-cut Toy Car 4,193 split edges, then 1,430, 591, 238, 81, 31, ...; the
// racing car with flip-prone triangles split at 10 /m too: 3,795, 1,244, 573, ... none after 26 rounds.
constexpr int cMaxCapRounds = 32;

} // namespace

Result<CapRemoval> RemoveCaps(ffd::TriangleMesh& ioMesh,
                              std::vector<std::vector<std::uint32_t>>& ioRigidParts, double inFlipDeviation,
                              double inBendCurvature)
{
    for (const auto& [value, name] :
         {std::pair{inFlipDeviation, "flip deviation"}, std::pair{inBendCurvature, "bend curvature"}})
        if (!(std::isfinite(value) && value >= 0.0))
            return MakeError(std::isfinite(value) ? EError::InvalidArgument : EError::NonFinite,
                             std::string("RemoveCaps: the ") + name + " must be finite and >= 0, not " +
                                 std::to_string(value));
    CapRemoval removal;
    if (inFlipDeviation > 0.0)
    {
        Result<std::size_t> flipped = ffd::FlipNearlyFlatEdges(ioMesh, inFlipDeviation, true, cCapAngle);
        if (flipped.HasError())
            return flipped.GetError();
        removal.mFlips = flipped.Get();
    }
    // The caps no flip removed lie on creases (the Toy Car's front lip): split them at their feet. A
    // neighbour split with a cap can leave a cap among its pieces; a nearly flat flip removes most of those,
    // so the two alternate until no cap is left.
    // intent: one kind of split taken: its vertices counted into ioCount, the parts following them
    const auto keep = [&](Result<ffd::RefinedMesh> inSplit, std::size_t& ioCount) -> Result<std::size_t>
    {
        if (inSplit.HasError())
            return inSplit.GetError();
        const std::size_t added = inSplit.Get().mSplitParents.size();
        if (added > 0)
        {
            ioRigidParts = PartsAfterRefinement(ioRigidParts, inSplit.Get());
            ioMesh = std::move(inSplit.Get().mMesh);
            ioCount += added;
        }
        return added;
    };
    for (int round = 0; round < cMaxCapRounds; ++round)
    {
        Result<std::size_t> caps = keep(ffd::SplitCaps(ioMesh, cCapAngle), removal.mSplitVertices);
        if (caps.HasError())
            return caps.GetError();
        std::size_t added = caps.Get();
        if (inBendCurvature > 0.0)
        {
            Result<std::size_t> prone =
                keep(ffd::SplitFlipProneTriangles(ioMesh, inBendCurvature), removal.mFlipProneVertices);
            if (prone.HasError())
                return prone.GetError();
            added += prone.Get();
        }
        if (added == 0)
            break;
        if (inFlipDeviation > 0.0)
        {
            Result<std::size_t> flipped = ffd::FlipNearlyFlatEdges(ioMesh, inFlipDeviation, true, cCapAngle);
            if (flipped.HasError())
                return flipped.GetError();
            removal.mFlips += flipped.Get();
        }
    }
    return removal;
}

} // namespace crumple::samples
