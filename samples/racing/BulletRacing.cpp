// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// A scripted racing session in Bullet: a btRaycastVehicle with a deformable body (the Khronos Toy Car from
// ../shared/data when present, else a procedural box) accelerates down a straight, clips a garden wall whose
// bricks fly, scrapes along concrete barriers angled into the road, breaks through a wooden fence whose
// pieces fly (destructible props: FEM, fracture, pieces made engine bodies) and hits a parked car, a driver
// steering it back to the course line after each knock (scenes/racing/RaceSession.h has the course,
// BulletRaceScene.cpp the scene). Prints one line per collision; writes a replay file, the deformed meshes
// (OBJ) and PNG pictures.
#include "BulletRaceScene.h"
#include "RunRaceSession.h"

using namespace crumple;
using namespace crumple::samples;

int main(int argc, char** argv)
{
    RaceOptions options;
    if (const int code = ParseRaceOptions(
            argc, argv, "crumple-racing-bullet",
            "A btRaycastVehicle with a deformable body clips a brick wall, scrapes along barriers, "
            "breaks through a fence, then hits a parked car.",
            options);
        code >= 0)
        return code;
    return RunRaceSession("crumple-racing-bullet", options, [](const RaceSceneSettings& inSettings) -> Result<std::unique_ptr<RaceScene>>
    {
        Result<std::unique_ptr<BulletRaceScene>> scene = BulletRaceScene::Create(inSettings);
        if (!scene)
            return scene.GetError();
        return std::unique_ptr<RaceScene>(std::move(scene).Get());
    });
}
