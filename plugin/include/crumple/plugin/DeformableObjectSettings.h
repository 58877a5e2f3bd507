// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/ffd/FfdDeformerSettings.h>
#include <crumple/ffd/TriangleMesh.h>
#include <crumple/plugin/DamageMaterial.h>

#include <array>

namespace crumple::plugin
{

/// Describes a deformable object: its render mesh, material and FFD zones (D4MD's "deformable object"
/// with its "geometry deformers"). Everything is in the frame of the body it is attached to.
struct CRUMPLE_API DeformableObjectSettings
{
    ffd::TriangleMesh mMesh;            ///< Render mesh, body frame (m)
    DamageMaterial mMaterial;           ///< Impulse-to-dent parameters
    ffd::FfdDeformerSettings mDeformer; ///< Zones and solver tolerances; with no zones, one zone is fitted
                                        ///< around the mesh (see FitZoneToMesh) using the two fields below
    /// Controls per axis of the fitted zone, each >= 4; all 0 (the default): from mFittedControlSpacing
    std::array<int, 3> mFittedControlCount{{0, 0, 0}};
    /// Control spacing of the fitted zone when mFittedControlCount is 0 (m), > 0. A control reaches two cells
    /// on either side, so a dent moves the surface at most about 3 spacings behind the contact: 0.15 m keeps
    /// a frontal crush off the roof and the rear of a car (an 8 x 8 x 8 lattice on a 4.4 m car has 0.63 m
    /// and moved the roof by half the crush). Finer costs controls, not dent time: the direct-manipulation
    /// solve scales with the points of a dent and the vertices it reaches, not with the lattice.
    double mFittedControlSpacing = 0.15;
    /// With mFittedControlCount all 0, the fitted zone's spacing is mFittedControlSpacing or finer: as fine
    /// as the material's occupant cell needs on this body (OccupantCellMaxSpacing of its length across
    /// mUpAxis, MeasureBodyLength: a quarter of a crush zone, finer than 0.15 m for a Campbell material on a
    /// body shorter than 2.4 m at the default crush-zone fraction of 0.25), so that a crush of one end cannot
    /// move the whole body. False: mFittedControlSpacing as given. Materials without a cell (the impulse
    /// factor, a crush zone of half the body or more) take mFittedControlSpacing either way.
    bool mFitSpacingToOccupantCell = true;
    double mFittedMaxTotalDeformation = 1.5;          ///< Max total deformation of the fitted zone (m)
    bool mInterpolateWideImpacts = true; ///< Fill gaps between contacts wider than the lattice spacing
    /// The body's up direction (body frame, unit): the Campbell crush measures its width across it
    Vec3 mUpAxis = Vec3::UnitZ();
    /// The body's forward direction (body frame, unit, across mUpAxis): tells a hit from behind from a
    /// frontal one, for a material with the rear's own stiffness (DamageMaterial::mHasRearStiffness; checked
    /// only then)
    Vec3 mForwardAxis = Vec3::UnitX();
};

/// Controls per axis for a lattice of inSize (m) with at most inSpacing (m) between controls: ceil(size /
/// spacing) cells plus 3, clamped to [4, FfdLatticeSettings::cMaxControlsPerAxis].
CRUMPLE_API std::array<int, 3> ControlCountForSpacing(const Vec3& inSize, double inSpacing);

/// An axis-aligned zone (body frame) enclosing inMesh with a margin of 1 % of its size plus 1 mm.
/// @param[in] inControlCount controls per axis, each >= 4; all 0: from inSpacing
CRUMPLE_API ffd::FfdZoneSettings FitZoneToMesh(const ffd::TriangleMesh& inMesh, const std::array<int, 3>& inControlCount,
                                   double inMaxTotalDeformation, double inSpacing = 0.15);

} // namespace crumple::plugin
