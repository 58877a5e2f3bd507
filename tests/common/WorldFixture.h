// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include "MeshHash.h"

#include <crumple/plugin/DamageWorld.h>

#include <memory>

#include <vector>

namespace crumple::common
{

/// A minimal damage world for tests (Jolt's PhysicsTestContext): a static floor, a static wall at x = 0
/// facing -x, and a 1,200 kg box car (4.2 m x 1.8 m x 1.4 m, body frame at its centre of mass) with a
/// deformable body, driving along +x towards the wall.
class WorldFixture
{
public:
    /// @param inTriangles    approximate triangle count of the car mesh
    /// @param inControlCount controls of the fitted FFD zone
    explicit WorldFixture(int inTriangles = 4000, std::array<int, 3> inControlCount = {8, 6, 6},
                          const plugin::DamageWorldSettings& inSettings = {});

    /// Car state at the moment its front (x = +2.1 in the body frame) touches the wall, moving at inSpeed.
    plugin::BodyState CarState(double inSpeed) const;

    /// A car-wall contact at a point of the car's front face (body frame y, z), as an engine reports it.
    plugin::ContactEvent FrontContact(double inY, double inZ, double inTime, double inDepth = 0.01) const;

    std::unique_ptr<plugin::DamageWorld> mWorldOwner; ///< On the heap: the world never moves
    plugin::DamageWorld& mWorld;
    plugin::BodyId mFloor, mWall, mCar;
    plugin::ObjectId mCarObject;
    Vec3 mHalfExtents{2.1, 0.9, 0.7};
    double mMass = 1200.0;
};


} // namespace crumple::common
