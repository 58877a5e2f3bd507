// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "CarMesh.h"

#include <crumple/crash/ShippedCars.h>

namespace crumple::crash
{

std::vector<NamedVehicle> ShippedCars()
{
    const std::filesystem::path meshes = samples::SharedDataFolder() / "meshes";
    std::vector<NamedVehicle> cars;
    NamedVehicle box{"box car", {}};
    box.mVehicle.mBoxSize = Vec3(4.4, 1.65, 1.4);
    box.mVehicle.mMass = 1575.0;
    cars.push_back(box);
    NamedVehicle toy{"Toy Car", {}};
    toy.mVehicle.mMesh = meshes / "toycar" / "ToyCar_geometry.gltf";
    toy.mVehicle.mMeshName = "ToyCar";
    toy.mVehicle.mMass = 1200.0;
    cars.push_back(toy);
    NamedVehicle truck{"Kenney truck", {}};
    truck.mVehicle.mMesh = meshes / "kenney_truck" / "vehicle-truck-red.glb";
    truck.mVehicle.mMeshLength = 4.8;
    truck.mVehicle.mMass = 1800.0;
    cars.push_back(truck);
    NamedVehicle hatchback{"Gazebo hatchback", {}};
    hatchback.mVehicle.mMesh = meshes / "gazebo_hatchback" / "hatchback.obj";
    hatchback.mVehicle.mMeshName = "Hatchback";
    hatchback.mVehicle.mMeshForwardAxis = static_cast<int>(samples::EMeshAxis::MinusY);
    hatchback.mVehicle.mMeshUpAxis = static_cast<int>(samples::EMeshAxis::PlusZ);
    hatchback.mVehicle.mMeshUnit = 0.0254;
    hatchback.mVehicle.mMass = 1200.0;
    cars.push_back(hatchback);
    return cars;
}

} // namespace crumple::crash
