// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "BrittleMaterial.h"

namespace crumple::common
{

fem::FemMaterialSettings BrittleMaterial(fem::EFractureMode inMode)
{
    fem::FemMaterialSettings material;
    material.mYoungsModulus = cBrittleYoung;
    material.mPoissonRatio = cBrittlePoisson;
    material.mDensity = 2000.0;
    material.mTensileStrength = cBrittleStrength;
    material.mFractureMode = inMode;
    return material;
}

fem::FemMaterialSettings StiffBrittleMaterial()
{
    fem::FemMaterialSettings material = BrittleMaterial(fem::EFractureMode::CrackPlane);
    material.mYoungsModulus = 1.0e10;
    material.mPoissonRatio = 0.2;
    return material;
}

} // namespace crumple::common
