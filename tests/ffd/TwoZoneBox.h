// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include "BoxMesh.h"
#include "Slivers.h"

#include <crumple/ffd/FfdDeformer.h>
#include <crumple/plugin/DeformableObjectSettings.h>

#include <array>

namespace crumple::test
{

/// A box car body of half extents inHalf (x from -inHalf.x to +inHalf.x) in two FFD zones split at x = 0.3,
/// the front one with inFrontControls and the middle one (x from -1.8) with inMiddleControls, so triangles
/// span the split and the rear 0.2 m lies in no zone (loose vertices).
/// @param[in] inSegments  the box mesh's segments per axis
/// @param[in] inMaxTotal  each zone's maximum total deformation (m)
/// @param[in] inSlivers   slivers (AddSlivers) added inside the box along its length (from y = z = 0, in the
///                        zones): a coarse box with them stays on a probe's cell-by-cell path
inline ffd::FfdDeformer TwoZoneBox(const Vec3& inHalf, const std::array<int, 3>& inSegments,
                                   const std::array<int, 3>& inFrontControls,
                                   const std::array<int, 3>& inMiddleControls, double inMaxTotal,
                                   int inSlivers = 0)
{
    ffd::TriangleMesh mesh = common::MakeBoxMesh(inHalf, inSegments);
    AddSlivers(mesh, Vec3(-1.7, 0.0, 0.0), inHalf.x() - 0.1 + 1.7, inSlivers);
    ffd::FfdDeformerSettings settings;
    const ffd::FfdZoneSettings whole = plugin::FitZoneToMesh(mesh, inFrontControls, inMaxTotal);
    ffd::FfdZoneSettings front = whole, middle = whole;
    front.mLattice.mOrigin.x() = 0.3;
    front.mLattice.mSize.x() = whole.mLattice.mOrigin.x() + whole.mLattice.mSize.x() - 0.3;
    middle.mLattice.mOrigin.x() = -1.8;
    middle.mLattice.mSize.x() = 2.1;
    middle.mLattice.mControlCount = inMiddleControls;
    settings.mZones = {front, middle};
    return ffd::FfdDeformer::Create(std::move(mesh), settings).Get();
}

} // namespace crumple::test
