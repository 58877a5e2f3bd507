// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "CarMesh.h"
#include "RemoveCaps.h"

#include <crumple/crash/RecutCarMesh.h>
#include <crumple/ffd/DropLooseSlivers.h>
#include <crumple/ffd/FlipFlatEdges.h>
#include <crumple/ffd/RefineLongEdges.h>

#include <utility>

namespace crumple::crash
{

Result<MeshPreparation> RecutCarMesh(ffd::TriangleMesh& ioMesh, std::vector<std::vector<std::uint32_t>>& ioRigidParts,
                                     double inMaxEdge, double inFlipDeviation)
{
    MeshPreparation preparation;
    preparation.mFileTriangles = ioMesh.mTriangles.size();
    preparation.mFileVertices = ioMesh.mPositions.size();
    if (inMaxEdge > 0.0)
    {
        preparation.mMaxEdge = inMaxEdge;
        Result<std::size_t> slivers = ffd::DropLooseSlivers(ioMesh);
        if (slivers.HasError())
            return slivers.GetError();
        preparation.mLooseSlivers = slivers.Get();
        Result<std::size_t> flipped = ffd::FlipFlatEdges(ioMesh);
        if (flipped.HasError())
            return flipped.GetError();
        preparation.mFlatFlips = flipped.Get();
        Result<ffd::RefinedMesh> refined = ffd::RefineLongEdges(ioMesh, inMaxEdge);
        if (refined.HasError())
            return refined.GetError();
        ioRigidParts = samples::PartsAfterRefinement(ioRigidParts, refined.Get());
        ioMesh = std::move(refined.Get().mMesh);
        flipped = ffd::FlipFlatEdges(ioMesh);
        if (flipped.HasError())
            return flipped.GetError();
        preparation.mFlatFlips += flipped.Get();
        preparation.mFlipDeviation = inFlipDeviation;
        Result<samples::CapRemoval> caps = samples::RemoveCaps(ioMesh, ioRigidParts, inFlipDeviation);
        if (caps.HasError())
            return caps.GetError();
        preparation.mNearlyFlatFlips = caps.Get().mFlips;
        preparation.mCapSplitVertices = caps.Get().mSplitVertices;
    }
    preparation.mTriangles = ioMesh.mTriangles.size();
    preparation.mVertices = ioMesh.mPositions.size();
    return preparation;
}

} // namespace crumple::crash
