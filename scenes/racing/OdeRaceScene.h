// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include "RaceScene.h"

#include <ode/ode.h>

#include <array>
#include <memory>
#include <vector>

namespace crumple::ode
{
class OdeAdapter;
}

namespace crumple::samples
{

/// The racing course (RaceCourse) in ODE: a chassis box around the racing car mesh (RaceCarMesh) on four
/// sphere wheels held by hinge-2 joints (suspension and a rear-wheel motor), the barriers and the ground as
/// static geoms, the parked car and the destructible props, with Crumple attached through the OdeAdapter (or
/// not: RaceSceneSettings::mAttach). The game adds one line to its near callback (OdeAdapter::OnCollide) and
/// one after dWorldQuickStep (OdeAdapter::AfterStep).
class OdeRaceScene final : public RaceScene
{
public:
    static Result<std::unique_ptr<OdeRaceScene>> Create(const RaceSceneSettings& inSettings);
    ~OdeRaceScene() override;

    Status StepFrame(const RaceNewBodies& inNewBodies) override;
    Transform GetCarPose() const override;
    Transform GetParkedPose() const override;

private:
    explicit OdeRaceScene(const RaceSceneSettings& inSettings);
    static void Near(void* inData, dGeomID inGeom1, dGeomID inGeom2);

    dWorldID mWorld = nullptr;
    dSpaceID mSpace = nullptr;
    dJointGroupID mContacts = nullptr;
    std::unique_ptr<ode::OdeAdapter> mAdapter;
    std::vector<dBodyID>
        mHeldBodies; ///< Held prop bodies (fence, brick wall), put back at their pose every step
    dBodyID mChassis = nullptr;
    dBodyID mParked = nullptr;
    double mWheelBase = 0.0; ///< m, for the driver's steering
    std::array<dJointID, 4> mHinges{};
};

} // namespace crumple::samples
