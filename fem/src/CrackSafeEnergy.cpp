// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/CrackSafeEnergy.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace crumple::fem
{

double CrackSafeEnergy(const FemMaterialSettings& inMaterial, double inSmallestGroupVolume,
                       double inStressFraction)
{
    const double strength = inMaterial.mTensileStrength;
    if (!std::isfinite(strength) || !std::isfinite(inStressFraction))
        return std::numeric_limits<double>::infinity();
    const double nu = inMaterial.mPoissonRatio;
    const double kappa = (1.0 + nu) * (1.0 - 2.0 * nu) / (1.0 - nu);
    const double stress = inStressFraction * strength;
    return stress * stress * kappa * inSmallestGroupVolume / (2.0 * inMaterial.mYoungsModulus);
}

double SmallestGroupVolume(const FractureLinks& inLinks, const TetMesh& inMesh)
{
    double smallest = std::numeric_limits<double>::infinity();
    for (int group = 0; group < inLinks.GetGroupCount(); ++group)
    {
        // intent: the group's elements in element order, as GroupPrincipalStress sums them
        double volume = 0.0;
        for (int entry = inLinks.mGroupElementOffsets[group]; entry < inLinks.mGroupElementOffsets[group + 1];
             ++entry)
            volume += inMesh.GetRestVolume(inLinks.mGroupElements[entry]);
        smallest = std::min(smallest, volume);
    }
    return smallest;
}

} // namespace crumple::fem
