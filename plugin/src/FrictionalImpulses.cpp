// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/base/Assert.h>
#include <crumple/plugin/FrictionalImpulses.h>

#include "FrictionContactRow.h"
#include "FrictionSubspaceStep.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace crumple::plugin
{

namespace
{

// The joint solve stops as soon as a sweep changes no contact point's velocity by more than cRelativeChange
// of the largest approach speed. A 1e-9 stop took a quarter less time on crumple-bench's sliding box (errors
// 1e-10), but moved the Bullet fence drive-through's outcome by 3 % of the car's speed loss (PropFenceTest's
// converged case): that coupling amplifies even such differences.
constexpr double cRelativeChange = 1.0e-12;

// Gauss-Seidel has stalled when over a window of this many sweeps no sweep moved a contact point's velocity
// by more than cStallChange of the largest approach speed and the distance from Coulomb's conditions
// (MeritOfRows) fell by less than cStallProgress of itself.
constexpr int cStallWindow = 50;
constexpr double cStallChange = 1.0e-9;
constexpr double cStallProgress = 0.01;
// A subspace step after a refused one waits until the distance from Coulomb's conditions is below this
// fraction of what it was at the refusal.
constexpr double cRetryProgress = 0.5;

// Kinetic energy made beyond this fraction of the sum of its terms' magnitudes is not round-off.
constexpr double cEnergyRoundOff = 1.0e-12;

// Projected Gauss-Seidel over every contact's normal row and friction block together, as engines solve
// contact (Bullet's sequential impulses, ODE's quick step), from ioRows' impulses: a normal impulse j >= 0
// takes the contact's normal velocity change to at least its target (zero impulse where it is more), then the
// friction impulse minimizes the kinetic energy over the cone mu j given every other impulse
// (LeastEnergyInDisc). Sweeps until no contact point's velocity changes by more than cRelativeChange of
// inSpeedScale (m/s) in a sweep, with subspace steps (FrictionSubspaceStep) between, after
// inSettings.mSubspaceInterval sweeps and then after twice as many each time. The sweeps hold the pair's
// velocity change as one 12-vector and each contact axis in the form SweepAxis works out once, so a row costs
// a dot product and an update of 12 numbers instead of lever-arm cross products and inertia products
// (crumple-bench --only impulse: the friction rows 1.1-1.9 times faster, 6153452).
FrictionSolveStats SolveJointly(const PairInverseMass& inPair, double inSpeedScale,
                                const FrictionSolveSettings& inSettings, std::vector<ContactRow>& ioRows)
{
    FrictionSolveStats stats;
    stats.mConverged = false;
    PairVector change = SweepChangeOfRows(ioRows);
    const bool subspace = inSettings.mSubspaceInterval > 0 &&
                          ioRows.size() <= static_cast<std::size_t>(inSettings.mSubspaceMaxContacts);
    std::int64_t interval = inSettings.mSubspaceInterval,
                 next_step = interval; // intent: doubling cannot overflow
    double window_moved = 0.0, window_merit = std::numeric_limits<double>::infinity();
    std::int64_t last_refused = -cStallWindow; // the sweep after which a subspace step was last refused
    double refused_merit = std::numeric_limits<double>::infinity(); // MeritOfRows when it was refused
    for (int sweep = 0; sweep < inSettings.mMaxSweeps; ++sweep)
    {
        ++stats.mSweeps;
        const PairVector start = change;
        for (ContactRow& row : ioRows)
        {
            if (row.mNormalResponse > 0.0)
            {
                const double residual = row.mSweepNormal.mSees.dot(change) - row.mTarget;
                const double updated = std::max(0.0, row.mNormalImpulse - residual / row.mNormalResponse);
                change += (updated - row.mNormalImpulse) * row.mSweepNormal.mMoves;
                row.mNormalImpulse = updated;
            }
            const double radius = ConeRadius(row.mFriction, row.mNormalImpulse);
            if (!(radius > 0.0) && row.mFrictionImpulse.isZero(0.0))
                continue;
            // intent: the slip without this row's own friction impulse, in its tangent basis
            const Eigen::Vector2d own(row.mTangent1.dot(row.mFrictionImpulse), row.mTangent2.dot(row.mFrictionImpulse));
            const Eigen::Vector2d velocity =
                row.mTangentVelocityBefore +
                Eigen::Vector2d(row.mSweepTangent1.mSees.dot(change), row.mSweepTangent2.mSees.dot(change));
            const Eigen::Vector2d slip = velocity - row.mTangentResponse * own;
            const Eigen::Vector2d t = row.mDisc.Solve(slip, radius);
            const Eigen::Vector2d step = t - own;
            change += step[0] * row.mSweepTangent1.mMoves + step[1] * row.mSweepTangent2.mMoves;
            row.mFrictionImpulse = t[0] * row.mTangent1 + t[1] * row.mTangent2;
        }
        // intent: converged when the sweep moved no contact point's velocity: impulses may still trade along a
        // direction that moves nothing (two points on a line pushing along it), and need not settle
        const PairVector sweep_change = change - start;
        const Vec3 linear = sweep_change.segment<3>(0) - sweep_change.segment<3>(6);
        const Vec3 angular_a = sweep_change.segment<3>(3), angular_b = sweep_change.segment<3>(9);
        double moved = 0.0;
        for (const ContactRow& row : ioRows)
            moved = std::max(moved,
                             (linear + angular_a.cross(row.mArms.mA) - angular_b.cross(row.mArms.mB)).norm());
        if (moved <= cRelativeChange * inSpeedScale)
        {
            stats.mConverged = true;
            break;
        }
        // intent: a stalled Gauss-Seidel (its sweeps trade impulses that move the points by round-off while
        // the answer stays as far from Coulomb's conditions) gets a subspace step at once, unless one was
        // refused within the stalled window (from the same state, to round-off); where that step is refused
        // too, neither can bring the answer closer and the solve stops (stats.mStalled) instead of sweeping
        // and stepping on to its bound. Without subspace steps (too many contacts) it sweeps on: a slow
        // Gauss-Seidel still converges there.
        window_moved = std::max(window_moved, moved);
        bool stalled = false;
        if (subspace && stats.mSweeps % cStallWindow == 0)
        {
            const double merit = MeritOfRows(inPair, ioRows);
            stalled = window_moved <= cStallChange * inSpeedScale &&
                      !(merit < (1.0 - cStallProgress) * window_merit);
            window_merit = merit;
            window_moved = 0.0;
            if (stalled && stats.mSweeps - last_refused < cStallWindow)
            {
                stats.mStalled = true;
                break;
            }
        }
        // intent: a subspace step after mSubspaceInterval sweeps, then after twice as many each time: a step
        // that finds no answer (states that cannot all hold) costs a bounded share of the sweeps
        // intent: after a refused step the next scheduled one waits until Gauss-Seidel has halved the
        // distance from Coulomb's conditions since: from a state no better the step would fail as it did
        const bool scheduled = stats.mSweeps == next_step && subspace;
        const bool retry = scheduled && !stalled && std::isfinite(refused_merit) &&
                           !(MeritOfRows(inPair, ioRows) < cRetryProgress * refused_merit);
        if (retry)
        {
            interval *= 2;
            next_step += interval;
        }
        if ((scheduled && !retry) || (stalled && subspace))
        {
            int iterations = 0;
            const ESubspaceOutcome outcome = FrictionSubspaceStep(inPair, inSpeedScale, ioRows, iterations);
            stats.mNewtonIterations += iterations;
            stats.mMostStepIterations = std::max(stats.mMostStepIterations, iterations);
            if (outcome != ESubspaceOutcome::Refused)
            {
                change = SweepChangeOfRows(ioRows);
                ++stats.mSubspaceSteps;
            }
            // intent: a least-squares point as close to Coulomb's conditions as the states allow:
            // Gauss-Seidel would only crawl to a point of its own no closer to them
            if (outcome == ESubspaceOutcome::Settled)
            {
                stats.mConverged = true;
                stats.mSettled = true;
                break;
            }
            if (outcome == ESubspaceOutcome::Refused)
            {
                if (stalled)
                {
                    stats.mStalled = true;
                    break;
                }
                last_refused = stats.mSweeps;
                refused_merit = MeritOfRows(inPair, ioRows);
            }
            else
                refused_merit = std::numeric_limits<double>::infinity();
            if (stats.mSweeps == next_step)
            {
                interval *= 2;
                next_step += interval;
            }
        }
    }
    return stats;
}

// Change of A's-minus-B's velocity at a point per unit impulse vector at the same point (s/kg), 3 by 3:
// W = (1/m_A + 1/m_B) I - [r_A]x I_A^-1 [r_A]x - [r_B]x I_B^-1 [r_B]x, with r the point's lever arms.
Mat3 PointResponse(const PairInverseMass& inPair, const LeverArms& inArms)
{
    Mat3 response;
    const Vec3 &r_a = inArms.mA, &r_b = inArms.mB;
    for (int k = 0; k < 3; ++k)
    {
        const Vec3 e = Vec3::Unit(k);
        response.col(k) = (inPair.mMassA + inPair.mMassB) * e + (inPair.mInertiaA * r_a.cross(e)).cross(r_a) +
                          (inPair.mInertiaB * r_b.cross(e)).cross(r_b);
    }
    return response;
}

// The change of the pair's kinetic energy that inRows' impulses make (J): with p_i the impulse on A at point
// i, v_i the A-minus-B velocity there before and u_i the change all impulses make there, dE = sum_i p_i .
// (v_i + u_i / 2), exactly (the energy is quadratic in the impulses), with no inertia inverted. outScale: the
// sum of the terms' magnitudes (J), the scale of the sum's round-off.
double KineticEnergyChange(const PairInverseMass& inPair, const std::vector<ContactRow>& inRows,
                           double& outScale)
{
    const VelocityChange change = ChangeOfRows(inPair, inRows);
    double made = 0.0;
    outScale = 0.0;
    for (const ContactRow& row : inRows)
    {
        const Vec3 impulse = row.mNormalImpulse * row.mNormal + row.mFrictionImpulse;
        const Vec3 half_change = 0.5 * change.At(row.mArms);
        made += impulse.dot(row.mVelocityBefore + half_change);
        outScale += std::abs(impulse.dot(row.mVelocityBefore)) + std::abs(impulse.dot(half_change));
    }
    return made;
}

} // namespace

std::vector<ContactImpulse> FrictionalImpulses(const BodyState& inA, const BodyState& inB,
                                               std::span<const ImpulseContact> inContacts,
                                               double inRestitution, double inClosingSpeed,
                                               const FrictionSolveSettings& inSettings,
                                               FrictionSolveStats* outStats)
{
    CRUMPLE_ASSERT(inRestitution >= 0.0 && inRestitution <= 1.0 && inClosingSpeed >= 0.0,
                   "FrictionalImpulses: restitution outside [0, 1] or a negative closing speed");
    CRUMPLE_ASSERT(
        inSettings.mMaxSweeps >= 1 && inSettings.mSubspaceInterval >= 0 &&
            inSettings.mSubspaceMaxContacts >= 0,
        "FrictionalImpulses: fewer than one sweep, or a negative subspace interval or contact count");
    if (outStats != nullptr)
        *outStats = {};
    // intent: the frictionless answer first, the start of the joint solve and the whole answer without friction
    const std::vector<double> normal = SimultaneousImpulses(inA, inB, inContacts, inRestitution, inClosingSpeed);
    std::vector<ContactImpulse> impulses(inContacts.size());
    for (std::size_t i = 0; i < inContacts.size(); ++i)
        impulses[i].mNormal = normal[i];
    bool any_friction = false;
    for (std::size_t i = 0; i < inContacts.size(); ++i)
    {
        CRUMPLE_ASSERT(inContacts[i].mFriction >= 0.0, "FrictionalImpulses: a negative friction coefficient");
        any_friction = any_friction || (inContacts[i].mFriction > 0.0 && impulses[i].mNormal > 0.0);
    }
    if (!any_friction)
        return impulses;

    // intent: every contact joins the joint solve, so one that friction turns towards the other body is held
    // too: a closing contact must change its normal velocity by -(1+e) v, any other must not approach faster
    // than the resting speed
    // intent: the masses read once: every contact's response and every sweep's impulses use them
    const PairInverseMass pair(inA, inB);
    std::vector<ContactRow> rows(inContacts.size());
    for (std::size_t i = 0; i < inContacts.size(); ++i)
    {
        const ImpulseContact& contact = inContacts[i];
        ContactRow& row = rows[i];
        row.mArms = LeverArms(inA, inB, contact.mPoint);
        row.mVelocityBefore = inA.PointVelocity(contact.mPoint) - inB.PointVelocity(contact.mPoint);
        row.mNormal = contact.mNormal;
        row.mTangent1 = contact.mNormal.unitOrthogonal();
        row.mTangent2 = contact.mNormal.cross(row.mTangent1);
        const Mat3 response = PointResponse(pair, row.mArms);
        row.mNormalResponse = row.mNormal.dot(response * row.mNormal);
        Eigen::Matrix<double, 3, 2> basis;
        basis << row.mTangent1, row.mTangent2;
        const Eigen::Matrix2d tangent_response = basis.transpose() * response * basis;
        // intent: symmetric as W is (rounding aside); friction that cannot move the contact stays out
        if (tangent_response.determinant() > 0.0 && tangent_response(0, 0) > 0.0)
        {
            row.mTangentResponse = 0.5 * (tangent_response + tangent_response.transpose());
            row.mFriction = contact.mFriction;
            if (row.mFriction > 0.0)
                row.mDisc = LeastEnergyInDisc(row.mTangentResponse);
        }
        const double v = RelativeNormalVelocity(inA, inB, contact.mPoint, contact.mNormal) +
                         std::max(contact.mSpeculativeSpeed, 0.0);
        row.mTarget = v < -inClosingSpeed ? -(1.0 + inRestitution) * v : -(v + inClosingSpeed);
        row.mSweepNormal = SweepAxis(pair, row.mArms, row.mNormal);
        row.mSweepTangent1 = SweepAxis(pair, row.mArms, row.mTangent1);
        row.mSweepTangent2 = SweepAxis(pair, row.mArms, row.mTangent2);
        row.mTangentVelocityBefore =
            Eigen::Vector2d(row.mTangent1.dot(row.mVelocityBefore), row.mTangent2.dot(row.mVelocityBefore));
        row.mNormalImpulse = impulses[i].mNormal;
    }
    double speed_scale = std::numeric_limits<double>::min();
    for (const ContactRow& row : rows)
        speed_scale = std::max(speed_scale, std::abs(row.mTarget));
    FrictionSolveStats stats = SolveJointly(pair, speed_scale, inSettings, rows);
    // intent: a solve stopped at its bound may have made kinetic energy (measured: 10 of 20,000 adversarial
    // sets with mu = +inf gained up to 144 %, whose impulses would dent as a much harder hit); then the
    // frictionless answer stands where it makes less
    double scale = 0.0;
    const double made = stats.mConverged ? 0.0 : KineticEnergyChange(pair, rows, scale);
    if (made > cEnergyRoundOff * scale)
    {
        std::vector<ContactRow> frictionless = rows;
        for (std::size_t i = 0; i < rows.size(); ++i)
        {
            frictionless[i].mNormalImpulse = impulses[i].mNormal;
            frictionless[i].mFrictionImpulse = Vec3::Zero();
        }
        double frictionless_scale = 0.0;
        if (KineticEnergyChange(pair, frictionless, frictionless_scale) < made)
        {
            rows = std::move(frictionless);
            stats.mFrictionDropped = true;
        }
    }
    if (outStats != nullptr)
        *outStats = stats;
    for (std::size_t i = 0; i < rows.size(); ++i)
        impulses[i] = {rows[i].mNormalImpulse, rows[i].mFrictionImpulse};
    return impulses;
}

} // namespace crumple::plugin
