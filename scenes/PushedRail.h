// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Result.h>
#include <crumple/fem/FemMaterialSettings.h>
#include <crumple/fem/TetMesh.h>
#include <crumple/fem/TetSolver.h>

#include <span>
#include <vector>

namespace crumple::common
{

/// A wooden fence rail pushed as a car pushes it, for the fracture convergence tests of the CPU and GPU
/// solvers: a 2 m fence (posts at its ends, one rail 0.1 m tall), 5 cm thick in cubes of 2.5 cm (two across),
/// of the wood preset, anchored at its base.
struct PushedRail
{
    fem::TetMesh mMesh;
    fem::FemMaterialSettings mMaterial;
    std::vector<int> mAnchoredNodes; ///< Mesh nodes at its base
};

/// The push: cPushSteps of the cPushedRailSteps steps of cPushedRailStep take an impulse each, shared by the
/// struck nodes, along +y.
constexpr int cPushedRailSteps = 12;
constexpr int cPushSteps = 4;
constexpr double cPushedRailStep = 1.0 / 120.0; ///< s

PushedRail MakePushedRail();

/// The struck nodes: those of the rail's front face (y = 0) within 0.15 m of its middle, read from a solver's
/// current positions (a breakable solver numbers its nodes after its first reconnection).
std::vector<int> PushedRailNodes(std::span<const Vec3> inPositions);

/// The pushed rail's CPU solver with inSettings, its base anchored (the struck nodes: PushedRailNodes()).
Result<fem::TetSolver> MakePushedRailSolver(const fem::TetSolverSettings& inSettings);

/// Before step inStep (0-based) of the push: inImpulse (N s) along +y shared by inStruck when inStep <
/// cPushSteps, else nothing. Works on any solver with ApplyImpulse(int, Vec3) (the CPU's and the GPU's).
template <class Solver>
Status PushRailBeforeStep(Solver& ioSolver, std::span<const int> inStruck, int inStep, double inImpulse)
{
    if (inStep >= cPushSteps)
        return Status::Ok();
    for (int node : inStruck)
        if (Status applied =
                ioSolver.ApplyImpulse(node, Vec3(0.0, inImpulse / static_cast<double>(inStruck.size()), 0.0));
            !applied)
            return applied;
    return Status::Ok();
}

} // namespace crumple::common
