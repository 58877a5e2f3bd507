// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/IsotropicMaterialMatrix.h>

namespace crumple::fem
{

Matrix6 IsotropicMaterialMatrix(double inYoungsModulus, double inPoissonRatio)
{
    // Normal block (1 - nu on the diagonal, nu off it), shear block (1 - 2 nu) / 2, common factor E /
    // ((1+nu)(1-2nu)).
    const double nu = inPoissonRatio;
    const double scale = inYoungsModulus / ((1.0 + nu) * (1.0 - 2.0 * nu));
    Matrix6 c = Matrix6::Zero();
    for (int i = 0; i < 3; ++i)
    {
        for (int j = 0; j < 3; ++j)
            c(i, j) = scale * (i == j ? 1.0 - nu : nu);
        c(i + 3, i + 3) = scale * 0.5 * (1.0 - 2.0 * nu);
    }
    return c;
}

} // namespace crumple::fem
