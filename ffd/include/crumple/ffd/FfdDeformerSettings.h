// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/ffd/DirectManipulation.h>
#include <crumple/ffd/FfdLatticeSettings.h>

#include <cstdint>
#include <vector>

namespace crumple::ffd
{

/// One deformation zone: a lattice and the most its points may ever move.
struct CRUMPLE_API FfdZoneSettings
{
    FfdLatticeSettings mLattice;        ///< The zone's volume and control resolution
    double mMaxTotalDeformation = 0.25; ///< Bound on the total displacement of any vertex of the zone (m), >= 0.
                                        ///< A dent that would push a vertex past it is scaled down as a whole
                                        ///< (its shape kept) until the vertex sits on the bound.
};

/// Settings of an FfdDeformer: the zones of one object and the solver's tolerances.
struct CRUMPLE_API FfdDeformerSettings
{
    std::vector<FfdZoneSettings> mZones; ///< One or more zones; a vertex belongs to the first zone containing it
    double mRankTolerance = cDefaultRankTolerance; ///< Relative pivot threshold of B^+ (see DirectManipulation.h)
    double mMergeDistance = 0.1;   ///< Constrained points of one dent closer than this, in lattice cells (max norm),
                                   ///< are merged and their displacements averaged: a cubic B-spline cannot bend
                                   ///< between them, and keeping both would only make B ill-conditioned
    double mCaptureDistance = 0.5; ///< A constrained point outside every zone but within this many cells of one
                                   ///< is moved onto its box; points further out are ignored (and counted)
    int mInverseIterations = 3;    ///< Fixed-point iterations mapping a deformed point back to its rest lattice
                                   ///< coordinate, so that repeated dents compose exactly where they are aimed
    double mMinControlSpacing = 0.2; ///< Fold guard (see FoldGuard.h): the smallest distance, as a fraction of
                                     ///< the lattice spacing along that axis, that two neighbouring controls
                                     ///< of a lattice line may come to along the line's axis, measured in the
                                     ///< lattice frame (axes^T times the deformed control positions). A control
                                     ///< pushed closer pushes its neighbour along, so the spline stays monotone
                                     ///< and the surface cannot fold. In [0, 1); 0 disables the guard
    /// What a dent's control displacements stay nearest to (see EDirectManipulationPrior): the quasi-interpolant
    /// by default, so that a uniform push moves the surface uniformly with no control overshoot; None gives
    /// D4MD's pure minimum-norm solve.
    EDirectManipulationPrior mPrior = EDirectManipulationPrior::QuasiInterpolant;
    /// Bound on a dent's largest control change over its largest wanted displacement (see
    /// DirectManipulationSolve): past it the solve drops weak directions of B instead of letting controls
    /// run metres away to meet targets that disagree between neighbouring points. >= 1, or infinity to
    /// disable. 3 admits every single isolated point, which the minimum-norm solve meets with a control of
    /// (4/6)^3 / (1/2)^3 = 2.37 times its displacement (a point at a knot), and so never fires on
    /// consistent targets (a flat push needs 1 with the quasi-interpolant prior). Measured on the FEM
    /// brick barrier's first dent (0.14 m lattice, merged targets up to 2.5 cm that disagree between
    /// neighbours): controls of 10.9 m at tau = 1e-3 become 7.3 cm at tau = 0.1, rank 124 of 206.
    double mMaxControlGain = 3.0;
    /// One-sided dents (see OneSidedControls): when a dent's wanted displacements all push one way, no
    /// control moves against that way, so no vertex does: a crush never bulges the surface out beside the
    /// pushed patch. False commits the solve's controls as they are (a general FFD edit).
    bool mOneSidedDents = true;
    /// Parts that keep their shape (wheels, tyres, rims; the game's choice): each a list of vertex indices
    /// of the rest mesh, no vertex in two parts. A part is not dented: all of its vertices move by the
    /// lattice's displacement at the centre of the part's rest bounding box, so it translates with the body
    /// around it (a wheel pushed back by a crush stays round; it does not turn). A part whose centre lies in no
    /// zone does not move. Empty (the default): every vertex follows the lattice where it is.
    std::vector<std::vector<std::uint32_t>> mRigidParts;
};

} // namespace crumple::ffd
