// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

// Private: the trilinear shape functions shared by the mesh check and the element stiffness.

#include <crumple/fem/HexMesh.h>

#include <Eigen/Core>
#include <Eigen/LU>

#include <algorithm>
#include <array>
#include <cmath>

namespace crumple::fem
{

/// Natural coordinates (xi, eta, zeta) of the 8 corners, in HexMesh corner order.
inline constexpr std::array<std::array<double, 3>, 8> cHexCornerSigns{{{{-1.0, -1.0, -1.0}},
                                                                       {{1.0, -1.0, -1.0}},
                                                                       {{1.0, 1.0, -1.0}},
                                                                       {{-1.0, 1.0, -1.0}},
                                                                       {{-1.0, -1.0, 1.0}},
                                                                       {{1.0, -1.0, 1.0}},
                                                                       {{1.0, 1.0, 1.0}},
                                                                       {{-1.0, 1.0, 1.0}}}};

/// The 12 edges as corner pairs.
inline constexpr std::array<std::array<int, 2>, 12> cHexEdges{{{{0, 1}},
                                                               {{1, 2}},
                                                               {{2, 3}},
                                                               {{3, 0}},
                                                               {{4, 5}},
                                                               {{5, 6}},
                                                               {{6, 7}},
                                                               {{7, 4}},
                                                               {{0, 4}},
                                                               {{1, 5}},
                                                               {{2, 6}},
                                                               {{3, 7}}}};

/// 2-point Gauss-Legendre abscissa 1/sqrt(3); the weights are 1.
inline constexpr double cHexGaussAbscissa = 0.57735026918962576450914878050196;

/// Natural coordinates of Gauss point inPoint (0..7), ordered like the corners.
inline Eigen::Vector3d HexGaussPoint(int inPoint)
{
    const std::array<double, 3>& s = cHexCornerSigns[inPoint];
    return Eigen::Vector3d(s[0], s[1], s[2]) * cHexGaussAbscissa;
}

/// Shape function gradients with respect to natural coordinates at inXi: 3 by 8, row i = d N_a / d xi_i.
/// N_a = (1 + xi xi_a)(1 + eta eta_a)(1 + zeta zeta_a) / 8.
inline Eigen::Matrix<double, 3, 8> HexNaturalGradient(const Eigen::Vector3d& inXi)
{
    Eigen::Matrix<double, 3, 8> gradient;
    for (int a = 0; a < 8; ++a)
    {
        const std::array<double, 3>& s = cHexCornerSigns[a];
        const double fx = 1.0 + inXi[0] * s[0];
        const double fy = 1.0 + inXi[1] * s[1];
        const double fz = 1.0 + inXi[2] * s[2];
        gradient(0, a) = 0.125 * s[0] * fy * fz;
        gradient(1, a) = 0.125 * fx * s[1] * fz;
        gradient(2, a) = 0.125 * fx * fy * s[2];
    }
    return gradient;
}

/// Jacobian J = dN/dxi * X: J(i, j) = d x_j / d xi_i (3 by 3), so that dN/dx = J^-1 dN/dxi.
inline Eigen::Matrix3d HexJacobian(const Eigen::Matrix<double, 3, 8>& inNaturalGradient, const HexCornerMatrix& inCorners)
{
    return inNaturalGradient * inCorners;
}

/// Smallest Jacobian determinant over the 8 Gauss points and the centre, divided by (longest edge / 2)^3:
/// 1 for a cube, <= 0 for an inverted element, NaN for non-finite corners.
inline double HexJacobianQuality(const HexCornerMatrix& inCorners)
{
    double longest = 0.0;
    for (const std::array<int, 2>& edge : cHexEdges)
        longest = std::max(longest, (inCorners.row(edge[0]) - inCorners.row(edge[1])).norm());
    const double half = 0.5 * longest;
    const double scale = half * half * half;
    if (!(scale > 0.0))
        return 0.0;
    double smallest = HexJacobian(HexNaturalGradient(Eigen::Vector3d::Zero()), inCorners).determinant();
    for (int g = 0; g < 8; ++g)
        smallest = std::min(smallest, HexJacobian(HexNaturalGradient(HexGaussPoint(g)), inCorners).determinant());
    return smallest / scale;
}

} // namespace crumple::fem
