// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include "BoxImpulseEngine.h"
#include "EngineCrash.h"

#include <memory>
#include <vector>

namespace crumple::common
{

/// EngineCrashSettings run in BoxImpulseEngine, an engine Crumple has no adapter for, joined to Crumple
/// through its engine-agnostic calls alone (docs/adapters.md): each step the car's pre-solve state
/// (DamageWorld::SetBodyState), the step's contacts (SubmitContacts) and the time (Update). The walls, the
/// offset wall, the pole, the target vehicle, the ground, a floating car and a drive without a wall are built
/// as in the Bullet and ODE scenes; scenery crates are not (Supports).
class BoxImpulseWallCrash
{
  public:
    /// False for the settings this scene does not build (scenery crates, a bare scene).
    static bool Supports(const EngineCrashSettings& inSettings);

    /// The crash in an engine of inEngine's contact and solver settings (its gravity and restitution the
    /// scene's)
    explicit BoxImpulseWallCrash(const EngineCrashSettings& inSettings,
                                 const BoxImpulseEngineSettings& inEngine = {});

    /// Steps to the end and summarizes.
    EngineCrashResult Run();
    /// One engine step of mTimeStep.
    void Step();

    plugin::DamageWorld& GetDamage() { return mDamage; }
    plugin::ObjectId GetCarObject() const { return mCarObject; }
    /// The target vehicle's deformable object (invalid without one)
    plugin::ObjectId GetTargetObject() const { return mTargetObject; }
    /// The car's state as Crumple reads it (mass, world inertia, frame, velocities)
    plugin::BodyState GetCarState() const;
    /// The moving bodies' kinetic energy, the car's and the target vehicle's (J)
    double KineticEnergy() const;
    CrashCounter& GetCounter() { return mCounter; }
    /// SetBodyState and SubmitContacts calls Crumple refused (none, unless the engine's output is bad)
    int GetRefusedCalls() const { return mRefusedCalls; }
    /// The contacts the engine reported in the last step
    int GetLastContactCount() const { return static_cast<int>(mEvents.size()); }

  private:
    /// The Crumple state of engine body inBody (its shape's box in its frame stated)
    plugin::BodyState StateOf(int inBody) const;

    EngineCrashSettings mSettings;
    BoxImpulseEngine mEngine;
    std::unique_ptr<plugin::DamageWorld> mDamageOwner; ///< On the heap: the world never moves
    plugin::DamageWorld& mDamage;
    int mCar = -1;
    int mTarget = -1;                 ///< The target vehicle's engine body, -1 without one
    std::vector<plugin::BodyId> mIds; ///< Crumple's id of each engine body
    plugin::ObjectId mCarObject;
    plugin::ObjectId mTargetObject;
    CrashCounter mCounter;
    double mTime = 0.0;
    int mRefusedCalls = 0;
    std::vector<plugin::ContactEvent> mEvents; ///< One step's, reused
};

} // namespace crumple::common
