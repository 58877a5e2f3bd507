// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/plugin/BaraffImpulse.h>

#include <span>
#include <vector>

namespace crumple::plugin
{

/// One contact's impulse: +mNormal n + mFriction on A, the opposite on B (world frame).
struct CRUMPLE_API ContactImpulse
{
    double mNormal = 0.0;          ///< Along the contact normal n (B to A) (N s), >= 0
    Vec3 mFriction = Vec3::Zero(); ///< Tangential impulse on A (N s), perpendicular to n, |mFriction| <= mu mNormal
};

/// Impulses with Coulomb friction of contacts that one engine step reported together for the same body pair.
///
/// Normal impulses are SimultaneousImpulses' (closing contacts only, K j = -(1+e) v, minimum norm, pushing
/// only), and each contact's friction impulse t stops its sliding (zero relative tangential velocity after
/// the impulses, no tangential restitution) where Coulomb's isotropic cone |t| <= mu j allows; otherwise it
/// slides and t is cut back onto the cone. Friction at a lever arm changes the normal approach speeds, and the
/// normal impulses bound friction, so the two are solved in turn until neither changes (staggered projections:
/// Kaufman, Sueda, James and Pai 2008, "Staggered projections for frictional contact in multibody systems").
/// Each friction solve is a projected Gauss-Seidel over the contacts' 2x2 tangent blocks of the impulse
/// response, warm-started by the previous round. The restitution target stays the approach speed before any
/// impulse: after the solve each pushing contact separates at e times the speed it closed with.
/// With mu = 0 on every contact the normal impulses are SimultaneousImpulses' bit for bit and friction is zero.
/// @param[in] inContacts       contacts with their mu (ImpulseContact::mFriction, >= 0, +inf for no sliding)
/// @param[in] inRestitution    coefficient of restitution e in [0, 1]
/// @param[in] inClosingSpeed   contacts approaching slower than this (m/s, >= 0), after their speculative
///                             speed, count as resting: zero impulse, normal and tangential
/// @return one ContactImpulse per contact, in order
CRUMPLE_API std::vector<ContactImpulse> FrictionalImpulses(const BodyState& inA, const BodyState& inB,
                                                           std::span<const ImpulseContact> inContacts,
                                                           double inRestitution, double inClosingSpeed);

} // namespace crumple::plugin
