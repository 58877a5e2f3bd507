// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Result.h>
#include <crumple/fem/HexMaterialSettings.h>

#include <Eigen/Core>

namespace crumple::fem
{

/// 6 by 6 isotropic elasticity matrix in Voigt order (xx, yy, zz, xy, yz, zx), engineering shear strains
/// (gamma = 2 epsilon): sigma = D epsilon, entries in Pa.
using HexElasticityMatrix = Eigen::Matrix<double, 6, 6>;

/// A validated isotropic linear-elastic material with its elasticity matrix.
class CRUMPLE_API HexMaterial
{
public:
    /// Validates the settings: E finite and > 0 (NonFinite / InvalidArgument), nu finite and in (-1, 0.5)
    /// (nu = 0.5 is incompressible and makes D infinite; nu <= -1 makes it indefinite).
    static Result<HexMaterial> Create(const HexMaterialSettings& inSettings);

    /// The settings it was created from
    const HexMaterialSettings& GetSettings() const { return mSettings; }
    /// D (Pa), 6 by 6, Voigt order (xx, yy, zz, xy, yz, zx) with engineering shear strains
    const HexElasticityMatrix& GetElasticity() const { return mElasticity; }
    /// Shear modulus G = E / (2 (1 + nu)) (Pa)
    double GetShearModulus() const;

private:
    explicit HexMaterial(const HexMaterialSettings& inSettings);

    HexMaterialSettings mSettings;
    HexElasticityMatrix mElasticity;
};

} // namespace crumple::fem
