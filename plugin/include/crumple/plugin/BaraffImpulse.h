// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/plugin/BodyState.h>

#include <span>
#include <vector>

namespace crumple::plugin
{

/// Normal approach velocity of A relative to B at world point inPoint along inNormal (B to A), from the
/// bodies' (pre-solve) states: v_rel = n . (v_A + w_A x r_A - v_B - w_B x r_B) (m/s). Negative when closing.
CRUMPLE_API double RelativeNormalVelocity(const BodyState& inA, const BodyState& inB, const Vec3& inPoint, const Vec3& inNormal);

/// Impulse magnitude of one frictionless contact (Baraff 1992, "Dynamic simulation of non-penetrating
/// rigid bodies", eq. 8-18; D4MD section 6.2):
///   j = -(1 + e) v_rel / (1/m_A + 1/m_B + n.((I_A^-1 (r_A x n)) x r_A) + n.((I_B^-1 (r_B x n)) x r_B)),
/// applied as +j n to A and -j n to B (N s). Zero when the contact is not closing (v_rel >= 0), and when
/// both bodies are static or kinematic.
/// @param[in] inA, inB         body states before the engine's solver
/// @param[in] inPoint          contact point, world frame (m)
/// @param[in] inNormal         unit normal from B to A, world frame
/// @param[in] inRestitution    coefficient of restitution e in [0, 1]
/// These are the solver's kernels, without an error channel: their inputs are validated where they enter the
/// library (DamageWorld::SubmitContacts, DamageWorldSettings), and a direct caller must keep to the ranges
/// above (a debug build asserts them).
CRUMPLE_API double BaraffImpulse(const BodyState& inA, const BodyState& inB, const Vec3& inPoint, const Vec3& inNormal,
                     double inRestitution);

/// One contact of a simultaneous impulse solve.
struct CRUMPLE_API ImpulseContact
{
    Vec3 mPoint = Vec3::Zero();  ///< World contact point (m)
    Vec3 mNormal = Vec3::UnitZ(); ///< Unit normal from B to A
    double mSpeculativeSpeed = 0.0; ///< Approach speed that only closes a gap within the step (m/s, >= 0): for a
                                    ///< contact reported at a distance g before touching, g / dt. Only the approach
                                    ///< beyond it is resolved now, as an engine's speculative contact solver does;
                                    ///< the rest arrives with the next step's contact
    double mFriction = 0.0;         ///< Coulomb friction coefficient mu (>= 0, +inf: no sliding), used by
                                    ///< FrictionalImpulses; SimultaneousImpulses is frictionless
};

/// Impulses of contacts that one engine step reported together for the same body pair (N s each, >= 0).
///
/// Each contact's own Baraff impulse would resolve the whole approach velocity again, so N points of one
/// impact would add up to N times the physical impulse. Instead the contacts are solved together: with
/// K_ij = n_i . (dv at i per unit impulse along n_j) (Baraff 1992, section 8, the contact-force matrix
/// applied to impulses), find j >= 0 with K j = -(1+e) v over the closing contacts, taking the
/// minimum-norm solution (complete orthogonal decomposition), so symmetric contact sets share the impulse
/// symmetrically and the total equals the single-contact impulse of the same impact. Contacts that would
/// need a pulling impulse are dropped from the active set and the rest re-solved (at most N rounds).
/// @param[in] inClosingSpeed  contacts approaching slower than this (m/s, >= 0), after their speculative
///                            speed, count as resting: zero impulse
CRUMPLE_API std::vector<double> SimultaneousImpulses(const BodyState& inA, const BodyState& inB,
                                         std::span<const ImpulseContact> inContacts, double inRestitution,
                                         double inClosingSpeed);

} // namespace crumple::plugin
