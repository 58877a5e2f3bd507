// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/TetSolverWorkspace.h>

#include "TetSolveScratch.h"

namespace crumple::fem
{

TetSolverWorkspace::TetSolverWorkspace() = default;
TetSolverWorkspace::~TetSolverWorkspace() = default;
TetSolverWorkspace::TetSolverWorkspace(const TetSolverWorkspace&) {}
TetSolverWorkspace::TetSolverWorkspace(TetSolverWorkspace&& inOther) noexcept = default;

// A copy drops the scratch and the factor: the copy rebuilds the same factor when it needs it.
TetSolverWorkspace& TetSolverWorkspace::operator=(const TetSolverWorkspace&)
{
    mValue.reset();
    return *this;
}

TetSolverWorkspace& TetSolverWorkspace::operator=(TetSolverWorkspace&& inOther) noexcept = default;

TetSolveScratch& TetSolverWorkspace::Get()
{
    if (!mValue)
        mValue = std::make_unique<TetSolveScratch>();
    return *mValue;
}

} // namespace crumple::fem
