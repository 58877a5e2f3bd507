// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Result.h>
#include <crumple/fem/FemMaterialSettings.h>
#include <crumple/fem/TetSolverSettings.h>
#include <crumple/props/FemProp.h>
#include <crumple/props/PropBody.h>
#include <crumple/props/PropWorld.h>

#include <functional>
#include <span>

namespace crumple::props
{

/// The solver settings of a held prop's FEM unless the game gives its own: the default implicit solver with
/// no gravity and no ground (the held body stands for what holds the prop up, so it sleeps until something
/// strikes it; pieces that break loose fall under the engine's gravity; a part left hanging on a thin joint
/// swings until damping stops it: give the prop the world's gravity and ground, fem::GroundPlane, for it to
/// fall onto the ground and come to rest), and the factor refreshed at the element frames
/// after 6 conjugate-gradient iterations (mFactorRefreshIterations) or once the iterations its frames cost
/// add up to a refresh (mFactorRefreshByCost): a struck prop bends, and with its
/// cracks converged (mCrackStressTolerance) the refresh no longer changes them. Measured, refresh 0 against
/// 6, two runs each: the drive-through fence (17,600 tetrahedra, 64 km/h) spent 2.93-2.97 s in its FEM
/// against 2.21-2.24 s in Bullet (worst step 214 against 102-106 ms) and 2.27 against 1.96-2.09 s in ODE
/// (worst 167-173 against 92-101 ms), the same links broken (220, 179); the racing fence's worst frame
/// 103-112 against 64-82 ms in Bullet, 61 against 50-53 ms in ODE.
CRUMPLE_API fem::TetSolverSettings HeldPropSolverSettings();

/// The FEM of a prop whose engine body is held (PropBodySettings::mHeld, a fence or a barrier anchored to the
/// ground): a prop on inBodyMesh (MakePropBody's mMesh, the body frame) with inSolver (its gravity and
/// ground, if any, in the body frame) and the nodes of inAnchoredNodes fixed (its footings:
/// TetFence::mGroundNodes), spreading each contact's impulse over inContactSpread (FemProp::SetContactSpread,
/// m; 0: the containing element's nodes). A prop with gravity starts at its static equilibrium on its
/// anchors (TetSolver::SolveStatic on a copy; the prop is a fresh solver at those positions, recorded and
/// replayed as any), so it sleeps within a few steps; where that solve fails it starts as made and sags.
/// Refused, in this order: a spread radius that is not finite and >= 0; a backend that is not an
/// EFemBackend; the first reason for a mesh, material or solver settings TetSolver::Create refuses; an
/// anchored node out of range. inPropSettings and ioProvider choose the backend as for FemProp::Create (the
/// CPU by default; a GPU request without a device, or for what the GPU solver lacks, runs on the CPU and says
/// why); the anchors are set on the CPU solver before it moves to the GPU.
CRUMPLE_API Result<FemProp> MakeHeldFemProp(const fem::TetMesh& inBodyMesh,
                                            const fem::FemMaterialSettings& inMaterial,
                                            std::span<const int> inAnchoredNodes,
                                            const fem::TetSolverSettings& inSolver = HeldPropSolverSettings(),
                                            double inContactSpread = 0.0,
                                            const FemPropSettings& inPropSettings = {},
                                            gpu::ComputeDeviceProvider* ioProvider = nullptr);

/// A held prop that AddHeldProp put in a PropWorld.
struct CRUMPLE_API HeldProp
{
    plugin::BodyId mBody; ///< Its engine body
    PropId mProp;         ///< Its FEM in the PropWorld
    PropBody mMade;       ///< MakePropBody's answer: the mesh in the body frame, the body's settings
};

/// Everything that puts a prop anchored to the ground into a game: MakePropBody (held, shape of cubes of
/// inShapeCellSize), its FEM (MakeHeldFemProp on the body-frame mesh, the nodes of inAnchoredNodes fixed),
/// the engine body (inMakeBody: the adapter's CreatePropBody, bound by the game) and PropWorld::AddProp. The
/// FEM's gravity and ground are inSolver's in the world frame (the frame of inPose), turned into the body
/// frame here. The FEM is made and checked (PropWorld::CheckCanAdd: a recorder that has failed or closed)
/// before the engine body, so bad input (mesh, material, solver settings, pose, anchors) or state creates
/// nothing; a body that inMakeBody made stays the adapter's only if AddProp still refuses it (an adapter of
/// another world, or a write error). inSolver, inContactSpread, inPropSettings and ioProvider: the FEM's
/// solver settings, contact spread radius and backend, as for MakeHeldFemProp.
CRUMPLE_API Result<HeldProp>
AddHeldProp(PropWorld& ioProps, const fem::TetMesh& inMesh, const fem::FemMaterialSettings& inMaterial,
            std::span<const int> inAnchoredNodes, const Transform& inPose, double inShapeCellSize,
            const std::function<Result<plugin::BodyId>(const plugin::PropBodySettings&)>& inMakeBody,
            const fem::TetSolverSettings& inSolver = HeldPropSolverSettings(), double inContactSpread = 0.0,
            const FemPropSettings& inPropSettings = {}, gpu::ComputeDeviceProvider* ioProvider = nullptr);

} // namespace crumple::props
