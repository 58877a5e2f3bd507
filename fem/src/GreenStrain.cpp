// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/GreenStrain.h>

namespace crumple::fem
{

Mat3 GreenStrain(const Mat3& inF)
{
    return 0.5 * (inF.transpose() * inF - Mat3::Identity());
}

} // namespace crumple::fem
