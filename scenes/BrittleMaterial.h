// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/fem/FemMaterialSettings.h>

namespace crumple::common
{

constexpr double cBrittleStrength = 1.0e6; ///< Tensile strength of the fracture tests' material (Pa)
constexpr double cBrittleYoung = 1.0e9;    ///< Its Young's modulus (Pa)
constexpr double cBrittlePoisson = 0.25;   ///< Its Poisson ratio

/// The brittle material the CPU and GPU fracture tests share: E = 1 GPa, nu = 0.25, rho = 2000 kg/m^3,
/// tensile strength 1 MPa, the given fracture mode.
fem::FemMaterialSettings BrittleMaterial(fem::EFractureMode inMode);

/// The stiff brittle walls' material (the fracture, factored-solve, stress and GPU tests): BrittleMaterial
/// with CrackPlane, E = 10 GPa and nu = 0.2.
fem::FemMaterialSettings StiffBrittleMaterial();

} // namespace crumple::common
