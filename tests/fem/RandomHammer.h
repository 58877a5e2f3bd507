// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/fem/TetSolver.h>

#include "DrawVec3.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <random>

namespace crumple::test
{

/// The FEM stress tests' blows, seeded: an impulse of 1e-3 ... 1e5 N s (log-uniform) on a random node in a
/// random direction, and step lengths of 1/240 ... 1/30 s, drawn in the order the tests were measured with
/// (node, magnitude, direction; then the step).
class RandomHammer
{
  public:
    explicit RandomHammer(std::uint32_t inSeed) : mRandom(inSeed) {}

    /// Strikes one random node of ioSolver.
    void Strike(fem::TetSolver& ioSolver)
    {
        const int node = static_cast<int>(mRandom() % static_cast<std::uint32_t>(ioSolver.GetNodeCount()));
        const double magnitude = std::pow(10.0, -3.0 + 8.0 * mUnit(mRandom));
        const Vec3 direction = common::DrawVec3([&] { return mNormal(mRandom); }).normalized();
        REQUIRE(ioSolver.ApplyImpulse(node, magnitude * direction).IsValid());
    }

    /// A step length in [1/240, 1/30] s.
    double StepLength() { return 1.0 / 240.0 + mUnit(mRandom) * (1.0 / 30.0 - 1.0 / 240.0); }

  private:
    std::mt19937 mRandom;
    std::uniform_real_distribution<double> mUnit{0.0, 1.0};
    std::normal_distribution<double> mNormal;
};

} // namespace crumple::test
