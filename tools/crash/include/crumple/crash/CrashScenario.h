// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Math.h>
#include <crumple/ffd/FfdDeformerSettings.h>
#include <crumple/plugin/DamageMaterial.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace crumple::crash
{

/// The rigid-body engine a scenario runs on.
enum class EEngine : std::uint8_t
{
    Bullet,
    Ode,
};

/// What the vehicle hits.
enum class ETarget : std::uint8_t
{
    /// A fixed rigid wall; its face turned by TargetSpec::mAngleDegrees about the vertical from facing the car
    RigidWall,
    /// A fixed rigid vertical pole of TargetSpec::mPoleRadius on the car's path (side-impact and tree tests)
    Pole,
    /// A fixed rigid wall that covers only TargetSpec::mOverlapPercent of the car's width, on its left
    /// (+y) side (the offset frontal tests; rigid here, where IIHS/Euro NCAP use a deformable face)
    OffsetWall,
    /// Another car: a deformable box body of TargetSpec::mVehicle*, standing or moving, its nearest point on
    /// the subject car's path
    Vehicle,
    /// A destructible barrier (fem::TetSolver of a prop material preset) standing for a static box in the
    /// engine, face at x = 0, anchored at its base: the car's collisions become nodal impulses on it; when a
    /// piece breaks loose the engine box is removed and the car drives on
    FemBarrier,
};

/// Bounds on a car mesh's length once scaled (m): mesh_length_m, and the longest side of a mesh scaled by
/// mesh_unit_m. Outside them the unit is wrong (a file in millimetres read as metres, or the reverse).
inline constexpr double cMinMeshLength = 0.1;
inline constexpr double cMaxMeshLength = 1000.0;
/// A road vehicle's length (m): a car mesh scaled outside it runs with a warning (is the unit right?), and
/// --strict refuses it; a scale model may be meant.
inline constexpr double cRoadVehicleMinLength = 1.0;
inline constexpr double cRoadVehicleMaxLength = 30.0;

/// The vehicle: a mesh file or a procedural box body, its mass and its damage material. SI units throughout;
/// the body frame is x forward, y left, z up, centred on the body's bounding box.
struct VehicleSpec
{
    std::filesystem::path mMesh;       ///< OBJ, glTF/GLB, PLY, FBX (assimp); empty: a procedural box. A relative
                                       ///< path in a file is relative to the scenario file's folder;
                                       ///< ParseCrashScenario stores the resolved path
    std::string mMeshName;             ///< Only the file's meshes whose name contains this (empty: all)
    double mMeshLength = 4.2;          ///< A mesh is scaled to this length along x (m), > 0, unless mMeshUnit is set
    double mMeshUnit = 0.0;            ///< Metres per file unit (0.0254: inches), > 0; 0: scale to mMeshLength
    /// The file's forward and up axes, as indices of samples::EMeshAxis (+x, -x, +y, -y, +z, -z); -1: by file
    /// type, glTF +z forward and +y up (its specification), others +x forward and +z up
    int mMeshForwardAxis = -1;
    int mMeshUpAxis = -1;
    /// A mesh's edges longer than this are split at their midpoints (m), >= 0; 0: the file's triangles as
    /// they are. A long thin triangle cannot follow a pocket that varies along it and turns over although the
    /// dent folds nothing (ffd::RefineLongEdges); the default is the default control spacing, so that no
    /// triangle spans more than a lattice cell, the scale the dent field varies on.
    double mMeshMaxEdge = 0.15;
    /// After the re-cut (mMeshMaxEdge > 0), edges whose flip moves the surface by at most this (m) are flipped
    /// where that makes the triangles Delaunay (ffd::FlipNearlyFlatEdges), >= 0; 0: only exactly flat pairs.
    /// A bevel or T-junction leaves caps a fraction of a millimetre high that turn over in a dent although the
    /// field folds nothing; a millimetre is below what a crash measurement or picture resolves.
    double mMeshFlipDeviation = 0.001;
    /// The file's meshes whose node or mesh name contains one of these (any case) keep their shape and move
    /// with the body around their centre (samples::CarMeshSettings::mRigidPartNames): wheels stay round.
    std::vector<std::string> mMeshRigidParts{"wheel", "tire", "tyre"};
    /// The scenario gave mMeshRigidParts: a fragment that finds no part is then a warning (a refusal with
    /// --strict); the default list finds what a mesh has and warns of nothing
    bool mMeshRigidPartsGiven = false;
    Vec3 mBoxSize{4.2, 1.8, 1.4};      ///< Size of the procedural box (m); a mesh's collision box is its
                                       ///< bounding box
    double mMass = 1200.0;             ///< kg, > 0
    /// Principal moments of inertia about the centre of mass (kg m^2); empty: those of a uniform box of
    /// mBoxSize and mMass
    std::optional<Vec3> mInertia;
    /// Without mInertia: false, a uniform solid box of the collision box; true, a uniform thin shell over the
    /// mesh's triangles (area-weighted), about the box centre, its diagonal taken as the principal moments
    bool mInertiaFromMesh = false;
    plugin::DamageMaterial mMaterial;  ///< Dent per impulse and its limits
    double mMaxTotalDeformation = 1.5; ///< Most any vertex may ever move, all collisions together (m), >= 0
    std::array<int, 3> mControlCount{{0, 0, 0}}; ///< FFD controls of the fitted zone, each >= 4; 0: from mControlSpacing
    double mControlSpacing = 0.15; ///< Control spacing (m) of zones without a control count (DeformableObjectSettings)
    /// control_spacing_m was given; without it (and without a control count or zones) the fitted zone's
    /// spacing is mControlSpacing or finer, as fine as the body's occupant cell needs
    /// (DeformableObjectSettings::mFitSpacingToOccupantCell)
    bool mControlSpacingGiven = false;
    /// Deformation zones (axis-aligned boxes in the body frame, each with its controls and total bound); empty:
    /// one zone fitted around the body with mControlCount and mMaxTotalDeformation
    std::vector<ffd::FfdZoneSettings> mZones;
};

/// The target.
struct TargetSpec
{
    ETarget mType = ETarget::RigidWall;
    double mAngleDegrees = 0.0; ///< Rigid wall: angle between its normal and the car's path (deg), in (-90, 90)
    double mPoleRadius = 0.127; ///< Pole: radius (m), > 0 (254 mm, the FMVSS 214 pole)
    double mOverlapPercent = 40.0; ///< Offset wall: share of the car's width it covers (%), in (0, 100]
    double mVehicleMass = 1500.0;              ///< Vehicle: kg, > 0
    Vec3 mVehicleSize{4.4, 1.7, 1.4};          ///< Vehicle: box size (m), each > 0
    double mVehicleHeadingDegrees = 90.0;      ///< Vehicle: heading from the subject's path (deg); 90 = side impact
    double mVehicleSpeed = 0.0;                ///< Vehicle: speed along its heading (m/s), >= 0
    double mVehicleOffset = 0.0;               ///< Vehicle: its centre's sideways position (m)
    Vec3 mBarrierSize{0.2, 3.0, 1.2};          ///< FEM barrier: thickness (x), width (y), height (z) (m), each > 0
    std::string mBarrierMaterial = "brick";    ///< FEM barrier: a fem::EPropMaterial preset name
    double mBarrierCell = 0.2;                 ///< FEM barrier: cube size of its tetrahedral grid (m), > 0
};

/// How the vehicle arrives.
struct ImpactSpec
{
    double mSpeed = 15.0;         ///< Speed at the start (m/s), > 0 (scenario files may give km/h)
    double mHeadingDegrees = 0.0; ///< Extra yaw of the car relative to its path (deg)
    double mOffset = 0.0;         ///< Sideways offset of the car's centre line from the target's centre (m)
};

/// A number the run measures, to check against an expectation.
enum class EQuantity : std::uint8_t
{
    ResidualCrush,       ///< Largest residual vertex displacement in a zone (m)
    DeltaV,              ///< Change of the car's velocity over the run, |v_end - v_start| (m/s)
    TotalImpulse,        ///< Sum of the car's collision impulses (N s)
    EnergyAbsorbed,      ///< Kinetic energy lost, 1/2 m (|v_start|^2 - |v_end|^2) (J)
    Collisions,          ///< Number of collisions involving the car
    FoldedVertices,      ///< Car body vertices whose surface normal the dents turned over (a fold): count
    OutwardDisplacement, ///< Largest residual displacement of a car vertex forward, along the car's initial
                         ///< direction of travel (m): a crush pushes the struck surface back, so a vertex
                         ///< moved forward is damage that leaked out of the dent (a ripple, a bulge)
    FoldedTriangles,     ///< Car body triangles whose face normal the dents turned over: count
    CrushAverage,        ///< CRASH3 average of the struck face's crush profile C1..C6 (m; StruckCrushProfile)
    PeakDeceleration, ///< Largest deceleration of the car along its initial travel (m/s^2): CFC 60 (SAE J211)
                      ///< when the engine step samples at >= 600 Hz, else the unfiltered step differences
    TimeToZeroVelocity, ///< First time the car's velocity along its initial travel reaches 0 (s); infinite:
                        ///< never
    WallGap, ///< Rigid and offset walls only: the mean distance the struck front ended behind the wall's
             ///< final plane (m, MeasureWallGap's mMean): a flat wall leaves a flat front, so this is its
             ///< dome
};

/// Where on the body a ResidualCrush is measured: the outer quarter of the body box along an axis (the
/// top fifth between the front and rear quarters for the roof), or anywhere. Zones overlap at corners.
enum class EZone : std::uint8_t
{
    Any,
    Front,
    Rear,
    Left,
    Right,
    Roof,
};

/// "This quantity must lie in [mMin, mMax]" (either bound may be infinite).
struct Expectation
{
    EQuantity mQuantity = EQuantity::ResidualCrush;
    EZone mZone = EZone::Any; ///< ResidualCrush only
    double mMin = -std::numeric_limits<double>::infinity(); ///< In the quantity's SI unit
    double mMax = std::numeric_limits<double>::infinity();  ///< In the quantity's SI unit
    std::string mText; ///< The expectation as written in the file, for messages
    double mDisplayScale = 1.0; ///< Measured SI value x this = the value in mText's unit (3.6 for km/h)
};

/// A crash test: vehicle, target, impact, engine, duration, expectations, outputs. Built by LoadCrashScenario.
struct CrashScenario
{
    std::string mName;                ///< Shown in reports
    EEngine mEngine = EEngine::Bullet;
    double mDuration = 0.6;           ///< Simulated time (s), > 0
    double mTimeStep = 1.0 / 120.0;   ///< Engine step (s), in [1e-6, 0.05]
    VehicleSpec mVehicle;
    TargetSpec mTarget;
    ImpactSpec mImpact;
    std::vector<Expectation> mExpectations;
    bool mPictures = true;            ///< Write PNG renders (needs EGL; skipped with a note without it)
    /// Sanity check impulse_momentum: largest relative disagreement between Crumple's impulses on the car and
    /// the car's momentum change over the collisions (crumple-crash --impulse-tolerance), in (0, 1]. 0.05: the
    /// engine scenes agree within 3 % (tests/engines), and rolling resistance over a crash pulse adds < 0.3 %.
    double mImpulseTolerance = 0.05;
};

/// The FEM barrier's material names, in fem::EPropMaterial order.
constexpr std::array<const char*, 5> cBarrierMaterialNames{"glass", "wood", "brick", "rubber", "steel"};

const char* ToString(EEngine inEngine);
const char* ToString(EQuantity inQuantity);
const char* ToString(EZone inZone);

} // namespace crumple::crash
