// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include "WallCrashScene.h"

namespace crumple::common
{

/// Steps ioScene, a wall crash whose world defers its dents (DamageWorldSettings::mDeferDents), until a
/// dispatch's dents are in flight on its job system, at most inMaxSteps steps; true when they are (the scene
/// is left at that moment).
bool StepUntilDentsInFlight(WallCrashScene& ioScene, int inMaxSteps = 200);

} // namespace crumple::common
