// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/ffd/CubicBSplineWeights.h>

namespace crumple::ffd
{

std::array<double, 4> CubicBSplineWeights(double inT)
{
    // Horner forms of the four cubic pieces; written out so that the operation order is fixed.
    const double t = inT;
    const double t2 = t * t;
    const double t3 = t2 * t;
    const double s = 1.0 - t;
    constexpr double cSixth = 1.0 / 6.0;
    return {s * s * s * cSixth, (3.0 * t3 - 6.0 * t2 + 4.0) * cSixth, (-3.0 * t3 + 3.0 * t2 + 3.0 * t + 1.0) * cSixth,
            t3 * cSixth};
}

} // namespace crumple::ffd
