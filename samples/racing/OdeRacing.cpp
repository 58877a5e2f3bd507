// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// The racing session of BulletRacing.cpp in ODE: a chassis on four sphere wheels held by hinge-2 joints
// (suspension and a rear-wheel motor), on the same course (scenes/racing/OdeRaceScene.cpp has the scene).
#include "OdeRaceScene.h"
#include "RunRaceSession.h"

using namespace crumple;
using namespace crumple::samples;

int main(int argc, char** argv)
{
    RaceOptions options;
    options.mOut = "racing-ode-output";
    if (const int code = ParseRaceOptions(
            argc, argv, "crumple-racing-ode",
            "An ODE car with a deformable body clips a brick wall, scrapes along barriers, breaks "
            "through a fence, then hits a parked car.",
            options);
        code >= 0)
        return code;
    return RunRaceSession("crumple-racing-ode", options, [](const RaceSceneSettings& inSettings) -> Result<std::unique_ptr<RaceScene>>
    {
        Result<std::unique_ptr<OdeRaceScene>> scene = OdeRaceScene::Create(inSettings);
        if (!scene)
            return scene.GetError();
        return std::unique_ptr<RaceScene>(std::move(scene).Get());
    });
}
