// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Result.h>
#include <crumple/ffd/FfdLatticeSettings.h>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace crumple::ffd
{

/// Where a point sits in a lattice: its cell and the local parameter inside it.
struct CRUMPLE_API LatticeLocation
{
    std::array<int, 3> mCell{{0, 0, 0}}; ///< Cell index per axis, in [0, n - 4]; controls mCell..mCell+3 reach it
    Vec3 mT = Vec3::Zero();              ///< Local parameter per axis, in [0, 1]
};

/// A uniform cubic B-spline free-form deformation lattice (Sederberg & Parry 1986; the D4MD variant without
/// phantom controls). It stores only control *displacements*: a point's displacement is
/// sum_{a,b,c} w_a(t_x) w_b(t_y) w_c(t_z) dC(i+a, j+b, k+c), so an undeformed lattice moves no point by even
/// one ulp, and the rest shape is never lost.
class CRUMPLE_API FfdLattice
{
public:
    /// Validates the settings (finite, positive size, rotation axes, >= 4 controls) and builds a lattice
    /// with zero displacements.
    static Result<FfdLattice> Create(const FfdLatticeSettings& inSettings);

    const FfdLatticeSettings& GetSettings() const { return mSettings; }
    /// Spline segments (cells) per axis: n - 3
    const std::array<int, 3>& GetCellCount() const { return mCellCount; }
    /// Control spacing per axis (m)
    const Vec3& GetSpacing() const { return mSpacing; }
    int GetControlCount() const { return static_cast<int>(mControlDisplacements.size()); }
    int GetCellTotal() const { return mCellCount[0] * mCellCount[1] * mCellCount[2]; }

    /// Lattice coordinate u of a body-frame point: u = axes^T (p - origin) / spacing, in [0, n-3] inside the box.
    Vec3 LatticeCoordinate(const Vec3& inBodyPoint) const;
    /// True when a lattice coordinate lies in the box, widened by inMargin cells on every side.
    bool Contains(const Vec3& inLatticeCoordinate, double inMargin = 0.0) const;
    /// Cell and local parameter of a lattice coordinate; coordinates outside the box are clamped onto it.
    LatticeLocation Locate(const Vec3& inLatticeCoordinate) const;
    /// Distance (m) from a body-frame point to the box, 0 inside.
    double DistanceToBox(const Vec3& inBodyPoint) const;

    /// Linear index of control (a, b, c): a + n_x (b + n_y c).
    int ControlIndex(int inA, int inB, int inC) const
    {
        return inA + mSettings.mControlCount[0] * (inB + mSettings.mControlCount[1] * inC);
    }
    /// Linear index of cell (i, j, k).
    int CellIndex(const std::array<int, 3>& inCell) const
    {
        return inCell[0] + mCellCount[0] * (inCell[1] + mCellCount[1] * inCell[2]);
    }
    /// Undeformed position of control (a, b, c), body frame (m).
    Vec3 RestControlPosition(int inA, int inB, int inC) const;

    /// Displacement (m, body frame) of a point at inLocation: the tensor-product sum over its 64 controls, in a
    /// fixed order, bitwise the same on every x86-64 processor (with AVX or without).
    Vec3 Displacement(const LatticeLocation& inLocation) const { return Displacement(inLocation, mControlDisplacements); }
    /// The same sum over another set of control displacements (#controls, ControlIndex order). Preconditions
    /// (checked by assertion only: it runs per vertex): inControls holds GetControlCount() entries and
    /// inLocation comes from Locate() of this lattice.
    Vec3 Displacement(const LatticeLocation& inLocation, std::span<const Vec3> inControls) const;

    /// Control displacements, body frame (m), indexed by ControlIndex.
    const std::vector<Vec3>& GetControlDisplacements() const { return mControlDisplacements; }
    std::vector<Vec3>& GetControlDisplacements() { return mControlDisplacements; }

private:
    explicit FfdLattice(const FfdLatticeSettings& inSettings);

    FfdLatticeSettings mSettings;
    std::array<int, 3> mCellCount{};
    Vec3 mSpacing = Vec3::Ones();
    std::vector<Vec3> mControlDisplacements;
    bool mWideSum = false; ///< Displacement takes the AVX sum (same bits, about twice as fast) where it runs
};

} // namespace crumple::ffd
