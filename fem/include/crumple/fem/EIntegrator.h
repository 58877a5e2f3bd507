// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <cstdint>

namespace crumple::fem
{

/// Time integration of a TetSolver.
enum class EIntegrator : std::uint8_t
{
    /// Explicit symplectic (semi-implicit) Euler, as in the paper (v += dt M^-1 f; x += dt v), sub-stepped
    /// automatically so that every sub-step is below the stable limit from StableTimeStep(). Cheap per
    /// sub-step, conserves energy well when undamped, but stiff materials need many sub-steps (steel cubes of
    /// 0.1 m: about 5,000 per 1/60 s frame).
    SymplecticEuler,
    /// Implicit (backward) Euler: Newton iterations on M (v1 - v0) = h f(x0 + h v1), each a matrix-free
    /// preconditioned conjugate-gradient solve of ((1 + h alpha) M + (h^2 + h beta) K) dv = r (Baraff &
    /// Witkin 1998 is the first iteration), with the rotated stiffness R K0 R^T for the corotated model.
    /// Stable at game time steps for any stiffness, numerically damped (energy decays; a spin slows by
    /// 1 / sqrt(1 + (omega h)^2) per step): the default for game steps and stiff materials.
    ImplicitEuler,
};

/// Short name of an EIntegrator, for messages.
CRUMPLE_API const char* ToString(EIntegrator inIntegrator);

} // namespace crumple::fem
