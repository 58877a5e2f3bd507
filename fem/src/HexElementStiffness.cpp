// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "HexFormat.h"
#include "HexShape.h"

#include <crumple/base/Math.h>
#include <crumple/fem/HexElementStiffness.h>

#include <Eigen/Cholesky>

namespace crumple::fem
{

namespace
{

// Strain-displacement rows of one vector field with scalar gradient inGradient (d/dx, d/dy, d/dz), written into
// columns inColumn .. inColumn + 2 of ioB (Voigt order xx, yy, zz, xy, yz, zx; engineering shear).
template <int Columns>
void WriteStrainColumns(const Eigen::Vector3d& inGradient, int inColumn, Eigen::Matrix<double, 6, Columns>& ioB)
{
    const double dx = inGradient[0];
    const double dy = inGradient[1];
    const double dz = inGradient[2];
    ioB.template block<6, 3>(0, inColumn) << dx, 0.0, 0.0, //
        0.0, dy, 0.0,                                      //
        0.0, 0.0, dz,                                      //
        dy, dx, 0.0,                                       //
        0.0, dz, dy,                                       //
        dz, 0.0, dx;
}

} // namespace

// Derivation. With J(i, j) = d x_j / d xi_i the corner-shape gradients are dN/dx = J^-1 dN/dxi, the strain is
// B_u u, and K_uu = sum_g B_u^T D B_u det J_g (all 2-point Gauss weights are 1).
// Incompatible modes (Taylor, Beresford & Wilson 1976): displacements gain sum_k P_k alpha_k with
// P_k = 1 - xi_k^2 and 3 components per mode (9 internal dofs alpha). Their gradients are taken through the
// centre Jacobian and scaled, dP/dx = (det J0 / det J) J0^-1 dP/dxi, so that integral(B_a) dV =
// det J0 J0^-1 integral(dP/dxi) dxi = 0: a constant stress does no work on alpha and the patch test holds
// for any parallelepiped-or-not element. Static condensation of the element equations
// [K_uu K_ua; K_au K_aa] [u; alpha] = [f; 0] gives K = K_uu - K_ua K_aa^-1 K_au. A rigid motion has B_u u = 0,
// hence K_au u = 0 and K u = 0: the 6 rigid modes stay the null space.
Result<HexElementStiffnessMatrix> HexElementStiffness(const HexCornerMatrix& inCorners, const HexMaterial& inMaterial)
{
    // Refuse corners whose Jacobian would be singular or negative somewhere in the element.
    if (!IsFinite(inCorners))
        return MakeError(EError::NonFinite, "HexElementStiffness: a corner position is NaN or infinite");
    const double quality = HexJacobianQuality(inCorners);
    if (!(quality >= cHexMinJacobianRatio))
        return MakeError(EError::DegenerateGeometry, "HexElementStiffness: the element is inverted, flat or twisted "
                                                     "(Jacobian ratio " +
                                                         HexFormat(quality) + "); check the corner order");

    const HexElasticityMatrix& d = inMaterial.GetElasticity();
    const bool incompatible = inMaterial.GetSettings().mFormulation == EHexFormulation::IncompatibleModes;

    // Centre Jacobian for the incompatible-mode gradients.
    const Eigen::Matrix3d j0 = HexJacobian(HexNaturalGradient(Eigen::Vector3d::Zero()), inCorners);
    const double det_j0 = j0.determinant();
    const Eigen::Matrix3d j0_inverse = j0.inverse();

    // Quadrature of K_uu, K_ua and K_aa.
    HexElementStiffnessMatrix k_uu = HexElementStiffnessMatrix::Zero();
    Eigen::Matrix<double, 24, 9> k_ua = Eigen::Matrix<double, 24, 9>::Zero();
    Eigen::Matrix<double, 9, 9> k_aa = Eigen::Matrix<double, 9, 9>::Zero();
    for (int g = 0; g < 8; ++g)
    {
        const Eigen::Vector3d xi = HexGaussPoint(g);
        const Eigen::Matrix<double, 3, 8> natural = HexNaturalGradient(xi);
        const Eigen::Matrix3d j = HexJacobian(natural, inCorners);
        const double det_j = j.determinant();
        const Eigen::Matrix<double, 3, 8> gradient = j.inverse() * natural;

        Eigen::Matrix<double, 6, 24> b_u;
        for (int c = 0; c < 8; ++c)
            WriteStrainColumns<24>(gradient.col(c), 3 * c, b_u);
        const Eigen::Matrix<double, 24, 6> bt_d = b_u.transpose() * d * det_j;
        k_uu += bt_d * b_u;

        if (incompatible)
        {
            // dP_k/dxi_i = -2 xi_k delta_ik, mapped through J0 and scaled by det J0 / det J.
            const Eigen::Matrix3d mode_natural = (-2.0 * xi).asDiagonal();
            const Eigen::Matrix3d mode_gradient = (det_j0 / det_j) * (j0_inverse * mode_natural);
            Eigen::Matrix<double, 6, 9> b_a;
            for (int k = 0; k < 3; ++k)
                WriteStrainColumns<9>(mode_gradient.col(k), 3 * k, b_a);
            k_ua += bt_d * b_a;
            k_aa += b_a.transpose() * d * b_a * det_j;
        }
    }

    // Condense the internal modes: K = K_uu - K_ua K_aa^-1 K_au (K_aa is SPD for a valid element).
    HexElementStiffnessMatrix k = k_uu;
    if (incompatible)
    {
        const Eigen::LLT<Eigen::Matrix<double, 9, 9>> k_aa_factor(0.5 * (k_aa + k_aa.transpose()));
        if (k_aa_factor.info() != Eigen::Success)
            return MakeError(EError::DegenerateGeometry,
                             "HexElementStiffness: the incompatible-mode block is not positive definite");
        k -= k_ua * k_aa_factor.solve(k_ua.transpose());
    }

    // Exact symmetry (the products above are symmetric only to rounding).
    const HexElementStiffnessMatrix symmetric = 0.5 * (k + k.transpose());
    return symmetric;
}

} // namespace crumple::fem
