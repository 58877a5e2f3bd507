// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include "RaceScene.h"
#include "RaceSession.h"

#include <functional>
#include <memory>

namespace crumple::samples
{

/// Makes an engine's racing scene (BulletRaceScene::Create, OdeRaceScene::Create).
using MakeRaceScene = std::function<Result<std::unique_ptr<RaceScene>>(const RaceSceneSettings&)>;

/// A racing sample's main after its options: makes the scene with Crumple attached, records and logs it
/// (RaceSession), drives inOptions.mDuration of 60 Hz frames, paints every sixth, and finishes (summary,
/// meshes, after.png). Returns the exit code: 0, or 2 with the reason on stderr, prefixed by inProgram.
int RunRaceSession(const char* inProgram, const RaceOptions& inOptions, const MakeRaceScene& inMakeScene);

} // namespace crumple::samples
