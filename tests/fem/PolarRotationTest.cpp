// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/PolarRotation.h>

#include "DrawVec3.h"

#include <catch2/catch.hpp>

#include <cstring>
#include <random>

using namespace crumple;
using namespace crumple::fem;

namespace
{

Quat RandomRotation(std::mt19937& ioRandom)
{
    std::normal_distribution<double> normal;
    // sequenced, last argument first (common::DrawVec3)
    const double z = normal(ioRandom), y = normal(ioRandom), x = normal(ioRandom), w = normal(ioRandom);
    return Quat(w, x, y, z).normalized();
}

// Deviation of a matrix from a proper rotation: |R^T R - I| + |det R - 1|.
double RotationError(const Mat3& inR)
{
    return (inR.transpose() * inR - Mat3::Identity()).norm() + std::abs(inR.determinant() - 1.0);
}

} // namespace

TEST_CASE("PolarRotation recovers R from F = R S from a cold start", "[fem]")
{
    std::mt19937 random(2026);
    std::uniform_real_distribution<double> stretch(0.5, 2.0);
    int worst_iterations = 0;
    for (int trial = 0; trial < 200; ++trial)
    {
        // Symmetric positive definite stretch with principal values in [0.5, 2] along random axes.
        const Mat3 axes = RandomRotation(random).toRotationMatrix();
        const Mat3 s =
            axes * common::DrawVec3([&] { return stretch(random); }).asDiagonal() * axes.transpose();
        const Quat r = RandomRotation(random);
        const Mat3 f = r.toRotationMatrix() * s;

        const Mat3 found = PolarRotation(f, Quat::Identity()).toRotationMatrix();
        CHECK((found - r.toRotationMatrix()).norm() < 1e-11);

        // Iterations needed (Newton: quadratic near the answer).
        for (int iterations = 1; iterations <= 40; ++iterations)
            if ((PolarRotation(f, Quat::Identity(), iterations).toRotationMatrix() - r.toRotationMatrix())
                    .norm() < 1e-11)
            {
                worst_iterations = std::max(worst_iterations, iterations);
                break;
            }
    }
    WARN("PolarRotation from identity: at most " << worst_iterations << " iterations for 200 random F = R S");
    CHECK(worst_iterations <= 20);
}

TEST_CASE("PolarRotation converges in one or two steps from a nearby warm start", "[fem]")
{
    std::mt19937 random(7);
    for (int trial = 0; trial < 50; ++trial)
    {
        const Quat r = RandomRotation(random);
        const Mat3 noise = Mat3::Random();
        const Mat3 s = Mat3::Identity() + 0.01 * (noise + noise.transpose());
        const Mat3 f = r.toRotationMatrix() * s;
        const Quat previous = r * Quat(Eigen::AngleAxisd(0.02, Vec3(1, -2, 0.5).normalized()));
        CHECK((PolarRotation(f, previous, 2).toRotationMatrix() - r.toRotationMatrix()).norm() < 1e-12);
    }
}

TEST_CASE("PolarRotation's matrix is the returned quaternion's, bit for bit, from any start", "[fem]")
{
    // The element passes take R from here instead of turning the quaternion into a matrix again: it must be
    // the same numbers whether the iteration ended on an update (a cold or far start) or without one (a
    // start at the answer).
    std::mt19937 random(11);
    int ended_on_update = 0, ended_without = 0;
    for (int trial = 0; trial < 200; ++trial)
    {
        const Quat r = RandomRotation(random);
        const Mat3 noise = Mat3::Random();
        const Mat3 f = r.toRotationMatrix() * (Mat3::Identity() + 0.05 * (noise + noise.transpose()));
        const Quat cold = PolarRotation(f, Quat::Identity());
        for (const Quat& start : {Quat::Identity(), cold, PolarRotation(f, cold)})
        {
            Mat3 matrix;
            const Quat q = PolarRotation(f, start, matrix);
            const Mat3 expected = q.toRotationMatrix();
            CHECK(std::memcmp(matrix.data(), expected.data(), sizeof(Mat3)) == 0);
            CHECK(q.coeffs() == PolarRotation(f, start).coeffs());
            (q.coeffs() == start.normalized().coeffs() ? ended_without : ended_on_update) += 1;
        }
    }
    // Both ways of ending were met (guards against a vacuous pass).
    CHECK(ended_on_update > 0);
    CHECK(ended_without > 0);
}

TEST_CASE("PolarRotation of rigid rotations up to 179 degrees is exact", "[fem]")
{
    for (double degrees : {1.0, 45.0, 90.0, 135.0, 179.0})
    {
        const Mat3 r =
            Eigen::AngleAxisd(degrees * 3.14159265358979323846 / 180.0, Vec3(0.2, -1.0, 0.4).normalized())
                .toRotationMatrix();
        INFO(degrees << " degrees");
        CHECK((PolarRotation(r, Quat::Identity()).toRotationMatrix() - r).norm() < 1e-12);
    }
}

TEST_CASE("PolarRotation returns a proper rotation for inverted and degenerate F", "[fem]")
{
    const Mat3 reflection = Vec3(1.0, 1.0, -1.0).asDiagonal();
    const Mat3 flattened = Vec3(1.0, 1.0, 0.0).asDiagonal();
    Mat3 rank_one = Mat3::Zero();
    rank_one.col(0) = Vec3(1.0, 2.0, 3.0);
    const Mat3 inverted =
        Eigen::AngleAxisd(0.5, Vec3::UnitY()).toRotationMatrix() * Vec3(-0.3, 1.2, 0.8).asDiagonal();
    for (const Mat3& f : {reflection, flattened, rank_one, Mat3(Mat3::Zero()), inverted})
    {
        const Mat3 r = PolarRotation(f, Quat::Identity()).toRotationMatrix();
        CHECK(r.allFinite());
        CHECK(RotationError(r) < 1e-12);
    }
}
