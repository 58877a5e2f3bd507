// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include "EngineCrash.h"

#include <crumple/ode/OdeAdapter.h>
#include <crumple/ode/OdeBodyState.h>

#include <ode/ode.h>

#include <memory>
#include <vector>

namespace crumple::common
{

/// EngineCrashSettings run in ODE (dWorldQuickStep, or dWorldStep once the scene holds a prop body; hash
/// space, contact joints).
class OdeWallCrash
{
public:
    /// Fastest ODE may push a penetrating body out of another (m/s); a resting car needs far less
    static constexpr double cMaxCorrectingSpeed = 0.5;
    /// Sweeps of ODE's quick step per step, ODE's default: 20, 100 and 500 gave the same impulses within 0.2 %
    /// on 30-60 degree hits, and 100 made a step with 100 resting crates cost five times dWorldStep's
    static constexpr int cQuickStepIterations = 20;
    /// The least error reduction of a contact that is not the ground's (a restitution of 0 would leave a
    /// penetration uncorrected): its push-out is then at most 2 % of the approach speed
    static constexpr double cMinWallErp = 0.02;
    explicit OdeWallCrash(const EngineCrashSettings& inSettings);
    ~OdeWallCrash();
    OdeWallCrash(const OdeWallCrash&) = delete;
    OdeWallCrash& operator=(const OdeWallCrash&) = delete;

    EngineCrashResult Run();
    void Step();

    dWorldID GetWorld() const { return mWorld; }
    dSpaceID GetSpace() const { return mSpace; }
    dBodyID GetCar() const { return mCar; }
    ode::OdeAdapter& GetAdapter() { return *mAdapter; }
    /// The damage body of the target: the wall or pole, a static geom registered with the adapter (so that its
    /// shape reaches the crush); the adapter's environment (the ground's) when the scene has neither
    plugin::BodyId GetWallBody() const { return mWallBody.IsValid() ? mWallBody : mAdapter->GetEnvironment(); }
    plugin::DamageWorld& GetDamage() { return mDamage; }
    plugin::ObjectId GetCarObject() const { return mCarObject; }
    /// A loose piece's body (the adapter's CreateConvexBody in this scene's world)
    Result<plugin::BodyId> MakeDebrisBody(const plugin::ConvexBodySettings& inSettings);
    /// A prop's body (the adapter's CreatePropBody in this scene's world)
    Result<plugin::BodyId> MakePropBody(const plugin::PropBodySettings& inSettings);
    /// Removes a body MakeDebrisBody or MakePropBody made, from the engine and the damage world (the
    /// adapter's RemoveBody): a restarted level's props and pieces. Refused for any other id.
    Status RemoveMadeBody(plugin::BodyId inBody);
    /// The car's state as Crumple reads it (mass, world inertia, frame, velocities)
    plugin::BodyState GetCarState() const;
    /// Sets the car's velocities (m/s, rad/s, world): for contacts solved outside the engine
    void SetCarVelocity(const Vec3& inLinear, const Vec3& inAngular);
    /// The target vehicle's deformable object (invalid without one)
    plugin::ObjectId GetTargetObject() const { return mTargetObject; }
    CrashCounter& GetCounter() { return mCounter; }

private:
    static void NearCallback(void* inData, dGeomID inGeom1, dGeomID inGeom2);
    /// Registers the wall or pole geom with the adapter (when attached) as the target's own body.
    void RegisterImpactor(dGeomID inGeom);

    EngineCrashSettings mSettings;
    dWorldID mWorld = nullptr;
    dSpaceID mSpace = nullptr;
    dJointGroupID mContacts = nullptr;
    dBodyID mCar = nullptr;
    plugin::BodyId mWallBody; ///< The wall or pole (RegisterImpactor); invalid without one or unattached
    std::unique_ptr<plugin::DamageWorld> mDamageOwner; ///< On the heap: the world never moves
    plugin::DamageWorld& mDamage;
    std::unique_ptr<ode::OdeAdapter> mAdapter;
    plugin::ObjectId mCarObject;
    dBodyID mTarget = nullptr;
    plugin::ObjectId mTargetObject;
    CrashCounter mCounter;
    std::vector<dBodyID> mHeldBodies; ///< Held prop bodies: their contacts get no error reduction (NearCallback)
};

} // namespace crumple::common
