// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/fem/TetSolver.h>

namespace crumple::test
{

/// Linear momentum of a prop, sum of m v over its nodes (kg m/s, the solver's frame).
inline Vec3 PropMomentum(const fem::TetSolver& inSolver)
{
    Vec3 momentum = Vec3::Zero();
    for (int node = 0; node < inSolver.GetNodeCount(); ++node)
        momentum += inSolver.GetMasses()[node] * inSolver.GetVelocities()[node];
    return momentum;
}

} // namespace crumple::test
