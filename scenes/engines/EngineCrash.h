// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/ffd/TriangleMesh.h>
#include <crumple/plugin/DamageWorld.h>

#include <array>
#include <cmath>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace crumple::common
{

/// Gravity of the crash scenes, along -z (m/s^2)
inline constexpr double cCrashGravity = 9.81;

/// The same scripted crash for every engine: a box car on a ground plane driven into a static wall at
/// x = 0 whose face is the plane x = 0, head-on or at a heading angle. Gravity and ground friction are on,
/// so the car also has resting contacts with the ground that must make no damage.
/// A second car as the target: a box rigid body, deformable too, standing or moving.
struct TargetVehicleSettings
{
    Vec3 mHalfExtents{2.2, 0.85, 0.7}; ///< Half size (m), its body frame x forward
    double mMass = 1500.0;             ///< kg
    double mYawDegrees = 90.0;         ///< Heading from +x (degrees); 90: broadside to the subject car (side impact)
    double mSpeed = 0.0;               ///< Along its heading (m/s)
    double mOffset = 0.0;              ///< Its centre's y (m)
    plugin::DamageMaterial mMaterial;  ///< Its body material
};

struct EngineCrashSettings
{
    Vec3 mHalfExtents{2.1, 0.9, 0.7};  ///< Car half size (m), body frame x forward, z up
    double mMass = 1200.0;             ///< Car mass (kg)
    double mSpeed = 15.0;              ///< Initial speed along +x (m/s)
    double mYawDegrees = 0.0;          ///< Heading relative to the wall normal (degrees)
    double mTimeStep = 1.0 / 120.0;    ///< Engine step (s)
    double mDuration = 0.6;            ///< Simulated time (s)
    double mGap = 0.3;                 ///< Distance from the car's nearest point to the wall at start (m)
    int mTriangles = 8000;             ///< Car render mesh size
    std::array<int, 3> mControlCount{{0, 0, 0}}; ///< Controls of the fitted FFD zone; 0: from mControlSpacing
    double mControlSpacing = 0.15;               ///< Control spacing of the fitted zone when mControlCount is 0 (m)
    /// mControlSpacing or finer, as the car's occupant cell needs (DeformableObjectSettings'); false: as
    /// given
    bool mFitSpacingToOccupantCell = true;
    plugin::DamageMaterial mMaterial;  ///< Car body material
    plugin::DamageWorldSettings mWorld; ///< Damage world settings
    bool mDriveOnly = false;           ///< No wall: the car just drives (and rests) on the ground
    bool mFloating = false;            ///< No gravity, no ground: the car flies and touches nothing
    int mSceneryBoxes = 0;             ///< Loose 1 m crates resting beside the road, unknown to Crumple: a realistic
                                       ///< engine load for overhead measurements
    /// Friction coefficient of every contact but the ground's (both engines' scenes give each pair this coefficient); 0 leaves
    /// the wall's normal impulses the only horizontal force on the car, to compare with Crumple's impulses
    double mFriction = 0.5;
    /// Friction coefficient between the car and the ground: a tyre's rolling resistance (0.01-0.015). The car
    /// is a sliding box, and a sliding box's friction (0.5) would slow it by 5 m/s^2 before the wall and pitch
    /// its front edge into the ground
    double mGroundFriction = 0.015;
    bool mAttach = true;               ///< Attach Crumple; false gives the bare engine scene, for overhead ratios
    bool mMeasureAdapterTime = false;  ///< The adapter measures its CPU time per step (its settings' mMeasureCpuTime)
    /// The car's render mesh in its body frame (x forward, z up, centred on the box); empty: a box mesh of
    /// mHalfExtents with about mTriangles triangles. The collision shape is always the box.
    std::optional<ffd::TriangleMesh> mCarMesh;
    /// Vertex lists of mCarMesh's rigid parts (ffd::FfdDeformerSettings::mRigidParts): its wheels
    std::vector<std::vector<std::uint32_t>> mCarRigidParts;
    std::optional<Vec3> mInertia;      ///< Principal moments of inertia (kg m^2); empty: those of the box
    double mWallAngleDegrees = 0.0;    ///< The wall turned about the vertical through the origin (degrees)
    double mOffset = 0.0;              ///< The car's start y, sideways from the wall's centre line (m)
    double mMaxTotalDeformation = 1.5; ///< Most any vertex of the car may ever move (m)
    std::vector<ffd::FfdZoneSettings> mZones; ///< The car's deformation zones; empty: one fitted zone
    double mPoleRadius = 0.0;          ///< > 0: the target is a vertical pole of this radius at the origin, not a wall
    double mOverlapFraction = 1.0;     ///< < 1: the wall covers only this share of the car's width, on its +y side
    /// Set: the target is this vehicle (its nearest point at x = 0) instead of a wall or pole
    std::optional<TargetVehicleSettings> mTargetVehicle;
};

/// The car's start: centre x so that its nearest bottom corner is mGap from the (possibly turned) wall face,
/// at y = mOffset, resting on the ground, yawed by mYawDegrees.
Transform CrashCarStart(const EngineCrashSettings& inSettings);

/// The target vehicle's start: yawed, resting on the ground, its nearest point at x = 0, centre at y = mOffset.
Transform TargetVehicleStart(const TargetVehicleSettings& inTarget);

/// The target vehicle's deformable-object settings (a box mesh of about 4,000 triangles).
plugin::DeformableObjectSettings TargetVehicleObject(const TargetVehicleSettings& inTarget);

/// An offset wall (mOverlapFraction < 1) covers y >= this (m); a full wall spans y in [-10, 10].
double CrashWallLeftEdge(const EngineCrashSettings& inSettings);

/// What a crash produced, in the car's body frame.
struct EngineCrashResult
{
    double mMaxDent = 0.0;               ///< Largest vertex displacement (m)
    Vec3 mDentCentroid = Vec3::Zero();   ///< Displacement-weighted mean rest position of dented vertices (m)
    int mCollisions = 0;                 ///< Collisions dispatched that involve the car
    double mTotalImpulse = 0.0;          ///< Sum of their impulses (N s)
    std::vector<Vec3> mPositions;        ///< Final deformed positions
    std::vector<std::byte> mDamage;      ///< SaveDamage() at the end
};

/// Settles the result of a finished run from its damage world.
EngineCrashResult SummarizeCrash(const plugin::DamageWorld& inWorld, plugin::ObjectId inCar, int inCollisions,
                                 double inTotalImpulse);

/// Crumple's impulses on inBody over the logged collisions, as one vector (world, N s): +J n on body A of
/// each contact, -J n on body B.
Vec3 ImpulseOnBody(std::span<const plugin::Collision> inLog, plugin::BodyId inBody);

/// Counts the car's collisions and impulses as they are dispatched.
class CrashCounter : public plugin::DamageListener
{
public:
    void OnCollision(const plugin::Collision& inCollision, std::span<const plugin::ObjectDent> inDents) override;
    int mCollisions = 0;
    double mTotalImpulse = 0.0;
    int mLimitedDents = 0; ///< Dents a bound limited (ffd::DentReport::IsLimited), any object
    int mStackedUpDents = 0; ///< Crushes that stacked up against an occupant cell (ffd::DentReport::mStackedUp)
    std::vector<plugin::Collision> mLog; ///< Every collision, in dispatch order
};

/// Steps inScene (BulletWallCrash, OdeWallCrash) for its settings' duration, flushes its damage world and
/// settles the result from the scene's counter (an empty result for a bare scene: inAttached false).
template <class Scene>
EngineCrashResult RunEngineCrash(Scene& ioScene, const EngineCrashSettings& inSettings, bool inAttached)
{
    const int steps = static_cast<int>(std::lround(inSettings.mDuration / inSettings.mTimeStep));
    for (int i = 0; i < steps; ++i)
        ioScene.Step();
    ioScene.GetDamage().Flush();
    if (!inAttached)
        return {};
    return SummarizeCrash(ioScene.GetDamage(), ioScene.GetCarObject(), ioScene.GetCounter().mCollisions,
                          ioScene.GetCounter().mTotalImpulse);
}

/// The impacts the engine-independence checks run at inKmH, named: frontal, 40 % offset, 30- and 45-degree
/// walls, a pole, and into a parked car's rear corner and its side; 0.3 s, a 2,000-triangle box car, friction
/// inFriction on every contact but the ground's (0 there: the car slides freely before the hit).
std::vector<std::pair<std::string, EngineCrashSettings>> ImpactMatrix(double inKmH, double inFriction);

/// The car's render mesh and deformable-object settings shared by every engine scene.
plugin::DeformableObjectSettings CrashCarObject(const EngineCrashSettings& inSettings);

} // namespace crumple::common
