// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/TetNodalForces.h>

namespace crumple::fem
{

std::array<Vec3, 4> TetNodalForces(const Mat3& inFirstPiolaStress, const Mat3& inRestEdgeInverse,
                                   double inRestVolume)
{
    // f_i = -dW/dx_i with W = V0 psi(F); x_i (i = 1..3) enters F through row i of D_m^-1, so dW/dx_i is
    // column i of V0 P D_m^-T, and x_0 enters with minus their sum.
    const Mat3 h = -inRestVolume * (inFirstPiolaStress * inRestEdgeInverse.transpose());
    const Vec3 f1 = h.col(0);
    const Vec3 f2 = h.col(1);
    const Vec3 f3 = h.col(2);
    return {-(f1 + f2 + f3), f1, f2, f3};
}

} // namespace crumple::fem
