// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/crash/CrashRun.h>

#include "CarMesh.h"
#include "EngineCrash.h"
#include "FemBarrierCoupling.h"
#include "SurfaceFolds.h"

#include <crumple/crash/RecutCarMesh.h>
#include <crumple/crash/StepOverlap.h>
#include <crumple/crash/TimeHistory.h>

#include <crumple/ffd/BoundingBox.h>
#include <crumple/plugin/DamageRecorder.h>

#if defined(CRUMPLE_CRASH_BULLET)
#include "BulletWallCrash.h"
#endif
#if defined(CRUMPLE_CRASH_ODE)
#include "OdeWallCrash.h"
#endif

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

namespace crumple::crash
{

namespace
{

// The loaded body's size (m, once scaled) against what a car can be: refused outside 0.1-1000 m (a unit off
// by a thousand: a 4 mm or a 4 km car runs and fails its sanity checks with no word of the cause) or under
// 0.1 m along any axis (a flat or squashed body: the engines let a wall through it, or drop it through the
// ground); warned of outside a road vehicle's 1-30 m (a unit off by ten; a scale model may be meant), and
// refused so under inStrict.
Status CheckBodySize(const VehicleSpec& inVehicle, const Vec3& inSize, bool inStrict,
                     std::vector<std::string>& outWarnings)
{
    const std::string file = inVehicle.mMesh.filename().string();
    char text[320];
    if (!(inSize.maxCoeff() >= cMinMeshLength && inSize.maxCoeff() <= cMaxMeshLength))
    {
        char scaled[64];
        if (inVehicle.mMeshUnit > 0.0)
            std::snprintf(scaled, sizeof(scaled), "mesh_unit_m %g", inVehicle.mMeshUnit);
        else
            std::snprintf(scaled, sizeof(scaled), "scaled to mesh_length_m %g along x",
                          inVehicle.mMeshLength);
        std::snprintf(
            text, sizeof(text),
            "%s measures %.3g m across once scaled (%s): a car body must measure %g-%g m; is the unit right?",
            file.c_str(), inSize.maxCoeff(), scaled, cMinMeshLength, cMaxMeshLength);
        return MakeError(EError::OutOfRange, text);
    }
    if (!(inSize.minCoeff() >= cMinMeshLength))
    {
        std::snprintf(text, sizeof(text),
                      "%s measures %.3g x %.3g x %.3g m (length, width, height) once scaled: a car body must "
                      "measure at least %g m along each axis (a flat sheet or a squashed mesh cannot crash)",
                      file.c_str(), inSize.x(), inSize.y(), inSize.z(), cMinMeshLength);
        return MakeError(EError::OutOfRange, text);
    }
    if (!(inSize.maxCoeff() >= cRoadVehicleMinLength && inSize.maxCoeff() <= cRoadVehicleMaxLength))
    {
        std::snprintf(text, sizeof(text),
                      "%s is %.3g m long once scaled, outside a road vehicle's %g-%g m: is the unit right "
                      "(mesh_unit_m, mesh_length_m)?",
                      file.c_str(), inSize.maxCoeff(), cRoadVehicleMinLength, cRoadVehicleMaxLength);
        if (inStrict)
            return MakeError(EError::InvalidArgument, std::string(text) + "; refused by --strict");
        outWarnings.push_back(text);
    }
    return Status::Ok();
}

// The collision window of a crash run (s).
constexpr double cCrashPulseWindow = 0.15;
// m: how far inside an offset wall's edge its wall gap is measured (MeasureWallGap's WallReach): the crush
// field fades across the footprint's edge over about the default control spacing.
constexpr double cWallEdgeMargin = 0.15;

// Principal moments (the diagonal) of a uniform thin shell of mass inMass over the mesh's triangles, about
// inCentre: a triangle of area A and corners x_i has integral x x^T dA = A / 12 (sum x_i x_i^T + s s^T),
// s = sum x_i.
Vec3 ShellInertia(const ffd::TriangleMesh& inMesh, const Vec3& inCentre, double inMass)
{
    Mat3 second = Mat3::Zero();
    double area = 0.0;
    for (const auto& triangle : inMesh.mTriangles)
    {
        const Vec3 a = inMesh.mPositions[triangle[0]] - inCentre, b = inMesh.mPositions[triangle[1]] - inCentre,
                   c = inMesh.mPositions[triangle[2]] - inCentre;
        const double triangle_area = 0.5 * (b - a).cross(c - a).norm();
        const Vec3 s = a + b + c;
        second += triangle_area / 12.0 * (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
        area += triangle_area;
    }
    second *= inMass / area;
    const Mat3 inertia = second.trace() * Mat3::Identity() - second;
    return inertia.diagonal();
}

// The scenario in the shared engine scene's terms.
Result<common::EngineCrashSettings> SceneSettings(const CrashScenario& inScenario, const CrashRunOptions& inOptions,
                                                  std::vector<std::string>& outWarnings,
                                                  std::optional<MeshPreparation>& outPreparation)
{
    const VehicleSpec& vehicle = inScenario.mVehicle;
    common::EngineCrashSettings settings;
    settings.mMass = vehicle.mMass;
    settings.mInertia = vehicle.mInertia;
    settings.mMaterial = vehicle.mMaterial;
    settings.mMaxTotalDeformation = vehicle.mMaxTotalDeformation;
    settings.mZones = vehicle.mZones;
    settings.mControlCount = vehicle.mControlCount;
    settings.mControlSpacing = vehicle.mControlSpacing;
    // intent: unless the scenario chose the spacing, a body shorter than 2.4 m gets the finer lattice its
    // occupant cell needs (DeformableObjectSettings::mFitSpacingToOccupantCell)
    settings.mFitSpacingToOccupantCell = !vehicle.mControlSpacingGiven;
    settings.mSpeed = inScenario.mImpact.mSpeed;
    settings.mYawDegrees = inScenario.mImpact.mHeadingDegrees;
    settings.mOffset = inScenario.mImpact.mOffset;
    settings.mWallAngleDegrees = inScenario.mTarget.mAngleDegrees;
    if (inScenario.mTarget.mType == ETarget::Pole)
        settings.mPoleRadius = inScenario.mTarget.mPoleRadius;
    if (inScenario.mTarget.mType == ETarget::OffsetWall)
        settings.mOverlapFraction = inScenario.mTarget.mOverlapPercent / 100.0;
    if (inScenario.mTarget.mType == ETarget::FemBarrier)
    {
        settings.mDriveOnly = true; // the engine never sees the barrier: FemBarrierCoupling meets the car
        settings.mWorld.mCountImpactOnce = false; // it reports each step's share of its push as an impulse
        settings.mWallAngleDegrees = 0.0;
    }
    if (inScenario.mTarget.mType == ETarget::Vehicle)
    {
        const TargetSpec& target = inScenario.mTarget;
        common::TargetVehicleSettings other;
        other.mHalfExtents = 0.5 * target.mVehicleSize;
        other.mMass = target.mVehicleMass;
        other.mYawDegrees = target.mVehicleHeadingDegrees;
        other.mSpeed = target.mVehicleSpeed;
        other.mOffset = target.mVehicleOffset;
        other.mMaterial = inScenario.mVehicle.mMaterial; // the same body material as the subject car
        settings.mTargetVehicle = other;
        settings.mWallAngleDegrees = 0.0;
    }
    // One collision per crash pulse: a car's crush against a barrier lasts about 0.1 s, longer than the
    // core's default window for game impacts (a yielding or crushing contact reaches Crumple over that time).
    settings.mWorld.mGrouping.mTimeWindow = cCrashPulseWindow;
    settings.mTimeStep = inScenario.mTimeStep;
    settings.mDuration = inScenario.mDuration;
    settings.mHalfExtents = 0.5 * vehicle.mBoxSize;
    if (!vehicle.mMesh.empty())
    {
        // glTF is +y up, +z forward by its specification; other formats are taken as x forward, z up.
        samples::CarMeshSettings mesh;
        mesh.mPath = vehicle.mMesh;
        mesh.mMeshName = vehicle.mMeshName;
        mesh.mLength = vehicle.mMeshLength;
        mesh.mUnit = vehicle.mMeshUnit;
        mesh.mRigidPartNames = vehicle.mMeshRigidParts;
        // intent: the glTF axes go by the extension in any case (TRUCK.GLB was read as +x forward, z up)
        std::string extension = vehicle.mMesh.extension().string();
        std::transform(extension.begin(), extension.end(), extension.begin(),
                       [](unsigned char inChar) { return static_cast<char>(std::tolower(inChar)); });
        const bool gltf = extension == ".gltf" || extension == ".glb";
        const auto forward = vehicle.mMeshForwardAxis >= 0 ? static_cast<samples::EMeshAxis>(vehicle.mMeshForwardAxis)
                                                           : (gltf ? samples::EMeshAxis::PlusZ : samples::EMeshAxis::PlusX);
        const auto up = vehicle.mMeshUpAxis >= 0 ? static_cast<samples::EMeshAxis>(vehicle.mMeshUpAxis)
                                                 : (gltf ? samples::EMeshAxis::PlusY : samples::EMeshAxis::PlusZ);
        Result<Mat3> rotation = samples::FileToBodyRotation(forward, up);
        if (rotation.HasError())
            return rotation.GetError();
        mesh.mFileToBody = rotation.Get();
        Result<samples::CarBody> body = samples::LoadCarBody(mesh);
        if (body.HasError())
            return body.GetError();
        const ffd::AlignedBox box = ffd::BoundingBox(body.Get().mMesh.mPositions);
        if (Status sized = CheckBodySize(vehicle, box.mMax - box.mMin, inOptions.mStrict, outWarnings);
            !sized)
            return sized.GetError();
        if (const std::vector<std::string>& unmatched = body.Get().mUnmatchedRigidPartNames;
            vehicle.mMeshRigidPartsGiven && !unmatched.empty())
        {
            std::string text = vehicle.mMesh.filename().string() + ": mesh_rigid_parts";
            for (std::size_t i = 0; i < unmatched.size(); ++i)
                text += (i == 0 ? " \"" : ", \"") + unmatched[i] + "\"";
            text += " name" + std::string(unmatched.size() == 1 ? "s" : "") + " no node or mesh of the file (parts found:";
            for (const std::string& name : body.Get().mRigidPartNames)
                text += " " + name;
            text += body.Get().mRigidPartNames.empty() ? " none)" : ")";
            if (inOptions.mStrict)
                return MakeError(EError::InvalidArgument, text + "; refused by --strict");
            outWarnings.push_back(text);
        }
        Result<ffd::TriangleMesh> loaded = std::move(body.Get().mMesh);
        std::vector<std::vector<std::uint32_t>> rigid_parts = std::move(body.Get().mRigidParts);
        if (const std::string warning = samples::ForwardAxisWarning(loaded.Get()); !warning.empty())
        {
            const std::string text = vehicle.mMesh.filename().string() + ": " + warning + " (forward " +
                                     std::string(samples::cMeshAxisNames[static_cast<int>(forward)]) + ", up " +
                                     std::string(samples::cMeshAxisNames[static_cast<int>(up)]) +
                                     "; scenario keys mesh_forward_axis and mesh_up_axis)";
            if (inOptions.mStrict)
                return MakeError(EError::InvalidArgument, text + "; refused by --strict");
            outWarnings.push_back(text);
        }
        Result<MeshPreparation> preparation =
            RecutCarMesh(loaded.Get(), rigid_parts, vehicle.mMeshMaxEdge, vehicle.mMeshFlipDeviation);
        if (preparation.HasError())
            return preparation.GetError();
        outPreparation = preparation.Get();
        // The collision box is the mesh's bounding box.
        const ffd::AlignedBox bounds = ffd::BoundingBox(loaded.Get().mPositions);
        settings.mHalfExtents = 0.5 * (bounds.mMax - bounds.mMin);
        if (vehicle.mInertiaFromMesh)
            settings.mInertia = ShellInertia(loaded.Get(), 0.5 * (bounds.mMin + bounds.mMax), vehicle.mMass);
        settings.mCarMesh = std::move(loaded.Get());
        settings.mCarRigidParts = std::move(rigid_parts);
    }
    if (const std::string warning =
            StepOverlapWarning(inScenario, MeasureStepOverlap(inScenario, settings.mHalfExtents));
        !warning.empty())
    {
        if (inOptions.mStrict)
            return MakeError(EError::InvalidArgument, warning + "; refused by --strict");
        outWarnings.push_back(warning);
    }
    return settings;
}

// The car front's crush pressure from its dent material: the material's no-damage impulse is Campbell's
// b0 times the mass, and a full-frontal rigid-wall hit at v dents C = factor (m v - m b0), so b1 = 1 / (factor m).
CarCrushPressure CrushPressure(const common::EngineCrashSettings& inSettings)
{
    const double mass = inSettings.mMass;
    const double width = 2.0 * inSettings.mHalfExtents.y(), height = 2.0 * inSettings.mHalfExtents.z();
    if (inSettings.mMaterial.mModel == plugin::ECrushModel::Campbell)
    {
        // Campbell's force per unit width A + B C, spread over the front's height.
        CarCrushPressure crush;
        crush.mAtZero = inSettings.mMaterial.mCrushA / height;
        crush.mPerMetre = inSettings.mMaterial.mCrushB / height;
        return crush;
    }
    const double b0 = inSettings.mMaterial.mImpulseThreshold / mass;
    CarCrushPressure crush;
    if (!(inSettings.mMaterial.mDeformationFactor > 0.0))
    {
        crush.mPerMetre = std::numeric_limits<double>::infinity(); // a front that never dents is rigid
        return crush;
    }
    const double b1 = 1.0 / (inSettings.mMaterial.mDeformationFactor * mass);
    crush.mAtZero = mass * b0 * b1 / width / height;
    crush.mPerMetre = mass * b1 * b1 / width / height;
    return crush;
}

// The world bounding box of the car's collision box.
ffd::AlignedBox CarWorldBounds(const Transform& inCar, const Vec3& inHalfExtents)
{
    ffd::AlignedBox bounds{Vec3::Constant(std::numeric_limits<double>::infinity()),
                           Vec3::Constant(-std::numeric_limits<double>::infinity())};
    for (int corner = 0; corner < 8; ++corner)
    {
        const Vec3 local((corner & 1) ? inHalfExtents.x() : -inHalfExtents.x(),
                         (corner & 2) ? inHalfExtents.y() : -inHalfExtents.y(),
                         (corner & 4) ? inHalfExtents.z() : -inHalfExtents.z());
        bounds.mMin = bounds.mMin.cwiseMin(inCar.ToWorld(local));
        bounds.mMax = bounds.mMax.cwiseMax(inCar.ToWorld(local));
    }
    return bounds;
}

// Runs one engine's scene to the end and fills the outcome.
template <class Scene>
Result<CrashOutcome> RunScene(const common::EngineCrashSettings& inSettings, const CrashRunOptions& inOptions,
                              const TargetSpec& inTarget)
{
    Scene scene(inSettings);
    // A destructible barrier stands with its face at x = 0, centred on y = 0, on the ground.
    std::optional<FemBarrierCoupling> barrier;
    const Vec3 barrier_centre = 0.5 * Vec3(inTarget.mBarrierSize.x(), 0.0, inTarget.mBarrierSize.z());
    if (inTarget.mType == ETarget::FemBarrier)
    {
        Result<FemBarrierCoupling> created = FemBarrierCoupling::Create(inTarget, barrier_centre, scene.GetDamage());
        if (created.HasError())
            return created.GetError();
        barrier.emplace(std::move(created.Get()));
    }
    // intent: refused before anything is written (the recorder below opens its file)
    std::vector<std::string> scene_warnings;
    if (const plugin::OccupantCellFit cell =
            scene.GetDamage().GetObject(scene.GetCarObject())->GetOccupantCellFit();
        cell.IsLost())
    {
        char text[400];
        std::snprintf(
            text, sizeof(text),
            "the car's lattice is too coarse to keep its occupant cell: its control spacing along the body "
            "(%.3g m) does not fit four times in a crush zone (%.3g m), so a crush along the body can move "
            "all of it; control_spacing_m %.3g or finer keeps the cell",
            cell.mSpacing, cell.mZoneLength, cell.mMaxSpacing);
        if (inOptions.mStrict)
            return MakeError(EError::InvalidArgument, std::string(text) + "; refused by --strict");
        scene_warnings.push_back(text);
    }
    std::unique_ptr<plugin::DamageRecorder> recorder;
    if (!inOptions.mReplayFile.empty())
    {
        Result<std::unique_ptr<plugin::DamageRecorder>> created =
            plugin::DamageRecorder::Create(inOptions.mReplayFile, scene.GetDamage());
        if (created.HasError())
            return created.GetError();
        recorder = std::move(created.Get());
    }
    CrashOutcome outcome;
    outcome.mWarnings = std::move(scene_warnings);
    outcome.mMass = inSettings.mMass;
    outcome.mGroundDeceleration =
        inSettings.mFloating ? 0.0 : inSettings.mGroundFriction * common::cCrashGravity;
    outcome.mStartVelocity = scene.GetCarState().mLinearVelocity;
    outcome.mStartTransform = scene.GetCarState().mTransform;
    outcome.mRestNormals = scene.GetDamage().GetObject(scene.GetCarObject())->GetDeformer().GetNormals();
    const int steps = static_cast<int>(std::lround(inSettings.mDuration / inSettings.mTimeStep));
    const plugin::BodyId car_body = scene.GetDamage().GetObjectBody(scene.GetCarObject());
    const CarCrushPressure crush = CrushPressure(inSettings);
    auto sample = [&](double inTime) {
        const plugin::BodyState car = scene.GetCarState();
        outcome.mHistory.push_back({inTime, car.mTransform.mTranslation, car.mLinearVelocity});
    };
    outcome.mHistory.reserve(static_cast<std::size_t>(steps) + 1);
    sample(0.0);
    const double edge_snap = scene.GetDamage().GetObject(scene.GetCarObject())->GetDeformer().GetMinSpacing();
    for (int step = 0; step < steps; ++step)
    {
        // Two-way: the barrier's contacts change the car's velocity before the engine moves it, and the
        // barrier's nodes take the opposite impulses.
        if (barrier)
        {
            const plugin::BodyState car = scene.GetCarState();
            Result<CarVelocity> after =
                barrier->Collide(car, car_body, inSettings.mHalfExtents, crush, inSettings.mMaxTotalDeformation, edge_snap,
                                 step * inSettings.mTimeStep, inSettings.mTimeStep, scene.GetDamage());
            if (after.HasError())
                return after.GetError();
            if (after.Get().mLinear != car.mLinearVelocity || after.Get().mAngular != car.mAngularVelocity)
                scene.SetCarVelocity(after.Get().mLinear, after.Get().mAngular);
        }
        scene.Step();
        if (barrier)
        {
            if (Result<fem::TetStepResult> result = barrier->Step(inSettings.mTimeStep); result.HasError())
                return result.GetError();
            // Breached: the car's box has passed the barrier's back face by more than its front can crush.
            if (std::isnan(outcome.mBarrierBreachTime) &&
                CarWorldBounds(scene.GetCarState().mTransform, inSettings.mHalfExtents).mMax.x() >
                    inTarget.mBarrierSize.x() + inSettings.mMaxTotalDeformation)
                outcome.mBarrierBreachTime = (step + 1) * inSettings.mTimeStep;
        }
        sample((step + 1) * inSettings.mTimeStep);
    }
    scene.GetDamage().Flush();
    if (barrier)
    {
        outcome.mBarrierFragments = static_cast<int>(barrier->GetSolver().ComputeFragments().size());
        outcome.mBarrierBrokenLinks = barrier->GetSolver().GetBrokenLinkCount();
        outcome.mBarrierMomentum = barrier->GetMomentumReceived();
    }
    outcome.mEndVelocity = scene.GetCarState().mLinearVelocity;
    outcome.mEndTransform = scene.GetCarState().mTransform;
    if (recorder)
        if (Status status = recorder->Close(); status.HasError())
            return status.GetError();

    outcome.mLimitedDents = scene.GetCounter().mLimitedDents;
    outcome.mStackedUpDents = scene.GetCounter().mStackedUpDents;
    for (const plugin::Collision& collision : scene.GetCounter().mLog)
    {
        const double impulse = collision.TotalImpulse();
        outcome.mCollisions.push_back({collision.mStartTime, collision.mEndTime, impulse,
                                       static_cast<int>(collision.mContacts.size())});
        outcome.mTotalImpulse += impulse;
        // Each contact pushes A along its normal (B to A) with its friction, and B the other way.
        const double side = collision.mBodyA == car_body ? 1.0 : collision.mBodyB == car_body ? -1.0 : 0.0;
        for (const plugin::CollisionContact& contact : collision.mContacts)
            outcome.mCarImpulse += side * contact.ImpulseOnA();
        if (side != 0.0)
        {
            outcome.mImpactStartTime = std::isnan(outcome.mImpactStartTime)
                                           ? collision.mStartTime
                                           : std::min(outcome.mImpactStartTime, collision.mStartTime);
            outcome.mImpactEndTime = std::isnan(outcome.mImpactEndTime) ? collision.mEndTime
                                                                         : std::max(outcome.mImpactEndTime, collision.mEndTime);
        }
        outcome.mPeakImpulse = std::max(outcome.mPeakImpulse, impulse);
    }
    // intent: a run in which the car met nothing (too slow or too short to reach the target) says so: its
    // expectations on crush would otherwise read as a car that took the hit undamaged
    if (std::isnan(outcome.mImpactStartTime))
    {
        char text[200];
        std::snprintf(
            text, sizeof(text),
            "the car met nothing in %g s (it started at %.3g m/s): it stopped short of the target or "
            "passed it by; check duration_s, the speed and the target's placement",
            inSettings.mDuration, outcome.mStartVelocity.norm());
        outcome.mWarnings.push_back(text);
    }
    const ffd::FfdDeformer& car = scene.GetDamage().GetObject(scene.GetCarObject())->GetDeformer();
    outcome.mRestMesh = car.GetRestMesh();
    outcome.mPositions = car.GetPositions();
    outcome.mNormals = car.GetNormals();
    for (EZone zone : {EZone::Any, EZone::Front, EZone::Rear, EZone::Left, EZone::Right, EZone::Roof})
        outcome.mResidualCrush[static_cast<int>(zone)] = ResidualCrush(outcome.mRestMesh, outcome.mPositions, zone);
    outcome.mFoldedVertices = common::FoldedVertices(outcome.mRestMesh, outcome.mPositions);
    outcome.mFoldedTriangles = common::FoldedTriangles(outcome.mRestMesh, outcome.mPositions);
    outcome.mCrushProfile = StruckCrushProfile(outcome.mRestMesh, outcome.mPositions);
    // intent: the car's initial travel in its own frame; a standing car (a target hitting it) has none
    const double start_speed = outcome.mStartVelocity.norm();
    if (start_speed > 0.0)
        outcome.mOutwardDisplacement = OutwardDisplacement(
            outcome.mRestMesh, outcome.mPositions,
            outcome.mStartTransform.DirectionToBody(outcome.mStartVelocity / start_speed));
    if (inTarget.mType == ETarget::RigidWall)
    {
        // The wall's face is the plane n . x = 0, n pointing into the wall (SanityChecks' NoTunnelling); in
        // the body frame as the car met it (the dents are planned in the body frame at the collision).
        const double angle = inTarget.mAngleDegrees * std::numbers::pi / 180.0;
        const Vec3 into_wall(std::cos(angle), std::sin(angle), 0.0);
        outcome.mWallGap = MeasureWallGap(outcome.mRestMesh, outcome.mRestNormals, outcome.mPositions,
                                          outcome.mStartTransform.DirectionToBody(into_wall));
    }
    if (inTarget.mType == ETarget::OffsetWall)
    {
        // The offset wall's face is x = 0 (n = +x) where y >= its edge (common::CrashWallLeftEdge). A point p
        // of the body at the start is at y = (R^T e_y) . p + t_y there; the field fades across the edge over
        // about a control spacing, so the wall's reach starts that far inside it.
        const Transform& start = outcome.mStartTransform;
        const WallReach reach{start.DirectionToBody(Vec3::UnitY()), common::CrashWallLeftEdge(inSettings) +
                                                                        cWallEdgeMargin -
                                                                        start.mTranslation.y()};
        outcome.mWallGap = MeasureWallGap(outcome.mRestMesh, outcome.mRestNormals, outcome.mPositions,
                                          start.DirectionToBody(Vec3::UnitX()), &reach);
    }
    if (scene.GetTargetObject().IsValid())
    {
        const ffd::FfdDeformer& target = scene.GetDamage().GetObject(scene.GetTargetObject())->GetDeformer();
        outcome.mTargetResidualCrush = ResidualCrush(target.GetRestMesh(), target.GetPositions(), EZone::Any);
    }
    return outcome;
}

} // namespace

double CrashOutcome::EnergyAbsorbed() const
{
    return 0.5 * mMass * (mStartVelocity.squaredNorm() - mEndVelocity.squaredNorm());
}

double CrashOutcome::Measure(const Expectation& inExpectation) const
{
    switch (inExpectation.mQuantity)
    {
    case EQuantity::ResidualCrush:
        return mResidualCrush[static_cast<int>(inExpectation.mZone)];
    case EQuantity::DeltaV:
        return DeltaV();
    case EQuantity::TotalImpulse:
        return mTotalImpulse;
    case EQuantity::EnergyAbsorbed:
        return EnergyAbsorbed();
    case EQuantity::Collisions:
        return static_cast<double>(mCollisions.size());
    case EQuantity::FoldedVertices:
        return static_cast<double>(mFoldedVertices);
    case EQuantity::FoldedTriangles:
        return static_cast<double>(mFoldedTriangles);
    case EQuantity::PeakDeceleration:
        return MakeTimeHistory(*this).mPeakDeceleration;
    case EQuantity::TimeToZeroVelocity:
    {
        const double time = MakeTimeHistory(*this).mTimeToZeroVelocity;
        return time < 0.0 ? std::numeric_limits<double>::infinity() : time;
    }
    case EQuantity::CrushAverage:
        return mCrushProfile.Average();
    case EQuantity::OutwardDisplacement:
        return mOutwardDisplacement;
    case EQuantity::WallGap:
        return mWallGap ? mWallGap->mMean : std::numeric_limits<double>::quiet_NaN();
    }
    return std::numeric_limits<double>::quiet_NaN();
}

const char* CarFaceName(ECarFace inFace)
{
    switch (inFace)
    {
    case ECarFace::Front:
        return "front";
    case ECarFace::Rear:
        return "rear";
    case ECarFace::Left:
        return "left";
    case ECarFace::Right:
        return "right";
    }
    return "unknown";
}

CrushProfile FaceCrushProfile(const ffd::TriangleMesh& inRest, std::span<const Vec3> inPositions,
                              ECarFace inFace)
{
    constexpr double cDamaged = 0.01; // m: a move shallower than this is not damage
    // intent: the face's normal axis and outward sign, and the axis across it that the stations run along
    const bool end = inFace == ECarFace::Front || inFace == ECarFace::Rear;
    const int normal = end ? 0 : 1, across = end ? 1 : 0;
    const double outward = inFace == ECarFace::Front || inFace == ECarFace::Left ? 1.0 : -1.0;
    const ffd::AlignedBox bounds = ffd::BoundingBox(inRest.mPositions);
    const double extent = bounds.mMax[normal] - bounds.mMin[normal];
    const double face = outward > 0.0 ? bounds.mMax[normal] : bounds.mMin[normal];
    const auto in_quarter = [&](const Vec3& inRestPoint)
    { return outward * (face - inRestPoint[normal]) <= 0.25 * extent; };
    const auto inward = [&](std::size_t inVertex)
    { return outward * (inRest.mPositions[inVertex][normal] - inPositions[inVertex][normal]); };
    CrushProfile profile;
    profile.mFace = inFace;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (std::size_t v = 0; v < inPositions.size(); ++v)
        if (in_quarter(inRest.mPositions[v]) && inward(v) > cDamaged)
        {
            lo = std::min(lo, inRest.mPositions[v][across]);
            hi = std::max(hi, inRest.mPositions[v][across]);
        }
    if (!(hi > lo))
        return profile;
    profile.mDamageWidth = hi - lo;
    const double spacing = profile.mDamageWidth / 5.0;
    std::array<bool, 6> measured{};
    for (std::size_t v = 0; v < inPositions.size(); ++v)
    {
        const Vec3& rest = inRest.mPositions[v];
        if (!in_quarter(rest))
            continue;
        const double crush = inward(v);
        for (std::size_t station = 0; station < 6; ++station)
            if (std::abs(rest[across] - (lo + static_cast<double>(station) * spacing)) <= 0.5 * spacing)
            {
                profile.mC[station] = measured[station] ? std::max(profile.mC[station], crush) : crush;
                measured[station] = true;
            }
    }
    // A coarse mesh may have no vertex near a station (a low-poly body's wide front face): it takes the
    // line between the nearest measured stations on either side (the two ends are always measured).
    for (std::size_t station = 1; station + 1 < 6; ++station)
    {
        if (measured[station])
            continue;
        std::size_t left = station - 1, right = station + 1;
        while (!measured[right])
            ++right;
        const double t = static_cast<double>(station - left) / static_cast<double>(right - left);
        profile.mC[station] = (1.0 - t) * profile.mC[left] + t * profile.mC[right];
    }
    return profile;
}

CrushProfile StruckCrushProfile(const ffd::TriangleMesh& inRest, std::span<const Vec3> inPositions)
{
    CrushProfile struck = FaceCrushProfile(inRest, inPositions, ECarFace::Front);
    for (ECarFace face : {ECarFace::Rear, ECarFace::Left, ECarFace::Right})
        if (CrushProfile profile = FaceCrushProfile(inRest, inPositions, face);
            profile.Average() > struck.Average())
            struck = profile;
    return struck;
}

double OutwardDisplacement(const ffd::TriangleMesh& inRest, std::span<const Vec3> inPositions, const Vec3& inForward)
{
    double largest = 0.0;
    for (std::size_t vertex = 0; vertex < inPositions.size(); ++vertex)
        largest = std::max(largest, (inPositions[vertex] - inRest.mPositions[vertex]).dot(inForward));
    return largest;
}

double ResidualCrush(const ffd::TriangleMesh& inRest, std::span<const Vec3> inPositions, EZone inZone)
{
    const ffd::AlignedBox bounds = ffd::BoundingBox(inRest.mPositions);
    const Vec3 size = bounds.mMax - bounds.mMin;
    double largest = 0.0;
    for (std::size_t vertex = 0; vertex < inPositions.size(); ++vertex)
    {
        const Vec3& p = inRest.mPositions[vertex];
        bool inside = true;
        switch (inZone)
        {
        case EZone::Any:
            break;
        case EZone::Front:
            inside = p.x() >= bounds.mMax.x() - 0.25 * size.x();
            break;
        case EZone::Rear:
            inside = p.x() <= bounds.mMin.x() + 0.25 * size.x();
            break;
        case EZone::Left:
            inside = p.y() >= bounds.mMax.y() - 0.25 * size.y();
            break;
        case EZone::Right:
            inside = p.y() <= bounds.mMin.y() + 0.25 * size.y();
            break;
        case EZone::Roof:
            // The passenger compartment's roof: the top fifth, between the front and rear quarters.
            inside = p.z() >= bounds.mMax.z() - 0.2 * size.z() && p.x() > bounds.mMin.x() + 0.25 * size.x() &&
                     p.x() < bounds.mMax.x() - 0.25 * size.x();
            break;
        }
        if (inside)
            largest = std::max(largest, (inPositions[vertex] - p).norm());
    }
    return largest;
}

Result<CrashOutcome> RunCrash(const CrashScenario& inScenario, const CrashRunOptions& inOptions)
{
    std::vector<std::string> warnings;
    std::optional<MeshPreparation> preparation;
    Result<common::EngineCrashSettings> settings = SceneSettings(inScenario, inOptions, warnings, preparation);
    if (settings.HasError())
        return settings.GetError();
    Result<CrashOutcome> outcome = MakeError(EError::InvalidArgument, "unknown engine");
    switch (inScenario.mEngine)
    {
    case EEngine::Bullet:
#if defined(CRUMPLE_CRASH_BULLET)
        outcome = RunScene<common::BulletWallCrash>(settings.Get(), inOptions, inScenario.mTarget);
#else
        outcome = MakeError(EError::InvalidArgument, "crumple-crash was built without Bullet (libbullet-dev)");
#endif
        break;
    case EEngine::Ode:
#if defined(CRUMPLE_CRASH_ODE)
        outcome = RunScene<common::OdeWallCrash>(settings.Get(), inOptions, inScenario.mTarget);
#else
        outcome = MakeError(EError::InvalidArgument, "crumple-crash was built without ODE (libode-dev)");
#endif
        break;
    }
    if (outcome.HasError())
        return outcome;
    // intent: the scenario's warnings first, then the scene's
    outcome.Get().mWarnings.insert(outcome.Get().mWarnings.begin(), warnings.begin(), warnings.end());
    outcome.Get().mMeshPreparation = preparation;
    return outcome;
}

} // namespace crumple::crash
