// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/crash/CrashScenario.h>

#include <string>
#include <vector>

namespace crumple::crash
{

/// A named vehicle of the crash tests and benchmarks.
struct NamedVehicle
{
    std::string mName;
    VehicleSpec mVehicle;
};

/// The box car (1,575 kg, 4.4 x 1.65 x 1.4 m) and the three car meshes of the shared data folder
/// (samples::SharedDataFolder): the Toy Car (1,200 kg), the Kenney truck (1,800 kg, 4.8 m) and the Gazebo
/// hatchback (1,200 kg, its -y forward, +z up and inches stated), all with the default material.
std::vector<NamedVehicle> ShippedCars();

} // namespace crumple::crash
