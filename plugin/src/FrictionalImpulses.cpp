// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/base/Assert.h>
#include <crumple/plugin/FrictionalImpulses.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>

namespace crumple::plugin
{

namespace
{

// Sweeps of the joint solve: it stops as soon as a sweep changes no contact point's velocity by more than
// cRelativeChange of the largest approach speed. Measured: 18-170 sweeps on the engine crash scenes
// (CrossEngineTest) and a box's four corners; crowds of redundant random contacts can crawl, and the bound
// ends those. A 1e-9 stop took a quarter less time on crumple-bench's sliding box (errors 1e-10), but moved
// the Bullet fence drive-through's outcome by 3 % of the car's speed loss (PropFenceTest's converged case):
// that coupling amplifies even such differences.
constexpr int cMaxSweeps = 1000;
constexpr double cRelativeChange = 1.0e-12;

// The radius of a contact's friction cone, mu j (N s): zero without a normal impulse, also for mu = +inf.
double ConeRadius(double inFriction, double inNormal)
{
    return inNormal > 0.0 ? inFriction * inNormal : 0.0;
}

// The pair's velocity changes from the impulses applied so far (the bodies' own velocities stay in their states).
struct VelocityChange
{
    Vec3 mLinearA = Vec3::Zero(), mAngularA = Vec3::Zero(), mLinearB = Vec3::Zero(), mAngularB = Vec3::Zero();

    // intent: impulse inImpulse on A at inPoint, its opposite on B
    void Apply(const BodyState& inA, const BodyState& inB, const Vec3& inPoint, const Vec3& inImpulse)
    {
        mLinearA += inA.InverseMass() * inImpulse;
        mAngularA += inA.InverseInertia() * (inPoint - inA.mCenterOfMass).cross(inImpulse);
        mLinearB -= inB.InverseMass() * inImpulse;
        mAngularB -= inB.InverseInertia() * (inPoint - inB.mCenterOfMass).cross(inImpulse);
    }
    // intent: A's-minus-B's velocity change at inPoint
    Vec3 At(const BodyState& inA, const BodyState& inB, const Vec3& inPoint) const
    {
        return mLinearA + mAngularA.cross(inPoint - inA.mCenterOfMass) - mLinearB - mAngularB.cross(inPoint - inB.mCenterOfMass);
    }
};

// Change of A's-minus-B's velocity at inPoint per unit impulse vector at the same point (s/kg), 3 by 3:
// W = (1/m_A + 1/m_B) I - [r_A]x I_A^-1 [r_A]x - [r_B]x I_B^-1 [r_B]x.
Mat3 PointResponse(const BodyState& inA, const BodyState& inB, const Vec3& inPoint)
{
    Mat3 response;
    const Vec3 r_a = inPoint - inA.mCenterOfMass, r_b = inPoint - inB.mCenterOfMass;
    for (int k = 0; k < 3; ++k)
    {
        const Vec3 e = Vec3::Unit(k);
        response.col(k) = (inA.InverseMass() + inB.InverseMass()) * e + (inA.InverseInertia() * r_a.cross(e)).cross(r_a) +
                          (inB.InverseInertia() * r_b.cross(e)).cross(r_b);
    }
    return response;
}

// The impulse in a disc of radius r that leaves the least kinetic energy: t minimizing 1/2 t^T M t + t^T c
// over |t| <= r, with c the slip the other impulses leave (Coulomb friction by the principle of maximal
// dissipation: the slip after, c + M t, is then zero or points against t). Inside the disc t = -M^-1 c; on its
// rim t = -(M + lambda I)^-1 c with lambda > 0 the root of 1/|t(lambda)| = 1/r, found by Newton's method on
// that nearly linear secular function (More and Sorensen 1983, the trust-region subproblem), in M's
// eigenbasis. M is positive definite (ContactRow leaves friction out where it is not); its factor and
// eigenbasis are worked out once per contact, as every sweep solves with the same M.
class LeastEnergyInDisc
{
public:
    LeastEnergyInDisc() = default;
    explicit LeastEnergyInDisc(const Eigen::Matrix2d& inResponse) : mFactor(inResponse), mEigen(inResponse) {}

    Eigen::Vector2d Solve(const Eigen::Vector2d& inSlip, double inRadius) const
    {
        if (!(inRadius > 0.0))
            return Eigen::Vector2d::Zero();
        const Eigen::Vector2d free = -mFactor.solve(inSlip);
        if (!(free.norm() > inRadius))
            return free;
        const Eigen::Vector2d d = mEigen.eigenvalues();
        const Eigen::Vector2d c = mEigen.eigenvectors().transpose() * inSlip;
        // |t(lambda)|^2 = sum c_k^2 / (d_k + lambda)^2; phi(lambda) = 1/|t| - 1/r rises from phi(0) < 0.
        double lambda = 0.0;
        for (int iteration = 0; iteration < 100; ++iteration)
        {
            const Eigen::Vector2d t = (c.array() / (d.array() + lambda)).matrix();
            const double norm = t.norm();
            const double derivative_of_norm = -(c.array().square() / (d.array() + lambda).cube()).sum() / norm;
            const double phi = 1.0 / norm - 1.0 / inRadius;
            const double next = lambda - phi / (-derivative_of_norm / (norm * norm));
            if (!(next > lambda) || next - lambda <= 1.0e-15 * (lambda + d.maxCoeff()))
            {
                lambda = std::max(next, lambda);
                break;
            }
            lambda = next;
        }
        Eigen::Vector2d t = -(mEigen.eigenvectors() * (c.array() / (d.array() + lambda)).matrix());
        // intent: on the rim exactly, whatever the last Newton step left
        t *= inRadius / t.norm();
        return t;
    }

private:
    Eigen::LDLT<Eigen::Matrix2d> mFactor;
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> mEigen;
};

// One contact in the joint solve: its normal row and its friction block.
struct ContactRow
{
    Vec3 mPoint = Vec3::Zero(), mNormal = Vec3::UnitZ(), mTangent1 = Vec3::UnitX(), mTangent2 = Vec3::UnitY();
    double mNormalResponse = 0.0; // n . W n (s/kg); zero: nothing can move the contact
    Eigen::Matrix2d mTangentResponse = Eigen::Matrix2d::Zero(); // T^T W T, symmetric positive definite or zero
    LeastEnergyInDisc mDisc;                                    // its friction step, where mFriction > 0
    double mTarget = 0.0;   // the least normal velocity change the contact must take (m/s)
    double mFriction = 0.0; // mu; zero where friction cannot act
    double mNormalImpulse = 0.0;
    Vec3 mFrictionImpulse = Vec3::Zero();
};

// Projected Gauss-Seidel over every contact's normal row and friction block together, as engines solve
// contact (Bullet's sequential impulses, ODE's quick step), from ioRows' impulses: a normal impulse j >= 0
// takes the contact's normal velocity change to at least its target (zero impulse where it is more), then the
// friction impulse minimizes the kinetic energy over the cone mu j given every other impulse
// (LeastEnergyInDisc). Sweeps until no contact point's velocity changes by more than cRelativeChange of
// inSpeedScale (m/s) in a sweep.
void SolveJointly(const BodyState& inA, const BodyState& inB, double inSpeedScale, std::vector<ContactRow>& ioRows)
{
    VelocityChange change;
    for (const ContactRow& row : ioRows)
        change.Apply(inA, inB, row.mPoint, row.mNormalImpulse * row.mNormal + row.mFrictionImpulse);
    for (int sweep = 0; sweep < cMaxSweeps; ++sweep)
    {
        const VelocityChange start = change;
        for (ContactRow& row : ioRows)
        {
            if (row.mNormalResponse > 0.0)
            {
                const double residual = row.mNormal.dot(change.At(inA, inB, row.mPoint)) - row.mTarget;
                const double updated = std::max(0.0, row.mNormalImpulse - residual / row.mNormalResponse);
                change.Apply(inA, inB, row.mPoint, (updated - row.mNormalImpulse) * row.mNormal);
                row.mNormalImpulse = updated;
            }
            const double radius = ConeRadius(row.mFriction, row.mNormalImpulse);
            if (!(radius > 0.0) && row.mFrictionImpulse.isZero(0.0))
                continue;
            // intent: the slip without this row's own friction impulse, in its tangent basis
            const Vec3 velocity = inA.PointVelocity(row.mPoint) - inB.PointVelocity(row.mPoint) + change.At(inA, inB, row.mPoint);
            const Eigen::Vector2d own(row.mTangent1.dot(row.mFrictionImpulse), row.mTangent2.dot(row.mFrictionImpulse));
            const Eigen::Vector2d slip =
                Eigen::Vector2d(row.mTangent1.dot(velocity), row.mTangent2.dot(velocity)) - row.mTangentResponse * own;
            const Eigen::Vector2d t = row.mDisc.Solve(slip, radius);
            const Vec3 updated = t[0] * row.mTangent1 + t[1] * row.mTangent2;
            change.Apply(inA, inB, row.mPoint, updated - row.mFrictionImpulse);
            row.mFrictionImpulse = updated;
        }
        // intent: converged when the sweep moved no contact point's velocity: impulses may still trade along a
        // direction that moves nothing (two points on a line pushing along it), and need not settle
        double moved = 0.0;
        VelocityChange sweep_change = change;
        sweep_change.mLinearA -= start.mLinearA;
        sweep_change.mAngularA -= start.mAngularA;
        sweep_change.mLinearB -= start.mLinearB;
        sweep_change.mAngularB -= start.mAngularB;
        for (const ContactRow& row : ioRows)
            moved = std::max(moved, sweep_change.At(inA, inB, row.mPoint).norm());
        if (moved <= cRelativeChange * inSpeedScale)
            break;
    }
}

} // namespace

std::vector<ContactImpulse> FrictionalImpulses(const BodyState& inA, const BodyState& inB,
                                               std::span<const ImpulseContact> inContacts, double inRestitution,
                                               double inClosingSpeed)
{
    CRUMPLE_ASSERT(inRestitution >= 0.0 && inRestitution <= 1.0 && inClosingSpeed >= 0.0,
                   "FrictionalImpulses: restitution outside [0, 1] or a negative closing speed");
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
    std::vector<ContactRow> rows(inContacts.size());
    for (std::size_t i = 0; i < inContacts.size(); ++i)
    {
        const ImpulseContact& contact = inContacts[i];
        ContactRow& row = rows[i];
        row.mPoint = contact.mPoint;
        row.mNormal = contact.mNormal;
        row.mTangent1 = contact.mNormal.unitOrthogonal();
        row.mTangent2 = contact.mNormal.cross(row.mTangent1);
        const Mat3 response = PointResponse(inA, inB, row.mPoint);
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
        row.mNormalImpulse = impulses[i].mNormal;
    }
    double speed_scale = std::numeric_limits<double>::min();
    for (const ContactRow& row : rows)
        speed_scale = std::max(speed_scale, std::abs(row.mTarget));
    SolveJointly(inA, inB, speed_scale, rows);
    for (std::size_t i = 0; i < rows.size(); ++i)
        impulses[i] = {rows[i].mNormalImpulse, rows[i].mFrictionImpulse};
    return impulses;
}

} // namespace crumple::plugin
