// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <memory>

namespace crumple::fem
{

struct TetSolveScratch; // private to the solver (src/TetSolveScratch.h)

/// Where a TetSolver keeps the scratch of its linear solves and its factored rest system: an implementation
/// detail of TetSolver, public only because the solver holds it by value. Created on first use and reused,
/// so a step allocates nothing once sized. A copy starts empty and builds its own on its first solve, which
/// gives the same factor bit for bit (it is a function of the mesh, the anchors and the step only): copies
/// stay independent and deterministic.
class CRUMPLE_API TetSolverWorkspace
{
public:
    TetSolverWorkspace();
    ~TetSolverWorkspace();
    TetSolverWorkspace(const TetSolverWorkspace& inOther);
    TetSolverWorkspace(TetSolverWorkspace&& inOther) noexcept;
    TetSolverWorkspace& operator=(const TetSolverWorkspace& inOther);
    TetSolverWorkspace& operator=(TetSolverWorkspace&& inOther) noexcept;

    /// The scratch, created on first access
    TetSolveScratch& Get();
    /// The scratch, or nullptr before its first access
    const TetSolveScratch* Find() const { return mValue.get(); }

  private:
    std::unique_ptr<TetSolveScratch> mValue;
};

} // namespace crumple::fem
