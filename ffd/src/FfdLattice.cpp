// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/ffd/CubicBSplineWeights.h>
#include <crumple/base/Assert.h>
#include <crumple/ffd/FfdLattice.h>

#include "TensorProductSum.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace crumple::ffd
{

namespace
{

std::string AxisName(int inAxis)
{
    return std::string(1, static_cast<char>('x' + inAxis));
}

} // namespace

Result<FfdLattice> FfdLattice::Create(const FfdLatticeSettings& inSettings)
{
    // Refuse anything that would make a lattice coordinate non-finite or a control index wrong.
    if (!IsFinite(inSettings.mOrigin) || !IsFinite(inSettings.mSize) || !IsFinite(inSettings.mAxes))
        return MakeError(EError::NonFinite, "FfdLatticeSettings: origin, axes and size must be finite");
    if (!(inSettings.mOrigin.cwiseAbs().maxCoeff() <= FfdLatticeSettings::cMaxExtent) ||
        !(inSettings.mSize.maxCoeff() <= FfdLatticeSettings::cMaxExtent))
        return MakeError(EError::OutOfRange, "FfdLatticeSettings: origin coordinates and size must be within 1e7 m");
    if (!IsRotation(inSettings.mAxes, 1.0e-6))
        return MakeError(EError::DegenerateGeometry,
                         "FfdLatticeSettings.mAxes must be orthonormal with determinant +1");
    for (int axis = 0; axis < 3; ++axis)
    {
        if (!(inSettings.mSize[axis] > 1.0e-9))
            return MakeError(EError::DegenerateGeometry, "FfdLatticeSettings.mSize." + AxisName(axis) + " = " +
                                                             std::to_string(inSettings.mSize[axis]) +
                                                             " m: the volume must have a positive size");
        const int n = inSettings.mControlCount[axis];
        if (n < FfdLatticeSettings::cMinControlsPerAxis || n > FfdLatticeSettings::cMaxControlsPerAxis)
            return MakeError(EError::InvalidArgument, "FfdLatticeSettings.mControlCount." + AxisName(axis) + " = " +
                                                          std::to_string(n) + ": a cubic lattice needs 4 to 256 "
                                                                              "controls per axis");
    }
    return FfdLattice(inSettings);
}

FfdLattice::FfdLattice(const FfdLatticeSettings& inSettings) : mSettings(inSettings)
{
    for (int axis = 0; axis < 3; ++axis)
    {
        mCellCount[axis] = inSettings.mControlCount[axis] - 3;
        mSpacing[axis] = inSettings.mSize[axis] / mCellCount[axis];
    }
    const std::size_t count = static_cast<std::size_t>(inSettings.mControlCount[0]) * inSettings.mControlCount[1] *
                              inSettings.mControlCount[2];
    mControlDisplacements.assign(count, Vec3::Zero());
    mWideSum = HasWideTensorProductSum();
}

Vec3 FfdLattice::LatticeCoordinate(const Vec3& inBodyPoint) const
{
    return (mSettings.mAxes.transpose() * (inBodyPoint - mSettings.mOrigin)).cwiseQuotient(mSpacing);
}

bool FfdLattice::Contains(const Vec3& inU, double inMargin) const
{
    for (int axis = 0; axis < 3; ++axis)
        if (!(inU[axis] >= -inMargin && inU[axis] <= mCellCount[axis] + inMargin))
            return false;
    return true;
}

LatticeLocation FfdLattice::Locate(const Vec3& inU) const
{
    LatticeLocation location;
    for (int axis = 0; axis < 3; ++axis)
    {
        // Clamp onto the box; u == n-3 belongs to the last cell with t = 1.
        // A NaN coordinate (an inverse mapping through an overflowed field) is taken as 0 rather than cast
        // to int: the location stays inside the lattice.
        const double u = std::isnan(inU[axis]) ? 0.0 : std::clamp(inU[axis], 0.0, static_cast<double>(mCellCount[axis]));
        const int cell = std::min(static_cast<int>(std::floor(u)), mCellCount[axis] - 1);
        location.mCell[axis] = cell;
        location.mT[axis] = u - cell;
    }
    return location;
}

double FfdLattice::DistanceToBox(const Vec3& inBodyPoint) const
{
    const Vec3 local = mSettings.mAxes.transpose() * (inBodyPoint - mSettings.mOrigin);
    const Vec3 outside = (-local).cwiseMax(local - mSettings.mSize).cwiseMax(Vec3::Zero());
    return outside.norm();
}

Vec3 FfdLattice::RestControlPosition(int inA, int inB, int inC) const
{
    // Controls sit one spacing before the box: control a of cell i is at (i + a - 1) * spacing.
    const Vec3 lattice_offset((inA - 1) * mSpacing.x(), (inB - 1) * mSpacing.y(), (inC - 1) * mSpacing.z());
    return mSettings.mOrigin + mSettings.mAxes * lattice_offset;
}

Vec3 FfdLattice::Displacement(const LatticeLocation& inLocation, std::span<const Vec3> inControls) const
{
    const int nx = mSettings.mControlCount[0];
    const int nxy = nx * mSettings.mControlCount[1];
    const int base = ControlIndex(inLocation.mCell[0], inLocation.mCell[1], inLocation.mCell[2]);
    CRUMPLE_ASSERT(inControls.size() == static_cast<std::size_t>(GetControlCount()) && inLocation.mCell[0] >= 0 &&
                       inLocation.mCell[1] >= 0 && inLocation.mCell[2] >= 0 && inLocation.mCell[0] < mCellCount[0] &&
                       inLocation.mCell[1] < mCellCount[1] && inLocation.mCell[2] < mCellCount[2],
                   "FfdLattice::Displacement: a location outside the lattice or controls of another lattice");

    // intent: the wide sum reads one double past the cell's last control, so not in the lattice's last cell
    const CellWeights weights = CellWeightsAt(inLocation.mT);
    const Vec3* first = &inControls[static_cast<std::size_t>(base)];
    const auto last = static_cast<std::size_t>(base + 3 * nxy + 3 * nx + 3);
    if (mWideSum && last + 1 < inControls.size())
        return WideTensorProductSum(first, nx, nxy, weights);
    return TensorProductSum(first, nx, nxy, weights);
}

} // namespace crumple::ffd
