// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "FrictionSubspaceStep.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace crumple::plugin
{

namespace
{

// A contact's friction is on its cone's rim (sliding) when it is within this fraction of the radius: the disc
// step (LeastEnergyInDisc) puts a sliding contact's friction on the rim to round-off.
constexpr double cRimFraction = 1.0 - 1.0e-9;

bool IsSliding(const ContactRow& inRow)
{
    const double radius = ConeRadius(inRow.mFriction, inRow.mNormalImpulse);
    return radius > 0.0 && std::isfinite(radius) && inRow.mFrictionImpulse.norm() >= cRimFraction * radius;
}

// Newton iterations per held set of states at most: from Gauss-Seidel's iterate they converge quadratically,
// and end when F's every scaled equation is within cConverged of zero.
constexpr int cMaxNewtonIterations = 30;
constexpr double cConverged = 1.0e-13;

// Halvings of a Newton step at most before it gives up on the states.
constexpr int cMaxHalvings = 30;

// A Newton iteration whose step needed at least cStagnantHalvings halvings and still left more than
// cStagnantResidual of |F|^2 has stagnated: the held states cannot all hold (nearly coplanar contacts whose
// targets no impulses meet together) and Gauss-Newton only creeps towards their least-squares point, each
// iteration a least-norm solve. Measured on the car's front on the moving fence (CarFrontOnFenceCrawl): the
// first step's Newton crept from |F| 2.7e-3 to 1.9e-3 over 20 iterations of 4-5 halvings each and hit the
// 32-iteration bound; every later step sat at a least-squares point taking 9-19 halvings per iteration.
// Ending Newton there hands the point to the state changes (and the one release) at once.
constexpr int cStagnantHalvings = 2;
constexpr double cStagnantResidual = 0.9;

// Changes of state within one step at most (a sticking contact whose friction leaves its cone turns sliding,
// a sliding one whose slip stops turns sticking, a pulling one lets go), each followed by a Newton solve.
constexpr int cMaxStateChanges = 8;

enum class EContactState
{
    Idle,     // let go: j = 0, t = 0
    Pushing,  // no friction: j only
    Sticking, // j, and t that stops the slip
    Sliding,  // j, and t = mu j against the slip
};

// A pushing contact in the subspace system: where its unknowns start in x (its normal impulse j, then its
// friction's two tangent components where it has friction) and its state.
struct SubspaceRow
{
    std::size_t mRow = 0;
    Eigen::Index mFirst = 0;
    bool mFriction = false;
    EContactState mState = EContactState::Pushing;
};

} // namespace

double MeritOfRows(const PairInverseMass& inPair, const std::vector<ContactRow>& inRows)
{
    const VelocityChange change = ChangeOfRows(inPair, inRows);
    double merit = 0.0;
    for (const ContactRow& row : inRows)
    {
        const Vec3 change_at = change.At(row.mArms);
        if (row.mNormalResponse > 0.0)
        {
            // intent: a pushing contact meets its target; an idle one only must not fall short of it
            const double missing = row.mTarget - row.mNormal.dot(change_at);
            merit = std::max(merit, row.mNormalImpulse > 0.0 ? std::abs(missing) : std::max(missing, 0.0));
        }
        const double radius = ConeRadius(row.mFriction, row.mNormalImpulse);
        if (!(radius > 0.0))
            continue;
        const Vec3 velocity = row.mVelocityBefore + change_at;
        const Vec3 slip = velocity - row.mNormal.dot(velocity) * row.mNormal;
        if (!IsSliding(row))
        {
            merit = std::max(merit, slip.norm());
            continue;
        }
        // intent: sliding friction points against the slip: the slip's part off -t, and any part along +t
        const Vec3 against = -row.mFrictionImpulse.normalized();
        const double along = slip.dot(against);
        merit = std::max(merit, (slip - along * against).norm() + std::max(-along, 0.0));
    }
    return merit;
}

// The step solves F(x) = 0 by Newton's method with the states held: for each pushing contact i (impulse
// p_i = j_i n_i + T_i t_i, velocity change u_i = sum_k W_ik p_k with W_ik the 3x3 response of point i to an
// impulse at k, slip s_i = T_i^T (v0_i + u_i)):
//   n_i . u_i - target_i = 0;   sticking: s_i = 0;   sliding: t_i + mu_i j_i s_i / |s_i| = 0;
//   idle: j_i = 0, t_i = 0,
// whose Jacobian takes d(s/|s|) = (I - s^ s^T) ds / |s|. The linear solves are least norm (complete
// orthogonal decomposition): redundant contacts make the system singular. Then states that the answer breaks
// change and it solves again.
ESubspaceOutcome FrictionSubspaceStep(const PairInverseMass& inPair, double inSpeedScale,
                                      std::vector<ContactRow>& ioRows, int& outIterations)
{
    outIterations = 0;
    // intent: the pushing contacts, their states and their unknowns' places
    std::vector<SubspaceRow> rows;
    Eigen::Index n = 0;
    for (std::size_t i = 0; i < ioRows.size(); ++i)
    {
        const ContactRow& row = ioRows[i];
        if (!(row.mNormalResponse > 0.0) || !(row.mNormalImpulse > 0.0))
            continue;
        const bool friction = ConeRadius(row.mFriction, row.mNormalImpulse) > 0.0;
        const EContactState state = !friction
                                        ? EContactState::Pushing
                                        : (IsSliding(row) ? EContactState::Sliding : EContactState::Sticking);
        rows.push_back({i, n, friction, state});
        n += friction ? 3 : 1;
    }
    if (rows.empty())
        return ESubspaceOutcome::Refused;
    Eigen::VectorXd x(n);
    for (const SubspaceRow& r : rows)
    {
        const ContactRow& row = ioRows[r.mRow];
        x[r.mFirst] = row.mNormalImpulse;
        if (r.mFriction)
            x.segment<2>(r.mFirst + 1) = Eigen::Vector2d(row.mTangent1.dot(row.mFrictionImpulse),
                                                         row.mTangent2.dot(row.mFrictionImpulse));
    }
    // intent: the linear part of F: each unknown's unit impulse as the velocity change along each unknown's
    // axis (n, t1, t2) at its point, and those velocities before any impulse
    std::vector<Vec3> axes(static_cast<std::size_t>(n));
    std::vector<const ContactRow*> owners(static_cast<std::size_t>(n));
    for (const SubspaceRow& r : rows)
    {
        const ContactRow& row = ioRows[r.mRow];
        const Vec3 row_axes[3] = {row.mNormal, row.mTangent1, row.mTangent2};
        for (Eigen::Index k = 0; k < (r.mFriction ? 3 : 1); ++k)
        {
            axes[static_cast<std::size_t>(r.mFirst + k)] = row_axes[k];
            owners[static_cast<std::size_t>(r.mFirst + k)] = &row;
        }
    }
    Eigen::MatrixXd response(n, n);
    Eigen::VectorXd before(n);
    for (Eigen::Index c = 0; c < n; ++c)
    {
        const std::size_t uc = static_cast<std::size_t>(c);
        VelocityChange unit;
        unit.Apply(inPair, owners[uc]->mArms, axes[uc]);
        for (Eigen::Index r = 0; r < n; ++r)
        {
            const std::size_t ur = static_cast<std::size_t>(r);
            response(r, c) = axes[ur].dot(unit.At(owners[ur]->mArms));
        }
        before[c] = axes[uc].dot(owners[uc]->mVelocityBefore);
    }

    // intent: F and its Jacobian at x, each equation scaled to a dimensionless size (velocities by the
    // approach speed, a sliding contact's impulse by the largest impulse); false where a sliding contact's
    // slip stopped
    const double impulse_scale = std::max(x.lpNorm<Eigen::Infinity>(), std::numeric_limits<double>::min());
    const double velocity_scale = std::max(inSpeedScale, std::numeric_limits<double>::min());
    const auto evaluate = [&](const Eigen::VectorXd& inX, Eigen::VectorXd& outF, Eigen::MatrixXd* outJacobian)
    {
        const Eigen::VectorXd velocity = before + response * inX; // along each axis, at its point (m/s)
        if (outJacobian != nullptr)
            *outJacobian = response / velocity_scale;
        for (const SubspaceRow& r : rows)
        {
            const Eigen::Index f = r.mFirst, count = r.mFriction ? 3 : 1;
            const ContactRow& row = ioRows[r.mRow];
            if (r.mState == EContactState::Idle)
            {
                outF.segment(f, count) = inX.segment(f, count) / impulse_scale;
                if (outJacobian != nullptr)
                {
                    outJacobian->middleRows(f, count).setZero();
                    outJacobian->block(f, f, count, count).setIdentity();
                    outJacobian->block(f, f, count, count) /= impulse_scale;
                }
                continue;
            }
            outF[f] = (velocity[f] - before[f] - row.mTarget) / velocity_scale;
            if (r.mState == EContactState::Pushing)
                continue;
            const Eigen::Vector2d slip = velocity.segment<2>(f + 1);
            if (r.mState == EContactState::Sticking)
            {
                outF.segment<2>(f + 1) = slip / velocity_scale;
                continue;
            }
            const double speed = slip.norm();
            if (!(speed > 0.0))
                return false;
            const Eigen::Vector2d direction = slip / speed;
            const double mu_j = row.mFriction * inX[f];
            outF.segment<2>(f + 1) = (inX.segment<2>(f + 1) + mu_j * direction) / impulse_scale;
            if (outJacobian == nullptr)
                continue;
            // intent: d/dx of t + mu j s^: mu j (I - s^ s^T)/|s| ds/dx, plus the identity on t and mu s^ on j
            const Eigen::Matrix2d turn =
                (mu_j / speed) * (Eigen::Matrix2d::Identity() - direction * direction.transpose());
            outJacobian->middleRows<2>(f + 1) = turn * response.middleRows<2>(f + 1);
            outJacobian->block<2, 2>(f + 1, f + 1) += Eigen::Matrix2d::Identity();
            outJacobian->block<2, 1>(f + 1, f) += row.mFriction * direction;
            outJacobian->middleRows<2>(f + 1) /= impulse_scale;
        }
        return true;
    };

    // intent: the impulses of x with the held states, as contact rows
    const auto candidate_rows = [&]
    {
        std::vector<ContactRow> candidate = ioRows;
        for (const SubspaceRow& r : rows)
        {
            ContactRow& row = candidate[r.mRow];
            const bool idle = r.mState == EContactState::Idle;
            row.mNormalImpulse = idle ? 0.0 : x[r.mFirst];
            row.mFrictionImpulse = Vec3::Zero();
            if (idle || !r.mFriction)
                continue;
            row.mFrictionImpulse = x[r.mFirst + 1] * row.mTangent1 + x[r.mFirst + 2] * row.mTangent2;
            if (r.mState == EContactState::Sliding) // intent: on the rim to round-off
                row.mFrictionImpulse *=
                    ConeRadius(row.mFriction, row.mNormalImpulse) / row.mFrictionImpulse.norm();
        }
        return candidate;
    };

    Eigen::VectorXd residual(n), trial_residual(n);
    Eigen::MatrixXd jacobian(n, n);
    bool least_squares = false, released = false;
    std::vector<ContactRow> candidate; // the step's answer as contact rows, and its MeritOfRows
    double merit = 0.0;
    for (int attempt = 0; attempt <= cMaxStateChanges; ++attempt)
    {
        // intent: Newton's method on F with the states held, its step halved until |F| falls (the sliding
        // directions make F nonsmooth enough for full steps to cycle)
        bool converged = false;
        for (int iteration = 0; iteration < cMaxNewtonIterations && !converged; ++iteration)
        {
            if (outIterations == cMaxStepIterations || !evaluate(x, residual, &jacobian))
                return ESubspaceOutcome::Refused;
            ++outIterations;
            if (residual.lpNorm<Eigen::Infinity>() <= cConverged)
            {
                converged = true;
                break;
            }
            const Eigen::VectorXd step =
                Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>(jacobian).solve(residual);
            if (!step.allFinite())
                return ESubspaceOutcome::Refused;
            double fraction = 1.0;
            int halvings = 0;
            const double residual_norm2 = residual.squaredNorm();
            double trial_norm2 = 0.0; // |F|^2 of the last step tried (once evaluated)
            const auto descends = [&]
            {
                if (!evaluate(x - fraction * step, trial_residual, nullptr))
                    return false;
                trial_norm2 = trial_residual.squaredNorm();
                return trial_norm2 < (1.0 - 1.0e-4 * fraction) * residual_norm2;
            };
            while (!descends())
            {
                if (++halvings > cMaxHalvings)
                    break;
                fraction *= 0.5;
            }
            // intent: no descent, or too little to be worth another least-norm solve (stagnation): a
            // least-squares point of states that cannot all hold, whose breaches name the states to change
            if (halvings > cMaxHalvings ||
                (halvings >= cStagnantHalvings && trial_norm2 > cStagnantResidual * residual_norm2))
                break;
            x -= fraction * step;
        }
        // intent: states the answer breaks change: a pulling contact lets go, sticking friction outside its
        // cone slides, sliding friction whose slip stopped sticks
        bool changed = false;
        const Eigen::VectorXd velocity = before + response * x;
        for (SubspaceRow& r : rows)
        {
            const ContactRow& row = ioRows[r.mRow];
            const Eigen::Index f = r.mFirst;
            if (r.mState == EContactState::Idle)
                continue;
            if (!(x[f] > 0.0))
            {
                r.mState = EContactState::Idle;
                x.segment(f, r.mFriction ? 3 : 1).setZero();
                changed = true;
            }
            else if (r.mState == EContactState::Sticking &&
                     !(x.segment<2>(f + 1).norm() <= ConeRadius(row.mFriction, x[f])))
            {
                // intent: Newton's next start on the rim, where the sliding state holds
                r.mState = EContactState::Sliding;
                x.segment<2>(f + 1) *= ConeRadius(row.mFriction, x[f]) / x.segment<2>(f + 1).norm();
                changed = true;
            }
            else if (r.mState == EContactState::Sliding && !(velocity.segment<2>(f + 1).norm() > 0.0))
            {
                r.mState = EContactState::Sticking;
                changed = true;
            }
        }
        // intent: states that hold end the search, converged or at a least-squares point of states a little
        // inconsistent (redundant sticking contacts: judged below by how close it comes to Coulomb's
        // conditions); further off, the pushing contact whose velocity passes its target furthest lets go
        // (it pushes apart more than it must: a piece on more ground contacts than its velocities need)
        if (!changed && !converged)
        {
            candidate = candidate_rows();
            merit = MeritOfRows(inPair, candidate);
            if (merit <= cSettledMerit * inSpeedScale)
                least_squares = true;
            else
            {
                SubspaceRow* release = nullptr;
                double furthest = 0.0;
                for (SubspaceRow& r : rows)
                {
                    const double passed = velocity[r.mFirst] - before[r.mFirst] - ioRows[r.mRow].mTarget;
                    if (r.mState != EContactState::Idle && passed > furthest)
                    {
                        furthest = passed;
                        release = &r;
                    }
                }
                // intent: one contact let go per step: a crowd that no single release makes consistent
                // costs Gauss-Seidel's steps one more Newton solve, not one per contact
                if (release == nullptr || released)
                    return ESubspaceOutcome::Refused;
                released = true;
                release->mState = EContactState::Idle;
                x.segment(release->mFirst, release->mFriction ? 3 : 1).setZero();
                changed = true;
            }
        }
        if (!changed)
            break;
        if (attempt == cMaxStateChanges)
            return ESubspaceOutcome::Refused;
    }

    // intent: the candidate impulses, kept only where they meet Coulomb's conditions better
    // intent: a least-squares point's candidate and merit were worked out above, from the same x
    if (!least_squares)
    {
        candidate = candidate_rows();
        merit = MeritOfRows(inPair, candidate);
    }
    if (!(merit < MeritOfRows(inPair, ioRows)) || (least_squares && !(merit <= cSettledMerit * inSpeedScale)))
        return ESubspaceOutcome::Refused;
    ioRows = std::move(candidate);
    return least_squares ? ESubspaceOutcome::Settled : ESubspaceOutcome::Kept;
}

} // namespace crumple::plugin
