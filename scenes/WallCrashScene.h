// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/plugin/DamageWorld.h>

#include <memory>

#include <array>
#include <vector>

namespace crumple::common
{

/// A box-shaped car driven into a static wall, with a tiny scripted rigid-body "engine" standing in for
/// Bullet or ODE: it reports up to mMaxContacts deepest penetrating surface samples per step (as a contact
/// manifold would), resolves them with the same simultaneous impulses, pushes the car out and integrates.
/// Used by tests, the demo and the benchmark, so all three exercise the core API the way an adapter will.
struct WallCrashSettings
{
    Vec3 mHalfExtents{2.1, 0.9, 0.7};      ///< Car body half size (m), body frame x forward
    double mMass = 1200.0;                 ///< Car mass (kg)
    double mSpeed = 15.0;                  ///< Initial speed towards the wall (m/s)
    double mYawDegrees = 0.0;              ///< Heading relative to the wall normal (degrees): 0 is head-on
    double mTimeStep = 1.0 / 60.0;         ///< Engine step (s)
    double mDuration = 0.4;                ///< Simulated time (s)
    int mTriangles = 20000;                ///< Approximate render-mesh triangle count
    std::array<int, 3> mControlCount{{10, 6, 6}}; ///< FFD controls of the single fitted zone
    int mSamplesPerEdge = 6;               ///< Surface samples per face edge used as candidate contact points
    int mMaxContacts = 4;                  ///< Contacts reported per step (Bullet's manifold keeps 4)
    plugin::DamageMaterial mMaterial;      ///< Car body material
    plugin::DamageWorldSettings mWorld;    ///< Damage world settings
};

/// The running scene.
class WallCrashScene
{
public:
    static Result<WallCrashScene> Create(const WallCrashSettings& inSettings);

    /// One engine step: snapshot, detect, submit, solve, integrate, update the damage world.
    void Step();
    /// Steps until mDuration, then flushes open collisions.
    void Run();

    plugin::DamageWorld& GetWorld() { return *mWorld; }
    const plugin::DamageWorld& GetWorld() const { return *mWorld; }
    plugin::BodyId GetCar() const { return mCar; }
    plugin::BodyId GetWall() const { return mWall; }
    plugin::ObjectId GetCarObject() const { return mCarObject; }
    const plugin::BodyState& GetCarState() const { return mCarState; }
    double GetTime() const { return mTime; }
    /// Contacts reported over the run
    int GetContactCount() const { return mContactCount; }

private:
    WallCrashScene(const WallCrashSettings& inSettings, std::unique_ptr<plugin::DamageWorld> inWorld)
        : mSettings(inSettings), mWorld(std::move(inWorld)) {}
    void UpdateInertia();

    WallCrashSettings mSettings;
    std::unique_ptr<plugin::DamageWorld> mWorld; ///< On the heap: the world never moves
    plugin::BodyId mCar, mWall;
    plugin::ObjectId mCarObject;
    plugin::BodyState mCarState, mWallState;
    Mat3 mLocalInverseInertia = Mat3::Identity();
    std::vector<Vec3> mSamples; ///< Candidate contact points on the car, body frame
    double mTime = 0.0;
    int mContactCount = 0;
};

} // namespace crumple::common
