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
            const double derivative_of_norm =
                -(c.array().square() / (d.array() + lambda).cube()).sum() / norm;
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
};

// The velocity change that inRows' impulses make together.
inline VelocityChange ChangeOfRows(const PairInverseMass& inPair, const std::vector<ContactRow>& inRows)
{
    VelocityChange change;
    for (const ContactRow& row : inRows)
        change.Apply(inPair, row.mArms, row.mNormalImpulse * row.mNormal + row.mFrictionImpulse);
    return change;
}

} // namespace crumple::plugin
