// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Result.h>
#include <crumple/crash/CrashScenario.h>
#include <crumple/crash/RecutCarMesh.h>
#include <crumple/crash/WallGap.h>
#include <crumple/ffd/TriangleMesh.h>

#include <array>
#include <cstddef>
#include <filesystem>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace crumple::crash
{

/// One collision of the car, as dispatched.
struct CrashCollisionRecord
{
    double mStartTime = 0.0; ///< s
    double mEndTime = 0.0;   ///< s
    double mImpulse = 0.0;   ///< Sum of its contact impulses (N s)
    int mContacts = 0;       ///< Contacts grouped into it
};

/// The car's state after one engine step (world frame).
struct CarSample
{
    double mTime = 0.0;                 ///< s
    Vec3 mPosition = Vec3::Zero();      ///< Centre of mass (m)
    Vec3 mVelocity = Vec3::Zero();      ///< Linear velocity (m/s)
};

/// A face of the car's body box (body frame: x forward, y to the left, z up).
enum class ECarFace
{
    Front, ///< +x
    Rear,  ///< -x
    Left,  ///< +y
    Right, ///< -y
};

/// The face's name in reports ("front", "rear", "left", "right").
const char* CarFaceName(ECarFace inFace);

/// The crush profile as accident reconstruction measures it (CRASH3/WinSMASH): six equally spaced crush
/// depths across the damaged width of a face, in the order of the body axis across it (the ends: C1 at the
/// car's right, -y, C6 at its left; the sides: C1 at the rear, -x, C6 at the front).
struct CrushProfile
{
    ECarFace mFace = ECarFace::Front; ///< The face measured
    double mDamageWidth = 0.0;        ///< Width of the face whose crush exceeds 1 cm (m); 0: no damage
    std::array<double, 6> mC{};       ///< Crush depth at the six stations (m), inward across the face
    /// CRASH3's average, (C1/2 + C2 + C3 + C4 + C5 + C6/2) / 5 (m): the crush of the same energy spread
    /// uniformly over the damage width
    double Average() const { return (0.5 * mC[0] + mC[1] + mC[2] + mC[3] + mC[4] + 0.5 * mC[5]) / 5.0; }
};

/// What a crash run measured. Velocities in the world frame; crush in the car's body frame.
struct CrashOutcome
{
    std::array<double, 6> mResidualCrush{}; ///< Largest residual vertex displacement per EZone (m)
    int mFoldedVertices = 0;                ///< Car body vertices turned over (common::FoldedVertices)
    int mFoldedTriangles = 0;               ///< Car body triangles turned over (common::FoldedTriangles)
    std::vector<std::string> mWarnings;     ///< What the run doubts about its input (a sideways mesh)
    std::optional<MeshPreparation> mMeshPreparation; ///< A mesh body's re-cut; empty for the procedural box
    CrushProfile mCrushProfile;                      ///< The struck face's crush profile (StruckCrushProfile)
    double mOutwardDisplacement = 0.0;      ///< Largest outward residual displacement (OutwardDisplacement, m)
    /// A rigid or offset wall's gap behind its final plane (MeasureWallGap); empty for other targets
    std::optional<WallGap> mWallGap;
    int mLimitedDents = 0;                  ///< Dents that a material bound clamped or scaled (any object)
    int mStackedUpDents = 0;                ///< Crushes that stacked up against the occupant cell (any object)
    Vec3 mStartVelocity = Vec3::Zero();     ///< Car velocity at the start (m/s)
    Vec3 mEndVelocity = Vec3::Zero();       ///< Car velocity at the end (m/s)
    double mMass = 0.0;                     ///< kg
    /// The most the ground's friction can take from the car's speed per second (m/s^2): the scene's ground
    /// friction coefficient (a tyre's rolling resistance) times gravity
    double mGroundDeceleration = 0.0;
    double mTotalImpulse = 0.0;             ///< Sum over the car's collisions (N s)
    Vec3 mCarImpulse = Vec3::Zero();        ///< The same impulses as vectors on the car, summed (world, N s)
    std::vector<CarSample> mHistory;        ///< The car at the start and after every engine step
    /// First and last contact time of the collisions that involve the car (s); NaN without any
    double mImpactStartTime = std::numeric_limits<double>::quiet_NaN();
    double mImpactEndTime = std::numeric_limits<double>::quiet_NaN();
    double mPeakImpulse = 0.0;              ///< Largest single collision impulse (N s)
    std::vector<CrashCollisionRecord> mCollisions; ///< In dispatch order
    ffd::TriangleMesh mRestMesh;            ///< The car body before (body frame, m)
    std::vector<Vec3> mPositions;           ///< The car body after (body frame, m), #V
    std::vector<Vec3> mNormals;             ///< Its vertex normals after, #V
    std::vector<Vec3> mRestNormals;         ///< Its vertex normals before, #V
    Transform mStartTransform;              ///< Car body to world at the start
    Transform mEndTransform;                ///< Car body to world at the end
    double mTargetResidualCrush = std::numeric_limits<double>::quiet_NaN(); ///< Target vehicle's largest residual
                                                                            ///< displacement (m); NaN without one
    int mBarrierFragments = 0;   ///< FEM barrier: pieces at the end (1 = whole); 0 without a barrier
    int mBarrierBrokenLinks = 0; ///< FEM barrier: links broken
    double mBarrierBreachTime = std::numeric_limits<double>::quiet_NaN(); ///< FEM barrier: when the car's front
                                                                          ///< passed its back face (s); NaN: never
    Vec3 mBarrierMomentum = Vec3::Zero(); ///< FEM barrier: momentum the car handed to it (world, N s)

    /// |v_end - v_start| (m/s)
    double DeltaV() const { return (mEndVelocity - mStartVelocity).norm(); }
    /// 1/2 m (|v_start|^2 - |v_end|^2) (J)
    double EnergyAbsorbed() const;
    /// The value an expectation checks, in its SI unit
    double Measure(const Expectation& inExpectation) const;
};

/// Where a run writes its replay file; empty: no recording.
struct CrashRunOptions
{
    std::filesystem::path mReplayFile;
    /// Refuse a scenario that would run with a warning instead of running it: a mesh whose stated forward
    /// axis is not its longest extent (samples::ForwardAxisWarning), rigid-part names that match
    /// no part, a time step too coarse for the car's overlap with its target (StepOverlapWarning)
    bool mStrict = false;
};

/// Loads the vehicle mesh (if any), builds the scene in the scenario's engine (a ground plane, the target,
/// the car as a box rigid body carrying the deformable mesh), runs it for mDuration and measures. Errors:
/// an unreadable mesh, an engine that was not built, a recorder that cannot write.
Result<CrashOutcome> RunCrash(const CrashScenario& inScenario, const CrashRunOptions& inOptions);

/// Largest displacement of the vertices in a zone of the body box (m): the outer quarter of its length
/// (front/rear) or width (left/right), the top fifth of its height between the front and rear quarters
/// (roof: the passenger compartment's), or all vertices (any). Zones overlap at corners: a frontal hit
/// also shows in left and right.
double ResidualCrush(const ffd::TriangleMesh& inRest, std::span<const Vec3> inPositions, EZone inZone);

/// A face's crush profile: the vertices of the face's outer quarter (rest position within a quarter of the
/// body's length, for an end, or width, for a side, of the face) whose inward move exceeds 1 cm span the
/// damage width; each of six equally spaced stations across it takes the deepest inward move of the quarter's
/// vertices within half a station spacing of it.
CrushProfile FaceCrushProfile(const ffd::TriangleMesh& inRest, std::span<const Vec3> inPositions,
                              ECarFace inFace);

/// The profile of the face a crash struck: of the four faces', the one of the largest CRASH3 average (the
/// front on a tie, and when nothing moved). A reverse into a wall is measured at the rear, a side pole at
/// the struck side.
CrushProfile StruckCrushProfile(const ffd::TriangleMesh& inRest, std::span<const Vec3> inPositions);

/// Largest residual displacement of a vertex along inForward (a unit direction in the body frame: the car's
/// initial direction of travel relative to the target), 0 when no vertex moved forward (m). The target
/// pushes the struck surface back against the travel; a vertex moved forward is damage that leaked from
/// the dent (a ripple of the direct-manipulation solve, a bulge on the unstruck side). Not the component
/// along the surface normal: in a crush the rear-facing faces inside the crushed volume move back too.
double OutwardDisplacement(const ffd::TriangleMesh& inRest, std::span<const Vec3> inPositions, const Vec3& inForward);

} // namespace crumple::crash
