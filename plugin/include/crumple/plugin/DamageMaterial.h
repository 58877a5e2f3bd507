// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Result.h>

#include <cstdint>

namespace crumple::plugin
{

/// How a collision's severity becomes crush depth.
enum class ECrushModel : std::uint8_t
{
    /// D4MD's: the depth is the deformation factor times the collision's impulse beyond a threshold, and the
    /// dent moves the contact points (direct manipulation). Cheap, engine-independent, blind to contact
    /// width: for games that tune dents by eye.
    ImpulseFactor = 0,
    /// Accident reconstruction's (Campbell, SAE 740565; CRASH3/WinSMASH): the energy the collision absorbed
    /// crushes the struck width w against a stiffness per unit width, E / w = A C + B C^2 / 2 + G, and the
    /// crushed region takes the impactor's shape (plugin::CampbellCrush). Narrow impacts (poles) crush
    /// deeper than wide ones of the same energy: for crash tests and believable racing damage.
    Campbell = 1,
};

/// How a deformable object turns impulse into dents (D4MD section 6.1: the "deformable object" properties).
/// Defaults: Campbell's crush law with the nominal mid-size car's stiffness, so a 1,575 kg car 1.65 m wide
/// hitting a rigid wall at 56 km/h crushes 0.55 m, on the line of shared/data/crash/campbell_oracle.csv and
/// inside its band (0.37-0.74 m). With ECrushModel::ImpulseFactor the factor 2e-5 m/(N s) crushes a 1,200 kg
/// car hitting a wall at 15 m/s (about 18 kN s) by 0.36 m.
struct CRUMPLE_API DamageMaterial
{
    double mDeformationFactor = 2.0e-5;   ///< Dent depth per unit impulse (m/(N s)), >= 0: depth = factor |J|,
                                          ///< like a spring turning force into displacement
    double mMinDeformation = 1.0e-3;      ///< Dents shallower than this are dropped (m), >= 0
    double mMaxInstantDeformation = 1.5;  ///< Deepest dent one collision can make at a contact (m), in [min, 1e6]: a
                                          ///< bound against runaway input, above the crush of a 64 km/h pole hit
    /// The part of a collision's impulse that leaves no permanent dent (N s), >= 0: the depth is
    /// factor (|J| - threshold) when |J| exceeds it. Campbell's linear crush model (SAE 740565) has a
    /// no-damage speed b0 (2.2-4.5 m/s for modern cars, SAE 2010-01-0069): against a rigid barrier that is
    /// an impulse of about (1 + e) m b0. 0 (the default): every impulse dents.
    double mImpulseThreshold = 0.0;

    ECrushModel mModel = ECrushModel::Campbell; ///< Which of the fields below turn a collision into crush

    // Campbell crush stiffness per unit width (ECrushModel::Campbell). Defaults: the nominal mid-size car
    // (1,450-1,700 kg, 1.65 m wide) of shared/data/crash/campbell_oracle.csv, whose line passes through
    // 0.556 m of residual crush at 56 km/h into a rigid barrier; samples/presets hold the other classes.
    double mCrushA = 50400.0;  ///< Force per unit width at the onset of crush (N/m), in [0, 1e12]
    double mCrushB = 549818.0; ///< Its growth per metre of crush (N/m^2), in (0, 1e12]
    double mCrushG = 2310.0;   ///< Energy per unit width absorbed with no residual crush (J/m), in [0, 1e12]; CRASH3
                               ///< takes A^2 / (2 B)
    /// The sides' own Campbell stiffness (CRASH3 keeps front, rear and side coefficients apart): when set,
    /// a crush across the body (its direction nearer the body's width than its length, BodyLength) takes
    /// mSideCrushA, B and G instead of mCrushA, B and G; the ends (front and rear) and a crush straight down
    /// keep those. Off by default, with no preset value: a side structure's stiffness varies widely from car
    /// to car and is not predicted by its class, size or mass (SAE 2017-01-1415 and 2020-01-0640 derive it
    /// per vehicle from its side crash tests), so it belongs to the vehicle's data, not to a class preset.
    bool mHasSideStiffness = false;
    double mSideCrushA = 0.0; ///< The sides' A (N/m), in [0, 1e12]; read only with mHasSideStiffness
    double mSideCrushB = 1.0; ///< The sides' B (N/m^2), in (0, 1e12]
    double mSideCrushG = 0.0; ///< The sides' G (J/m), in [0, 1e12]
    /// The rear's own Campbell stiffness: when set, a crush along the body that pushes it forward (a hit from
    /// behind: the crush direction within 90 degrees of DeformableObjectSettings::mForwardAxis) takes
    /// mRearCrushA, B and G; the front keeps mCrushA, B and G, and across the body the sides' take precedence
    /// (mHasSideStiffness). A car's rear structure is not its front (SAE 2010-01-0069 measured both on one
    /// model and found that CRASH3's default coefficients did not capture the difference). Off by default,
    /// with no preset value, as for the sides: the rear's coefficients belong to the vehicle's data.
    bool mHasRearStiffness = false;
    double mRearCrushA = 0.0; ///< The rear's A (N/m), in [0, 1e12]; read only with mHasRearStiffness
    double mRearCrushB = 1.0; ///< The rear's B (N/m^2), in (0, 1e12]
    double mRearCrushG = 0.0; ///< The rear's G (J/m), in [0, 1e12]
    /// Narrowest width a crush is spread over (m), > 0: a car's bumper beam and longitudinal rails carry
    /// a pole's load over more than the pole's diameter. An assumption to set per vehicle, not a measured value.
    double mMinCrushWidth = 0.5;
    /// What remains of a crushed length, in [0, 1): the crushed region is compacted to this fraction of its
    /// depth behind the impactor's final face (sheet-metal crush tubes fold to about a quarter of their length).
    double mCrushedLengthFraction = 0.25;
    /// Share of the body's length (its longest horizontal extent at rest) at each end that crushes, in
    /// (0, 0.5]; the occupant cell between the two ends is modelled rigid. A crush along the length (within
    /// 60 degrees of it) compacts its zone only up to a control spacing short of the cell; a crush that would
    /// reach further stacks up: the zone compacts past mCrushedLengthFraction, ever more slowly, towards half
    /// of it, so the cabin and its roof never move (CrushPlan). 0.25: the front and rear quarters of a car,
    /// bumper to windscreen base and boot (an assumption to set per vehicle, not a measured value); 0.5: no
    /// cell (every crush compacts as deep as Campbell's law asks). Sideways crushes are not limited, nor are
    /// crushes on a lattice whose spacing along the length exceeds a quarter of the zone (it cannot keep them
    /// apart). With mCrushedLengthFraction below the fold guard's gap (FfdDeformerSettings::mMinControlSpacing)
    /// a stacked-up crush leaks into the cell (CrushPlan).
    double mCrushZoneFraction = 0.25;
};

/// Checks a material at the API boundary: every field finite and within the range its comment gives, and a
/// known model. The message names the offending field. DeformableObject::Create refuses what this refuses;
/// the Campbell helpers (CampbellCrush.h) crush nothing with such a material.
CRUMPLE_API Status ValidateDamageMaterial(const DamageMaterial& inMaterial);

} // namespace crumple::plugin
