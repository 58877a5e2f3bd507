// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

namespace crumple::plugin
{

/// How a deformable object turns impulse into dents (D4MD section 6.1: the "deformable object" properties).
/// Defaults suit a steel car body: a 1,200 kg car hitting a rigid wall at 15 m/s (about 18 kN s) is crushed
/// to the instantaneous maximum in one collision.
struct DamageMaterial
{
    double mDeformationFactor = 2.0e-5;   ///< Dent depth per unit impulse (m/(N s)), >= 0: depth = factor |J|,
                                          ///< like a spring turning force into displacement
    double mMinDeformation = 1.0e-3;      ///< Dents shallower than this are dropped (m), >= 0
    double mMaxInstantDeformation = 0.3;  ///< Deepest dent one collision can make at a contact (m), >= min
    /// The part of a collision's impulse that leaves no permanent dent (N s), >= 0: the depth is
    /// factor (|J| - threshold) when |J| exceeds it. Campbell's linear crush model (SAE 740565) has a
    /// no-damage speed b0 (2.2-4.5 m/s for modern cars, SAE 2010-01-0069): against a rigid barrier that is
    /// an impulse of about (1 + e) m b0. 0 (the default): every impulse dents.
    double mImpulseThreshold = 0.0;
};

} // namespace crumple::plugin
