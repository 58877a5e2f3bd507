// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// The joint friction solve's building blocks against independent answers: the least-energy impulse in a disc
// (LeastEnergyInDisc) against a search over the rim's angle, and the sweeps' 12-vector form of a contact
// axis (SweepAxis) against the 3-vector lever-arm arithmetic (VelocityChange) it replaces.
#include "FrictionContactRow.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <random>

using namespace crumple;
using namespace crumple::plugin;

namespace
{

// The energy the disc step minimizes: 1/2 t^T M t + t^T c.
double DiscEnergy(const Eigen::Matrix2d& inResponse, const Eigen::Vector2d& inSlip,
                  const Eigen::Vector2d& inT)
{
    return 0.5 * inT.dot(inResponse * inT) + inT.dot(inSlip);
}

// The rim's minimizer found without the secular equation: the energy at t = r (cos a, sin a) sampled at 3,600
// angles, the best refined by golden-section search over its neighbours' interval (the energy along the rim
// is smooth and, between neighbouring samples this close, unimodal), then by Newton's method on the angle.
Eigen::Vector2d RimMinimumBySearch(const Eigen::Matrix2d& inResponse, const Eigen::Vector2d& inSlip,
                                   double inRadius)
{
    const auto at = [&](double inAngle) -> Eigen::Vector2d
    { return inRadius * Eigen::Vector2d(std::cos(inAngle), std::sin(inAngle)); };
    const auto energy = [&](double inAngle) { return DiscEnergy(inResponse, inSlip, at(inAngle)); };
    constexpr int cSamples = 3600;
    const double step = 2.0 * std::numbers::pi / cSamples;
    int best = 0;
    for (int k = 1; k < cSamples; ++k)
        if (energy(k * step) < energy(best * step))
            best = k;
    double low = (best - 1) * step, high = (best + 1) * step;
    const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
    for (int iteration = 0; iteration < 200 && high - low > 1.0e-15; ++iteration)
    {
        const double left = high - golden * (high - low), right = low + golden * (high - low);
        if (energy(left) < energy(right))
            high = right;
        else
            low = left;
    }
    // intent: then Newton's method on the energy's derivative along the rim, in long double, from there: the
    // search alone stops where the flat rim's energies differ by round-off (1e-7 to 1e-6 r)
    using Real = long double;
    const Real r = inRadius, m00 = inResponse(0, 0), m01 = inResponse(0, 1), m11 = inResponse(1, 1);
    const Real c0 = inSlip.x(), c1 = inSlip.y();
    Real angle = 0.5L * (low + high);
    for (int iteration = 0; iteration < 50; ++iteration)
    {
        const Real cs = std::cos(angle), sn = std::sin(angle);
        // f(a) = r^2/2 u^T M u + r c^T u, u = (cos a, sin a)
        const Real first =
            r * r * ((m11 - m00) * sn * cs + m01 * (cs * cs - sn * sn)) + r * (-c0 * sn + c1 * cs);
        const Real second =
            r * r * ((m11 - m00) * (cs * cs - sn * sn) - 4.0L * m01 * sn * cs) - r * (c0 * cs + c1 * sn);
        if (!(second > 0.0L))
            break;
        angle -= first / second;
    }
    return at(static_cast<double>(angle));
}

// A random symmetric positive definite 2x2 with eigenvalues between inLow and inHigh (s/kg).
Eigen::Matrix2d RandomResponse(std::mt19937& ioRandom, double inLow, double inHigh)
{
    std::uniform_real_distribution<double> exponent(std::log10(inLow), std::log10(inHigh)),
        angle(0.0, std::numbers::pi);
    const double a = angle(ioRandom);
    Eigen::Matrix2d rotation;
    rotation << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
    const Eigen::Vector2d values(std::pow(10.0, exponent(ioRandom)), std::pow(10.0, exponent(ioRandom)));
    return rotation * values.asDiagonal() * rotation.transpose();
}

} // namespace

TEST_CASE("The least-energy impulse in a disc: inside it the free answer, on its rim the searched minimum",
          "[plugin]")
{
    std::mt19937 random(2026);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), fraction(0.01, 0.99);
    int inside = 0, on_rim = 0;
    for (int trial = 0; trial < 2000; ++trial)
    {
        // intent: responses isotropic to 1e6 apart, slips of any direction and size
        const Eigen::Matrix2d response =
            trial % 10 == 0 ? Eigen::Matrix2d::Identity() * 2.0e-3 : RandomResponse(random, 1.0e-5, 10.0);
        // intent: half the slips uniform, half made from a free answer of any direction (uniform slips give a
        // free answer along M's weak axis nearly always, hiding errors along its strong one)
        const Eigen::Vector2d slip =
            trial % 2 == 0 ? Eigen::Vector2d(Eigen::Vector2d(unit(random), unit(random)) *
                                             std::pow(10.0, 2.0 * unit(random)))
                           : Eigen::Vector2d(-(response * Eigen::Vector2d(unit(random), unit(random))) *
                                             std::pow(10.0, 2.0 * unit(random)));
        // intent: the free answer by another factorisation; its round-off grows with M's condition number
        const Eigen::Vector2d free = response.ldlt().solve(-slip);
        const Eigen::Vector2d eigenvalues =
            Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(response).eigenvalues();
        const double condition = eigenvalues.maxCoeff() / eigenvalues.minCoeff();
        // intent: radii both above and below the free answer's length
        const double radius = free.norm() * (trial % 3 == 0 ? 1.0 / fraction(random) : fraction(random));
        const Eigen::Vector2d t = LeastEnergyInDisc(response).Solve(slip, radius);
        INFO("trial " << trial);
        if (radius >= free.norm())
        {
            ++inside;
            CHECK((t - free).norm() <= 1.0e-14 * condition * free.norm());
            continue;
        }
        ++on_rim;
        CHECK(std::abs(t.norm() - radius) <= 1.0e-14 * radius);
        const Eigen::Vector2d searched = RimMinimumBySearch(response, slip, radius);
        CHECK((t - searched).norm() <= 1.0e-11 * radius);
        // intent: no point of the rim does better (to the round-off of the energy's terms), and the slip left
        // points against the impulse (maximal dissipation: M t + c = -lambda t, lambda >= 0)
        // intent: M t's round-off is |M| |t| eps, far above |M t| eps where M is ill-conditioned
        const double scale = (eigenvalues.maxCoeff() * radius + slip.norm()) * radius;
        CHECK(DiscEnergy(response, slip, t) <= DiscEnergy(response, slip, searched) + 1.0e-13 * scale);
        const Eigen::Vector2d slip_after = response * t + slip;
        CHECK(std::abs(slip_after.x() * t.y() - slip_after.y() * t.x()) <= 1.0e-12 * scale);
        CHECK(slip_after.dot(t) <= 0.0);
    }
    CHECK(inside > 500);
    CHECK(on_rim > 1000);
    // intent: isotropic responses have the closed form t = -r c / |c| on the rim
    const Eigen::Vector2d slip(0.3, -0.4);
    const Eigen::Vector2d t = LeastEnergyInDisc(Eigen::Matrix2d::Identity() * 5.0e-4).Solve(slip, 2.0);
    CHECK((t + 2.0 * slip / slip.norm()).norm() <= 4.0e-16 * 2.0);
    CHECK(LeastEnergyInDisc(Eigen::Matrix2d::Identity()).Solve(slip, 0.0) == Eigen::Vector2d::Zero());
}

TEST_CASE("A contact axis in the sweeps' 12-vector form sees and moves what the lever-arm arithmetic does",
          "[plugin]")
{
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), mass(0.1, 100.0);
    const auto random_vector = [&] { return Vec3(unit(random), unit(random), unit(random)); };
    const auto random_inertia = [&]
    {
        const Mat3 a = Mat3::Random() + 2.0 * Mat3::Identity();
        return Mat3(a * a.transpose());
    };
    const auto as_pair_vector = [](const VelocityChange& inChange)
    {
        PairVector v;
        v << inChange.mLinearA, inChange.mAngularA, inChange.mLinearB, inChange.mAngularB;
        return v;
    };
    for (int trial = 0; trial < 200; ++trial)
    {
        BodyState a, b;
        // intent: B static or kinematic in some pairs, A kinematic in others (zero inverse mass and inertia)
        a.mMotionType = trial % 4 == 2 ? EMotionType::Kinematic : EMotionType::Dynamic;
        b.mMotionType = trial % 4 == 0 ? EMotionType::Static
                                       : (trial % 8 == 1 ? EMotionType::Kinematic : EMotionType::Dynamic);
        a.mMass = mass(random);
        b.mMass = mass(random);
        a.mInverseInertiaWorld = random_inertia();
        b.mInverseInertiaWorld = random_inertia();
        a.mCenterOfMass = random_vector();
        b.mCenterOfMass = random_vector();
        const PairInverseMass pair(a, b);
        const LeverArms arms(a, b, 3.0 * random_vector());
        const Vec3 axis = random_vector().normalized();
        const SweepAxis sweep(pair, arms, axis);
        // intent: an impulse along the axis, and a velocity change made by other impulses elsewhere
        const double p = 50.0 * unit(random);
        VelocityChange applied;
        applied.Apply(pair, arms, p * axis);
        const PairVector moved = p * sweep.mMoves;
        INFO("trial " << trial);
        CHECK((moved - as_pair_vector(applied)).norm() <= 1.0e-14 * moved.norm());
        VelocityChange other;
        for (int k = 0; k < 3; ++k)
            other.Apply(pair, LeverArms(a, b, 3.0 * random_vector()), 10.0 * random_vector());
        const double seen = sweep.mSees.dot(as_pair_vector(other)), expected = axis.dot(other.At(arms));
        CHECK(std::abs(seen - expected) <=
              1.0e-13 * as_pair_vector(other).norm() * (1.0 + 2.0 * 3.0 * std::sqrt(3.0)));
        if (b.mMotionType == EMotionType::Static)
            CHECK(sweep.mMoves.tail<6>().isZero(0.0));
        if (b.mMotionType == EMotionType::Kinematic)
            CHECK(sweep.mMoves.tail<6>().isZero(0.0));
        if (a.mMotionType == EMotionType::Kinematic)
            CHECK(sweep.mMoves.head<6>().isZero(0.0));
    }
}
