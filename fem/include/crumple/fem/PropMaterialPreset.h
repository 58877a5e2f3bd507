// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Result.h>
#include <crumple/fem/EPropMaterial.h>
#include <crumple/fem/FemMaterialSettings.h>
#include <crumple/fem/ProceduralEdgeSettings.h>

namespace crumple::fem
{

/// A prop material: the physical constants for the FEM solver and the parameters of its procedural broken
/// edges. Both pass their validation (FemMaterial::Create, ValidateProceduralEdgeSettings).
struct CRUMPLE_API PropMaterialPreset
{
    FemMaterialSettings mMaterial; ///< Elasticity, density, damping, plasticity and fracture
    ProceduralEdgeSettings mEdges; ///< Display sections and their edges (seed 0; set your own per prop)
};

/// The preset for inMaterial, from typical handbook values (room temperature, isotropic simplification):
///  - Glass, soda-lime float glass (EN 572-1): E 70 GPa, nu 0.22, 2500 kg/m^3; practical tensile strength
///    of annealed panes 30-70 MPa (surface flaws), taken as 50 MPa; no plasticity; DetachGroup (brittle,
///    cube-sized shards). Edges: square-ish 0.2 m sections, few edge vertices (5 /m, +-1 cm).
///  - Wood, spruce / pine along the grain (EN 338 C24 class: E_0,mean 11 GPa; clear wood tensile strength
///    parallel to the grain 40-90 MPa), simplified to isotropic: E 10 GPa, nu 0.3, 500 kg/m^3, tensile
///    40 MPa, no plasticity, CrackPlane. Edges: long thin planks 0.6 x 0.1 m, 40 vertices /m at +-2.4 cm on
///    horizontal edges (splinters along the grain; the most ProceduralEdgeMesh accepts when sections shrink
///    to 2/3 of 0.1 m), none on vertical ones.
///  - Brick, clay-brick masonry in cement-lime mortar: E 12 GPa (Eurocode 6 suggests 1000 f_k, 5-15 GPa),
///    nu 0.2, 1900 kg/m^3; tensile strength governed by the mortar bond, 0.1-2 MPa, taken as 1.5 MPa;
///    no plasticity; DetachGroup (whole bricks come out). Edges: UK brick faces 0.215 x 0.065 m, straight
///    (no jitter, no edge vertices).
///  - Rubber, soft natural rubber: E 5 MPa, nu 0.49 (nearly incompressible; the solver caps nu at 0.495),
///    1100 kg/m^3, tensile strength 25 MPa (at several hundred percent strain: a linear model hardly
///    reaches it), no plasticity, CrackPlane. Edges: large 0.5 m sections, 2 vertices /m at +-1 cm.
///  - Steel, structural S235 (EN 10025-2): E 210 GPa, nu 0.3, 7850 kg/m^3, yield 235 MPa with
///    instantaneous flow, plastic strain cap 0.25 (elongation at break >= 26 %), tensile strength 360 MPa,
///    CrackPlane. Edges: large 0.5 m sections, 2 vertices /m at +-5 mm.
/// Damping so that props come to rest: Rayleigh mass damping alpha = 0.2 1/s (1 for rubber), a drag that
/// caps free fall at g / alpha = 49 m/s, and stiffness damping beta ~ 0.01 m / c (c the P-wave speed:
/// 2e-6 s for glass, wood and steel, 4e-6 s brick, 4e-5 s rubber), which gives the fastest mode of 0.1 m
/// elements (omega ~ 2 c / 0.1 m) a damping ratio of about 0.1 and leaves slow modes nearly undamped.
/// Refused: a value that is not an EPropMaterial.
CRUMPLE_API Result<PropMaterialPreset> MakePropMaterialPreset(EPropMaterial inMaterial);

} // namespace crumple::fem
