// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/EdgeMatrix.h>

namespace crumple::fem
{

Mat3 EdgeMatrix(const Vec3& inP0, const Vec3& inP1, const Vec3& inP2, const Vec3& inP3)
{
    Mat3 edges;
    edges.col(0) = inP1 - inP0;
    edges.col(1) = inP2 - inP0;
    edges.col(2) = inP3 - inP0;
    return edges;
}

} // namespace crumple::fem
