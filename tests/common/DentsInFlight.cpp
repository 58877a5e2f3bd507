// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "DentsInFlight.h"

namespace crumple::common
{

bool StepUntilDentsInFlight(WallCrashScene& ioScene, int inMaxSteps)
{
    for (int step = 0; step < inMaxSteps; ++step)
    {
        ioScene.Step();
        if (ioScene.GetWorld().HasDentsInFlight())
            return true;
    }
    return false;
}

} // namespace crumple::common
