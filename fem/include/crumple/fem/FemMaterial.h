// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Result.h>
#include <crumple/fem/FemMaterialSettings.h>
#include <crumple/fem/IsotropicMaterialMatrix.h>

namespace crumple::fem
{

/// A validated FemMaterialSettings with the quantities derived from it: the 6x6 material matrix and the Lame
/// parameters. Immutable once created.
class CRUMPLE_API FemMaterial
{
public:
    /// Refuses non-finite values, E <= 0, density <= 0, nu outside (-1, cMaxPoissonRatio], negative damping,
    /// an unknown model or fracture mode, a yield stress, creep rate or tensile strength <= 0 (infinity is
    /// accepted: "off") or a negative or infinite plastic strain cap, naming the field and value.
    static Result<FemMaterial> Create(const FemMaterialSettings& inSettings);

    /// The settings it was created from
    const FemMaterialSettings& GetSettings() const { return mSettings; }
    /// The isotropic 6x6 material matrix C (Pa), Voigt order xx, yy, zz, xy, yz, zx, engineering shear
    const Matrix6& GetMaterialMatrix() const { return mMaterialMatrix; }
    /// First Lame parameter lambda = E nu / ((1 + nu)(1 - 2 nu)) (Pa)
    double GetLambda() const { return mLambda; }
    /// Shear modulus mu = G = E / (2 (1 + nu)) (Pa)
    double GetShearModulus() const { return mShearModulus; }
    /// Dilatational (P-wave) speed sqrt((lambda + 2 mu) / rho) (m/s), the fastest wave in the material
    double GetWaveSpeed() const;
    /// True when the yield stress is finite: elements accumulate plastic strain
    bool IsPlastic() const;
    /// True when the tensile strength is finite: element groups can detach
    bool IsBreakable() const;

private:
    explicit FemMaterial(const FemMaterialSettings& inSettings);

    FemMaterialSettings mSettings;
    Matrix6 mMaterialMatrix = Matrix6::Zero();
    double mLambda = 0.0;
    double mShearModulus = 0.0;
};

} // namespace crumple::fem
