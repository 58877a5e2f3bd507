// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <cstdint>

namespace crumple::fem
{

/// Preconditioner of the conjugate-gradient solves of TetSolver's implicit steps and SolveStatic().
enum class EImplicitPreconditioner : std::uint8_t
{
    /// The rest system a M + b K0 factored once (sparse Cholesky) and reused while the connectivity, the
    /// anchors and the time step stay the same, rotated per node for the corotated model: 1 to 10 iterations
    /// per solve for any stiffness. Costs a factorisation on the first step and after each fracture,
    /// SetNodeFixed() or change of time step, and the factor's memory (a few times the mesh's for props of
    /// 10^3 to 10^4 tetrahedra). A breakable material also keeps each element's rest stiffness between
    /// factorisations (about 800 bytes per element), so refactoring after a crack does not recompute it.
    /// Falls back to BlockJacobi for a solve it cannot factor (a static solve whose anchors leave the body
    /// free to move). On the GPU (gpu::GpuTetSolver), whose solves cannot run sequential triangular solves,
    /// the rest system enters instead through a coarse correction on the rigid modes of node aggregates
    /// (TetCoarseSpace), built on the first implicit step and after each crack, anchor or time-step change
    /// and turned with its aggregates before a step that follows a solve longer than mFactorRefreshIterations
    /// (the default 0: every step but the first).
    RestFactorization,
    /// Block Jacobi plus a coarse correction on the six rigid modes: no setup and no memory, but the
    /// iteration count grows with the stiffness and the mesh size (hundreds for steel). On the GPU, block
    /// Jacobi alone.
    BlockJacobi,
};

/// Short name of an EImplicitPreconditioner, for messages.
CRUMPLE_API const char* ToString(EImplicitPreconditioner inPreconditioner);

} // namespace crumple::fem
