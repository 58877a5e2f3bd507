// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/base/Assert.h>
#include <crumple/plugin/BaraffImpulse.h>

#include <Eigen/QR>

#include <algorithm>
#include <cmath>

namespace crumple::plugin
{

namespace
{

// Change of A's-minus-B's velocity along inNormalI at inPointI per unit impulse +n_j on A, -n_j on B.
double ImpulseResponse(const BodyState& inA, const BodyState& inB, const Vec3& inPointI, const Vec3& inNormalI,
                       const Vec3& inPointJ, const Vec3& inNormalJ)
{
    const Vec3 ra_i = inPointI - inA.mCenterOfMass, ra_j = inPointJ - inA.mCenterOfMass;
    const Vec3 rb_i = inPointI - inB.mCenterOfMass, rb_j = inPointJ - inB.mCenterOfMass;
    const Vec3 dv_a = inA.InverseMass() * inNormalJ + (inA.InverseInertia() * ra_j.cross(inNormalJ)).cross(ra_i);
    const Vec3 dv_b = inB.InverseMass() * inNormalJ + (inB.InverseInertia() * rb_j.cross(inNormalJ)).cross(rb_i);
    return inNormalI.dot(dv_a + dv_b);
}

} // namespace

double RelativeNormalVelocity(const BodyState& inA, const BodyState& inB, const Vec3& inPoint, const Vec3& inNormal)
{
    return inNormal.dot(inA.PointVelocity(inPoint) - inB.PointVelocity(inPoint));
}

double BaraffImpulse(const BodyState& inA, const BodyState& inB, const Vec3& inPoint, const Vec3& inNormal,
                     double inRestitution)
{
    CRUMPLE_ASSERT(inRestitution >= 0.0 && inRestitution <= 1.0 && std::abs(inNormal.norm() - 1.0) <= 1.0e-6,
                   "BaraffImpulse: restitution outside [0, 1] or a normal that is not unit");
    const double v_rel = RelativeNormalVelocity(inA, inB, inPoint, inNormal);
    if (!(v_rel < 0.0))
        return 0.0;
    const double denominator = ImpulseResponse(inA, inB, inPoint, inNormal, inPoint, inNormal);
    // Two immovable bodies: nothing can change their velocity.
    if (!(denominator > 0.0))
        return 0.0;
    return -(1.0 + inRestitution) * v_rel / denominator;
}

std::vector<double> SimultaneousImpulses(const BodyState& inA, const BodyState& inB,
                                         std::span<const ImpulseContact> inContacts, double inRestitution,
                                         double inClosingSpeed)
{
    CRUMPLE_ASSERT(inRestitution >= 0.0 && inRestitution <= 1.0 && inClosingSpeed >= 0.0,
                   "SimultaneousImpulses: restitution outside [0, 1] or a negative closing speed");
    const std::size_t n = inContacts.size();
    std::vector<double> impulses(n, 0.0);
    std::vector<double> v_rel(n);
    std::vector<std::size_t> active;
    for (std::size_t i = 0; i < n; ++i)
    {
        v_rel[i] = RelativeNormalVelocity(inA, inB, inContacts[i].mPoint, inContacts[i].mNormal) +
                   std::max(inContacts[i].mSpeculativeSpeed, 0.0);
        if (v_rel[i] < -inClosingSpeed)
            active.push_back(i);
    }
    if (active.empty())
        return impulses;

    // One closing contact: the scalar formula, exactly as published.
    if (active.size() == 1)
    {
        const ImpulseContact& c = inContacts[active[0]];
        const double response = ImpulseResponse(inA, inB, c.mPoint, c.mNormal, c.mPoint, c.mNormal);
        impulses[active[0]] = response > 0.0 ? -(1.0 + inRestitution) * v_rel[active[0]] / response : 0.0;
        return impulses;
    }

    // The closing contacts' response matrix K and target -(1+e) v.
    const auto m = static_cast<Eigen::Index>(active.size());
    Eigen::MatrixXd k(m, m);
    Eigen::VectorXd target(m);
    for (Eigen::Index r = 0; r < m; ++r)
    {
        const ImpulseContact& ci = inContacts[active[static_cast<std::size_t>(r)]];
        target[r] = -(1.0 + inRestitution) * v_rel[active[static_cast<std::size_t>(r)]];
        for (Eigen::Index c = 0; c < m; ++c)
        {
            const ImpulseContact& cj = inContacts[active[static_cast<std::size_t>(c)]];
            k(r, c) = ImpulseResponse(inA, inB, ci.mPoint, ci.mNormal, cj.mPoint, cj.mNormal);
        }
    }
    if (!(k.diagonal().maxCoeff() > 0.0))
        return impulses; // both bodies immovable

    // Active set: minimum-norm solve over the pushing contacts, drop any that would pull, repeat.
    Eigen::VectorXd j = Eigen::VectorXd::Zero(m);
    std::vector<Eigen::Index> pushing(static_cast<std::size_t>(m));
    for (Eigen::Index r = 0; r < m; ++r)
        pushing[static_cast<std::size_t>(r)] = r;
    while (!pushing.empty())
    {
        const auto p = static_cast<Eigen::Index>(pushing.size());
        Eigen::MatrixXd k_sub(p, p);
        Eigen::VectorXd t_sub(p);
        for (Eigen::Index r = 0; r < p; ++r)
        {
            t_sub[r] = target[pushing[static_cast<std::size_t>(r)]];
            for (Eigen::Index c = 0; c < p; ++c)
                k_sub(r, c) = k(pushing[static_cast<std::size_t>(r)], pushing[static_cast<std::size_t>(c)]);
        }
        Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> decomposition;
        decomposition.setThreshold(1.0e-10);
        decomposition.compute(k_sub);
        const Eigen::VectorXd solution = decomposition.solve(t_sub);
        const double scale = solution.cwiseAbs().maxCoeff();
        std::vector<Eigen::Index> kept;
        for (Eigen::Index r = 0; r < p; ++r)
            if (solution[r] >= -1.0e-12 * scale)
                kept.push_back(pushing[static_cast<std::size_t>(r)]);
        if (kept.size() == pushing.size())
        {
            j.setZero();
            for (Eigen::Index r = 0; r < p; ++r)
                j[pushing[static_cast<std::size_t>(r)]] = std::max(solution[r], 0.0);
            break;
        }
        pushing = std::move(kept);
    }

    // Projected Gauss-Seidel polish of the complementarity conditions (j >= 0, K j - target >= 0,
    // j (K j - target) = 0): a no-op when the active-set answer already satisfies them, which keeps
    // symmetric sets symmetric; otherwise it pushes the dropped contacts that still approach.
    const double tolerance = 1.0e-14 * std::max(target.cwiseAbs().maxCoeff(), 1.0e-300);
    for (int sweep = 0; sweep < 200; ++sweep)
    {
        double change = 0.0;
        for (Eigen::Index r = 0; r < m; ++r)
        {
            const double residual = k.row(r).dot(j) - target[r];
            const double updated = std::max(0.0, j[r] - residual / k(r, r));
            change = std::max(change, std::abs(updated - j[r]) * k(r, r));
            j[r] = updated;
        }
        if (change <= tolerance)
            break;
    }
    for (Eigen::Index r = 0; r < m; ++r)
        impulses[active[static_cast<std::size_t>(r)]] = j[r];
    return impulses;
}

} // namespace crumple::plugin
