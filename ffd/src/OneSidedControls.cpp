// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/ffd/OneSidedControls.h>

#include <cmath>

namespace crumple::ffd
{

int OneSidedControls(const Eigen::MatrixX3d& inWanted, Eigen::MatrixX3d& ioDelta)
{
    // The push direction: the mean wanted displacement.
    const Eigen::RowVector3d sum = inWanted.colwise().sum();
    const double length = sum.norm();
    if (!(length > 0.0) || !std::isfinite(length))
        return 0;
    const Eigen::RowVector3d push = sum / length;

    // One-sided only when no point is asked to move against it (round-off of a perpendicular push allowed).
    const double largest = inWanted.rowwise().norm().maxCoeff();
    if ((inWanted * push.transpose()).minCoeff() < -1.0e-12 * largest)
        return 0;

    // Remove each control's component against the push.
    int clipped = 0;
    for (Eigen::Index row = 0; row < ioDelta.rows(); ++row)
    {
        const double along = ioDelta.row(row).dot(push);
        if (along < 0.0)
        {
            ioDelta.row(row) -= along * push;
            ++clipped;
        }
    }
    return clipped;
}

} // namespace crumple::ffd
