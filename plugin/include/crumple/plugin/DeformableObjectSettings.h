// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/ffd/FfdDeformerSettings.h>
#include <crumple/ffd/TriangleMesh.h>
#include <crumple/plugin/DamageMaterial.h>

#include <array>

namespace crumple::plugin
{

/// Describes a deformable object: its render mesh, material and FFD zones (D4MD's "deformable object"
/// with its "geometry deformers"). Everything is in the frame of the body it is attached to.
struct DeformableObjectSettings
{
    ffd::TriangleMesh mMesh;            ///< Render mesh, body frame (m)
    DamageMaterial mMaterial;           ///< Impulse-to-dent parameters
    ffd::FfdDeformerSettings mDeformer; ///< Zones and solver tolerances; with no zones, one zone is fitted
                                        ///< around the mesh (see FitZoneToMesh) using the two fields below
    std::array<int, 3> mFittedControlCount{{8, 8, 8}}; ///< Controls per axis of the fitted zone
    double mFittedMaxTotalDeformation = 0.5;          ///< Max total deformation of the fitted zone (m)
    bool mInterpolateWideImpacts = true; ///< Fill gaps between contacts wider than the lattice spacing
};

/// An axis-aligned zone (body frame) enclosing inMesh with a margin of 1 % of its size plus 1 mm.
ffd::FfdZoneSettings FitZoneToMesh(const ffd::TriangleMesh& inMesh, const std::array<int, 3>& inControlCount,
                                   double inMaxTotalDeformation);

} // namespace crumple::plugin
