// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include "RaceProps.h"

#include <crumple/base/Math.h>
#include <crumple/plugin/DamageWorld.h>

#include <crumple/ffd/TriangleMesh.h>

#include <functional>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace crumple::common
{
class ThreadJobSystem;
}

namespace crumple::samples
{

/// How a racing scene (BulletRaceScene, OdeRaceScene) is made.
struct RaceSceneSettings
{
    double mSpeed = 20.0;     ///< The car's target speed (m/s)
    int mThreads = 1;         ///< Threads of the game's job system handed to Crumple
    bool mDeferDents = false; ///< DamageWorldSettings::mDeferDents
    bool mDeferImpulses = false;  ///< DamageWorldSettings::mDeferImpulses (with mDeferDents)
    bool mPropsOffThread = false; ///< props::PropWorldSettings::mStepOffThread: the props' FEM as a task
    /// False: the engine alone, with the same course and cars but no Crumple (no damage world, adapter,
    /// deformable objects or props): the bare side of a frame budget (crumple-bench frame_budget)
    bool mAttach = true;
};

/// Told the engine bodies a frame's engine steps made (the props' pieces), after each step that made some.
using RaceNewBodies = std::function<void(std::span<const RaceNewPiece>)>;

/// A racing scene, whatever the engine: what the racing samples and the frame-budget benchmark step and
/// read. The engine's scene (BulletRaceScene, OdeRaceScene) builds the course; this part holds Crumple's side.
class RaceScene
{
public:
    virtual ~RaceScene();
    RaceScene(const RaceScene&) = delete;
    RaceScene& operator=(const RaceScene&) = delete;

    /// One 60 Hz frame: the driver's throttle and steering, then four engine steps of 1/240 s, the props' FEM
    /// after each (a held prop body takes the struck members' velocity at every step: a frame's worth of
    /// steps against a fence at rest would take from the car what four fences would).
    virtual Status StepFrame(const RaceNewBodies& inNewBodies) = 0;
    /// Where the engine has the two cars now
    virtual Transform GetCarPose() const = 0;
    virtual Transform GetParkedPose() const = 0;

    /// The damage world, the cars' deformable objects and the props (null without Crumple attached)
    plugin::DamageWorld* GetDamage() { return mDamage.get(); }
    const plugin::DeformableObject* GetCar() const { return mCarObject; }
    const plugin::DeformableObject* GetParked() const { return mParkedObject; }
    RaceProps* GetProps() { return mProps.get(); }
    /// The bodies' names for the collision log
    const std::map<plugin::BodyId, std::string>& GetNames() const { return mNames; }
    /// Crumple's share of the last StepFrame (the game thread's CPU time, ms): the adapter's calls (its
    /// GetLastStepStats().mSeconds: contacts, impulses, body states, dispatching and landing dents) and the
    /// props' Step (their FEM, or with mPropsOffThread its hand-over, the engine's calls for new pieces and
    /// shapes included); not the engine's own collision detection and solve, of the props' pieces among other
    /// bodies, nor the drawing meshes the sample makes of new pieces (RaceProps::GetLastStepDrawingMs). 0
    /// without Crumple.
    double GetLastFrameCrumpleMs() const { return mFrameCrumpleMs; }

protected:
    explicit RaceScene(const RaceSceneSettings& inSettings);
    /// With mAttach: the game's job system (threads started per parallel for, handed to Crumple for dents)
    /// and the damage world, before the engine's adapter is made.
    Status CreateDamageWorld();
    /// A car's deformable object on its body, with inMesh as its body mesh.
    Result<const plugin::DeformableObject*> CreateCarObject(plugin::BodyId inBody, const ffd::TriangleMesh& inMesh);
    /// Keeps the course's props (RaceProps::Create's answer) and names their bodies for the log.
    Status KeepProps(Result<std::unique_ptr<RaceProps>> inProps);
    /// After one engine step of inStep seconds: the props' FEM, and the bodies their pieces became.
    Status StepProps(double inStep, const RaceNewBodies& inNewBodies);

    RaceSceneSettings mSettings;
    std::unique_ptr<common::ThreadJobSystem> mJobs;
    std::unique_ptr<plugin::DamageWorld> mDamage;
    std::unique_ptr<RaceProps> mProps; ///< Reset by the engine's scene before its adapter goes
    const plugin::DeformableObject* mCarObject = nullptr;
    const plugin::DeformableObject* mParkedObject = nullptr;
    std::map<plugin::BodyId, std::string> mNames;
    double mFrameCrumpleMs = 0.0; ///< GetLastFrameCrumpleMs: the engine's scene resets it and adds its adapter's

private:
  std::vector<RaceNewPiece> mPieces; // scratch: the bodies one engine step made
};

} // namespace crumple::samples
