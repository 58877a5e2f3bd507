// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/MaterialStress.h>

namespace crumple::fem
{

Mat3 MaterialStress(const Matrix6& inMaterialMatrix, const Mat3& inStrain)
{
    // Voigt strain with engineering shear from the symmetric part of the tensor.
    Vector6 strain;
    strain << inStrain(0, 0), inStrain(1, 1), inStrain(2, 2), inStrain(0, 1) + inStrain(1, 0),
        inStrain(1, 2) + inStrain(2, 1), inStrain(2, 0) + inStrain(0, 2);
    const Vector6 stress = inMaterialMatrix * strain;

    // Back to a symmetric tensor.
    Mat3 sigma;
    sigma << stress[0], stress[3], stress[5], //
        stress[3], stress[1], stress[4],      //
        stress[5], stress[4], stress[2];
    return sigma;
}

} // namespace crumple::fem
