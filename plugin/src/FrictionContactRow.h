// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

// The joint friction solve's contact rows, shared by its Gauss-Seidel sweeps (FrictionalImpulses.cpp) and its
// subspace step (FrictionSubspaceStep.cpp). Private to the plugin.

#include <crumple/plugin/BodyState.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <vector>

namespace crumple::plugin
{

// The radius of a contact's friction cone, mu j (N s): zero without a normal impulse, also for mu = +inf.
inline double ConeRadius(double inFriction, double inNormal)
{
    return inNormal > 0.0 ? inFriction * inNormal : 0.0;
}

// The pair's inverse masses and world inverse inertias (zero for a body that is not dynamic), read once per
// solve: every sweep applies impulses with them.
struct PairInverseMass
{
    double mMassA = 0.0, mMassB = 0.0;                       // 1/kg
    Mat3 mInertiaA = Mat3::Zero(), mInertiaB = Mat3::Zero(); // 1/(kg m^2), world frame

    PairInverseMass(const BodyState& inA, const BodyState& inB)
        : mMassA(inA.InverseMass()), mMassB(inB.InverseMass()), mInertiaA(inA.InverseInertia()),
          mInertiaB(inB.InverseInertia())
    {
    }
};

// A point's lever arms from the two centres of mass (m), world frame.
struct LeverArms
{
    Vec3 mA = Vec3::Zero(), mB = Vec3::Zero();

    LeverArms() = default;
    LeverArms(const BodyState& inA, const BodyState& inB, const Vec3& inPoint)
        : mA(inPoint - inA.mCenterOfMass), mB(inPoint - inB.mCenterOfMass)
    {
    }
};

// The pair's velocity changes from the impulses applied so far (the bodies' own velocities stay in their
// states).
struct VelocityChange
{
    Vec3 mLinearA = Vec3::Zero(), mAngularA = Vec3::Zero(), mLinearB = Vec3::Zero(), mAngularB = Vec3::Zero();

    // intent: impulse inImpulse on A at the point with lever arms inArms, its opposite on B
    void Apply(const PairInverseMass& inPair, const LeverArms& inArms, const Vec3& inImpulse)
    {
        mLinearA += inPair.mMassA * inImpulse;
        mAngularA += inPair.mInertiaA * inArms.mA.cross(inImpulse);
        mLinearB -= inPair.mMassB * inImpulse;
        mAngularB -= inPair.mInertiaB * inArms.mB.cross(inImpulse);
    }
    // intent: A's-minus-B's velocity change at the point with lever arms inArms
    Vec3 At(const LeverArms& inArms) const
    {
        return mLinearA + mAngularA.cross(inArms.mA) - mLinearB - mAngularB.cross(inArms.mB);
    }
};

// The impulse in a disc of radius r that leaves the least kinetic energy: t minimizing 1/2 t^T M t + t^T c
// over |t| <= r, with c the slip the other impulses leave (Coulomb friction by the principle of maximal
// dissipation: the slip after, c + M t, is then zero or points against t). Inside the disc t = -M^-1 c; on
// its rim t = -(M + lambda I)^-1 c with lambda > 0 the root of 1/|t(lambda)| = 1/r, found by Newton's method
// on that nearly linear secular function (More and Sorensen 1983, the trust-region subproblem), in M's
// eigenbasis. M is positive definite (ContactRow leaves friction out where it is not); its inverse and
// eigenbasis are worked out once per contact, as every sweep solves with the same M.
class LeastEnergyInDisc
{
  public:
    // A Newton step of at most this fraction of lambda + d_min is the last one: t moves with lambda on the
    // scale of lambda + d_min (the nearest pole of t(lambda)), and the next step would be of the order of the
    // square (quadratic convergence). Scaled by lambda + d_max instead (6153452) the answer's direction was
    // off by up to 17 degrees where M was 1e8 anisotropic (found by a review against a quad-precision
    // answer).
    static constexpr double cLastStep = 1.0e-8;

    LeastEnergyInDisc() = default;
    explicit LeastEnergyInDisc(const Eigen::Matrix2d& inResponse) : mInverse(inResponse.inverse())
    {
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(inResponse);
        mValues = eigen.eigenvalues();
        mVectors = eigen.eigenvectors();
    }

    Eigen::Vector2d Solve(const Eigen::Vector2d& inSlip, double inRadius) const
    {
        if (!(inRadius > 0.0))
            return Eigen::Vector2d::Zero();
        const Eigen::Vector2d free = -(mInverse * inSlip);
        if (!(free.squaredNorm() > inRadius * inRadius))
            return free;
        const Eigen::Vector2d& d = mValues;
        const Eigen::Vector2d c = mVectors.transpose() * inSlip;
        // |t(lambda)|^2 = sum c_k^2 / (d_k + lambda)^2; phi(lambda) = 1/|t| - 1/r is concave and rises from
        // phi(0) < 0, so Newton's iterates from a point where phi <= 0 rise to the root without passing it.
        // |t(lambda)| >= |c| / (d_max + lambda) makes |c| / r - d_max such a point: the root itself where M
        // is a multiple of the identity, and a few iterations short of it otherwise.
        const double inverse_radius = 1.0 / inRadius;
        double lambda = std::max(c.norm() * inverse_radius - d.maxCoeff(), 0.0);
        for (int iteration = 0; iteration < 100; ++iteration)
        {
            // intent: with u_k = 1/(d_k + lambda): t_k = c_k u_k, |t|' = -sum t_k^2 u_k / |t|, and the Newton
            // step -phi / phi' = -phi |t|^3 / sum t_k^2 u_k
            const Eigen::Array2d u = 1.0 / (d.array() + lambda);
            const Eigen::Array2d t = c.array() * u;
            const double norm2 = t.square().sum();
            const double norm = std::sqrt(norm2);
            const double phi = 1.0 / norm - inverse_radius;
            const double next = lambda - phi * norm2 * norm / (t.square() * u).sum();
            if (!(next > lambda))
                break; // at the root to round-off
            // intent: a step this small leaves an error of the order of its square (Newton converges
            // quadratically here), far below what the rim's direction can show: taken without another
            // evaluation (FrictionSweepTest: the slip left against t to 1e-12 of its terms, M up to 1e6
            // anisotropic)
            const bool last = next - lambda <= cLastStep * (lambda + d.minCoeff());
            lambda = next;
            if (last)
                break;
        }
        Eigen::Vector2d t = -(mVectors * (c.array() / (d.array() + lambda)).matrix());
        // intent: on the rim exactly, whatever the last Newton step left
        t *= inRadius / t.norm();
        return t;
    }

  private:
    Eigen::Matrix2d mInverse = Eigen::Matrix2d::Zero();
    Eigen::Vector2d mValues = Eigen::Vector2d::Zero();  // M's eigenvalues, ascending
    Eigen::Matrix2d mVectors = Eigen::Matrix2d::Zero(); // its eigenvectors, as columns
};

// The pair's velocity change as one vector, (v_A, w_A, v_B, w_B) (m/s, rad/s): what the sweeps update.
using PairVector = Eigen::Matrix<double, 12, 1>;

// One axis of a contact (its normal or a tangent) as the sweeps see it: an impulse p along the axis on A (its
// opposite on B) changes the pair's velocity by p mMoves, and the change of A's-minus-B's velocity at the
// point along the axis is mSees . change (the 3-vector forms' lever-arm cross products worked out once).
struct SweepAxis
{
    PairVector mSees = PairVector::Zero();
    PairVector mMoves = PairVector::Zero();

    SweepAxis() = default;
    SweepAxis(const PairInverseMass& inPair, const LeverArms& inArms, const Vec3& inAxis)
    {
        // intent: a . (w x r) = w . (r x a)
        const Vec3 turn_a = inArms.mA.cross(inAxis), turn_b = inArms.mB.cross(inAxis);
        mSees << inAxis, turn_a, -inAxis, -turn_b;
        mMoves << inPair.mMassA * inAxis, inPair.mInertiaA * turn_a, -inPair.mMassB * inAxis,
            -(inPair.mInertiaB * turn_b);
    }
};

// One contact in the joint solve: its normal row and its friction block.
struct ContactRow
{
    Vec3 mNormal = Vec3::UnitZ(), mTangent1 = Vec3::UnitX(), mTangent2 = Vec3::UnitY();
    LeverArms mArms;                     // the point's lever arms
    Vec3 mVelocityBefore = Vec3::Zero(); // A's-minus-B's velocity at the point before any impulse (m/s)
    double mNormalResponse = 0.0; // n . W n (s/kg); zero: nothing can move the contact
    Eigen::Matrix2d mTangentResponse =
        Eigen::Matrix2d::Zero(); // T^T W T, symmetric positive definite or zero
    LeastEnergyInDisc mDisc;     // its friction step, where mFriction > 0
    double mTarget = 0.0;        // the least normal velocity change the contact must take (m/s)
    double mFriction = 0.0;      // mu; zero where friction cannot act
    double mNormalImpulse = 0.0;
    Vec3 mFrictionImpulse = Vec3::Zero();
    SweepAxis mSweepNormal, mSweepTangent1, mSweepTangent2;           // the sweeps' forms of the three axes
    Eigen::Vector2d mTangentVelocityBefore = Eigen::Vector2d::Zero(); // mVelocityBefore along the tangents
};

// The pair's velocity change that inRows' impulses make together, as the sweeps hold it.
inline PairVector SweepChangeOfRows(const std::vector<ContactRow>& inRows)
{
    PairVector change = PairVector::Zero();
    for (const ContactRow& row : inRows)
        change += row.mNormalImpulse * row.mSweepNormal.mMoves +
                  row.mTangent1.dot(row.mFrictionImpulse) * row.mSweepTangent1.mMoves +
                  row.mTangent2.dot(row.mFrictionImpulse) * row.mSweepTangent2.mMoves;
    return change;
}

// The velocity change that inRows' impulses make together.
inline VelocityChange ChangeOfRows(const PairInverseMass& inPair, const std::vector<ContactRow>& inRows)
{
    VelocityChange change;
    for (const ContactRow& row : inRows)
        change.Apply(inPair, row.mArms, row.mNormalImpulse * row.mNormal + row.mFrictionImpulse);
    return change;
}

} // namespace crumple::plugin
