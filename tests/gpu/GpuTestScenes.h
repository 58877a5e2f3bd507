// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include "CantileverScene.h"

#include <crumple/fem/TetSolver.h>
#include <crumple/gpu/GpuTetSolver.h>

#include <cstdint>
#include <memory>
#include <vector>

namespace crumple::test
{

/// The bar tests' soft material: E 10 MPa, Poisson 0.3, 1000 kg/m^3, Rayleigh alpha 1 1/s and beta 1e-4 s
/// (a few hundred explicit sub-steps per frame), of model inModel.
fem::FemMaterialSettings SoftBarMaterial(fem::EElasticModel inModel = fem::EElasticModel::CorotatedLinear);

/// A 0.6 m x 0.2 m x 0.2 m bar of 6 x 2 x 2 cubes clamped at x = 0 (its nine nodes there anchored).
fem::TetSolver ClampedBar(const fem::FemMaterialSettings& inMaterial,
                          const fem::TetSolverSettings& inSettings);
/// The bar's tip corner node (6, 2, 2)
inline constexpr int cBarTipNode = 6 + 7 * (2 + 3 * 2);

/// The fracture tests' brittle wall: 2 m x 0.2 m x 1 m of 0.2 m cubes (E 10 GPa, Poisson 0.2, mass damping 2
/// 1/s) anchored along its base, its front face struck with inImpulse (N s, along +y) shared by the four
/// nodes of cell (7, 0, 3)'s front face.
fem::TetSolver StruckBrittleWall(const fem::TetSolverSettings& inSettings, double inImpulse);

/// A cantilever of inSettings on 20 x 2 x 2 cells with mass damping critical for its first bending mode, as
/// a scene (its solver at rest: the reference positions), on the GPU, and solved to statics on the CPU.
struct DampedCantilever
{
    common::CantileverScene mScene;
    gpu::GpuTetSolver mGpu;
    common::CantileverScene mStatic;
};
DampedCantilever MakeDampedCantilever(const std::shared_ptr<gpu::ComputeDevice>& inDevice,
                                      common::CantileverSettings inSettings);

/// Largest distance between the matching points of inA and inB (m).
double MaxDistance(const std::vector<Vec3>& inA, const std::vector<Vec3>& inB);

/// What RandomBlows did.
struct BlowCounts
{
    int mDiverged = 0; ///< Steps that diverged and were restored
    int mMoved = 0;    ///< Steps after which some position differed from the step before
};
/// 20 steps of inDeltaTime, each after a blow of 1e-3 to 1e5 N s (log-uniform, seeded by inSeed) on a random
/// node; REQUIREs a finite state after each.
BlowCounts RandomBlows(gpu::GpuTetSolver& ioGpu, double inDeltaTime, std::uint64_t inSeed);
/// A 1e30 N s blow on inNode overflows float: the next step reports ETetStepEvent::Diverged and the positions
/// are restored bit for bit (CHECKed).
void CheckBlowUpRestored(gpu::GpuTetSolver& ioGpu, int inNode);

} // namespace crumple::test
