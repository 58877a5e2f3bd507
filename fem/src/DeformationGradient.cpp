// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/DeformationGradient.h>
#include <crumple/fem/EdgeMatrix.h>

namespace crumple::fem
{

Mat3 DeformationGradient(const Vec3& inX0, const Vec3& inX1, const Vec3& inX2, const Vec3& inX3,
                         const Mat3& inRestEdgeInverse)
{
    // F maps rest edges to current edges: D_s = F D_m.
    return EdgeMatrix(inX0, inX1, inX2, inX3) * inRestEdgeInverse;
}

} // namespace crumple::fem
