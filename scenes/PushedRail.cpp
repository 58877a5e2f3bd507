// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "PushedRail.h"

#include <crumple/fem/PropMaterialPreset.h>
#include <crumple/fem/TetFence.h>

#include <cmath>

namespace crumple::common
{

PushedRail MakePushedRail()
{
    fem::TetFenceSettings fence;
    fence.mLength = 2.0;
    fence.mHeight = 1.0;
    fence.mThickness = 0.05;
    fence.mCellSize = 0.025;
    fence.mPostSpacing = 2.0;
    fence.mRailCount = 1;
    fem::TetFence made = fem::MakeTetFence(fence).Get();
    return {std::move(made.mMesh), fem::MakePropMaterialPreset(fem::EPropMaterial::Wood).Get().mMaterial,
            std::move(made.mGroundNodes)};
}

std::vector<int> PushedRailNodes(std::span<const Vec3> inPositions)
{
    std::vector<int> struck;
    for (std::size_t node = 0; node < inPositions.size(); ++node)
        if (inPositions[node].y() == 0.0 && std::abs(inPositions[node].x() - 1.0) < 0.15)
            struck.push_back(static_cast<int>(node));
    return struck;
}

Result<fem::TetSolver> MakePushedRailSolver(const fem::TetSolverSettings& inSettings)
{
    const PushedRail rail = MakePushedRail();
    Result<fem::TetSolver> solver = fem::TetSolver::Create(rail.mMesh, rail.mMaterial, inSettings);
    if (!solver)
        return solver;
    if (Status anchored = solver.Get().SetNodesFixed(rail.mAnchoredNodes, true); !anchored)
        return anchored.GetError();
    return solver;
}

} // namespace crumple::common
