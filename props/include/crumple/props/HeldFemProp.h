// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Result.h>
#include <crumple/fem/FemMaterialSettings.h>
#include <crumple/props/FemProp.h>

#include <span>

namespace crumple::props
{

/// The FEM of a prop whose engine body is held (PropBodySettings::mHeld, a fence or a barrier anchored to the
/// ground): a CPU prop on inBodyMesh (MakePropBody's mMesh, the body frame) with the default implicit
/// solver, no gravity in its FEM (the held body stands for what holds the prop up, so it sleeps until
/// something strikes it; pieces that break loose fall under the engine's gravity) and the nodes of
/// inAnchoredNodes fixed (its footings: TetFence::mGroundNodes). Refused with the first reason for a mesh or
/// material FemProp::Create refuses or an anchored node out of range.
CRUMPLE_API Result<FemProp> MakeHeldFemProp(const fem::TetMesh& inBodyMesh, const fem::FemMaterialSettings& inMaterial,
                                            std::span<const int> inAnchoredNodes);

} // namespace crumple::props
