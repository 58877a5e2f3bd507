// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/plugin/BaraffImpulse.h>

#include <Eigen/Core>

#include <span>
#include <vector>

namespace crumple::plugin
{

/// The contacts of one body pair that close faster than the resting speed, and what the normal impulse solve
/// needs of them (SimultaneousImpulses, FrictionalImpulses).
struct ClosingContacts
{
    std::vector<std::size_t> mIndices; ///< Into the caller's contacts, ascending
    Eigen::MatrixXd mResponse;         ///< K, #closing by #closing: K_ij = n_i . (dv at i per unit impulse +n_j on A, -n_j on B)
    Eigen::VectorXd mTarget;           ///< -(1+e) v_rel per closing contact, its speculative speed included (m/s)
};

/// Change of A's-minus-B's velocity along inNormalI at inPointI per unit impulse +n_j on A, -n_j on B (s/kg).
double ImpulseResponse(const BodyState& inA, const BodyState& inB, const Vec3& inPointI, const Vec3& inNormalI,
                       const Vec3& inPointJ, const Vec3& inNormalJ);

/// The contacts approaching faster than inClosingSpeed after their speculative speed, with K and the target.
ClosingContacts FindClosingContacts(const BodyState& inA, const BodyState& inB, std::span<const ImpulseContact> inContacts,
                                    double inRestitution, double inClosingSpeed);

/// Normal impulses j >= 0 (N s) with K j = target wherever a contact pushes: minimum-norm solves over an
/// active set that drops pulling contacts, then a projected Gauss-Seidel polish of the complementarity
/// conditions. One contact: target / K, exactly as published. All zero when both bodies are immovable.
Eigen::VectorXd SolveNormalImpulses(const Eigen::MatrixXd& inResponse, const Eigen::VectorXd& inTarget);

} // namespace crumple::plugin
