// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/crash/CrashRun.h>

#include "CarMesh.h"
#include "EngineCrash.h"

#include <crumple/ffd/BoundingBox.h>
#include <crumple/fem/CollisionImpulses.h>
#include <crumple/fem/PropMaterialPreset.h>
#include <crumple/fem/TetGrid.h>
#include <crumple/fem/TetSolver.h>
#include <crumple/plugin/DamageRecorder.h>

#if defined(CRUMPLE_CRASH_BULLET)
#include "BulletWallCrash.h"
#endif
#if defined(CRUMPLE_CRASH_ODE)
#include "OdeWallCrash.h"
#endif

#include <cmath>
#include <limits>
#include <numbers>

namespace crumple::crash
{

namespace
{

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
Result<common::EngineCrashSettings> SceneSettings(const CrashScenario& inScenario)
{
    const VehicleSpec& vehicle = inScenario.mVehicle;
    common::EngineCrashSettings settings;
    settings.mMass = vehicle.mMass;
    settings.mInertia = vehicle.mInertia;
    settings.mMaterial = vehicle.mMaterial;
    settings.mMaxTotalDeformation = vehicle.mMaxTotalDeformation;
    settings.mZones = vehicle.mZones;
    settings.mControlCount = vehicle.mControlCount;
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
        settings.mBarrierHalfExtents = 0.5 * inScenario.mTarget.mBarrierSize;
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
        const std::string extension = vehicle.mMesh.extension().string();
        if (extension == ".gltf" || extension == ".glb")
            mesh.mFileToBody << 0, 0, 1, 1, 0, 0, 0, 1, 0;
        Result<ffd::TriangleMesh> loaded = samples::LoadCarMesh(mesh);
        if (loaded.HasError())
            return loaded.GetError();
        // The collision box is the mesh's bounding box.
        const ffd::AlignedBox bounds = ffd::BoundingBox(loaded.Get().mPositions);
        settings.mHalfExtents = 0.5 * (bounds.mMax - bounds.mMin);
        if (vehicle.mInertiaFromMesh)
            settings.mInertia = ShellInertia(loaded.Get(), 0.5 * (bounds.mMin + bounds.mMax), vehicle.mMass);
        settings.mCarMesh = std::move(loaded.Get());
    }
    return settings;
}

// The destructible barrier: a tetrahedral grid of the barrier box in its engine body's frame (centred),
// anchored at its base, fed with the collisions on that body.
class FemBarrier : public plugin::DamageListener
{
public:
    static Result<std::unique_ptr<FemBarrier>> Create(const TargetSpec& inTarget, plugin::BodyId inBody)
    {
        static constexpr const char* cNames[] = {"glass", "wood", "brick", "rubber", "steel"};
        int material = 2;
        for (int index = 0; index < 5; ++index)
            if (inTarget.mBarrierMaterial == cNames[index])
                material = index;
        Result<fem::PropMaterialPreset> preset = fem::MakePropMaterialPreset(static_cast<fem::EPropMaterial>(material));
        if (preset.HasError())
            return preset.GetError();
        fem::TetGridSettings grid;
        grid.mOrigin = -0.5 * inTarget.mBarrierSize;
        grid.mSize = inTarget.mBarrierSize;
        for (int axis = 0; axis < 3; ++axis)
            grid.mCellCount[axis] = std::max(1, static_cast<int>(std::lround(inTarget.mBarrierSize[axis] / inTarget.mBarrierCell)));
        Result<fem::TetMesh> mesh = fem::TetGrid(grid);
        if (mesh.HasError())
            return mesh.GetError();
        fem::TetSolverSettings settings;
        settings.mIntegrator = fem::EIntegrator::SymplecticEuler; // follows the stress wave of a hit
        settings.mMaxSubSteps = 100000;
        Result<fem::TetSolver> solver = fem::TetSolver::Create(mesh.Get(), preset.Get().mMaterial, settings);
        if (solver.HasError())
            return solver.GetError();
        std::unique_ptr<FemBarrier> barrier(new FemBarrier(std::move(solver.Get()), inBody));
        for (int node = 0; node < barrier->mSolver.GetNodeCount(); ++node)
            if (barrier->mSolver.GetNodeRestPositions()[node].z() <= grid.mOrigin.z() + 1e-9)
                (void)barrier->mSolver.SetNodeFixed(node, true);
        return barrier;
    }
    void OnCollision(const plugin::Collision& inCollision, std::span<const plugin::ObjectDent>) override
    {
        if (inCollision.mBodyA == mBody || inCollision.mBodyB == mBody)
            (void)fem::ApplyCollision(mSolver, inCollision, mBody);
    }
    fem::TetSolver mSolver;

private:
    FemBarrier(fem::TetSolver inSolver, plugin::BodyId inBody) : mSolver(std::move(inSolver)), mBody(inBody) {}
    plugin::BodyId mBody;
};

// Runs one engine's scene to the end and fills the outcome.
template <class Scene, class VelocityOf, class TransformOf>
Result<CrashOutcome> RunScene(const common::EngineCrashSettings& inSettings, const CrashRunOptions& inOptions,
                              const TargetSpec& inTarget, VelocityOf inVelocityOf, TransformOf inTransformOf)
{
    Scene scene(inSettings);
    std::unique_ptr<FemBarrier> barrier;
    if (inTarget.mType == ETarget::FemBarrier)
    {
        Result<std::unique_ptr<FemBarrier>> created = FemBarrier::Create(inTarget, scene.GetBarrierBody());
        if (created.HasError())
            return created.GetError();
        barrier = std::move(created.Get());
        scene.GetDamage().AddListener(barrier.get());
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
    outcome.mMass = inSettings.mMass;
    outcome.mStartVelocity = inVelocityOf(scene);
    outcome.mStartTransform = inTransformOf(scene);
    outcome.mRestNormals = scene.GetDamage().GetObject(scene.GetCarObject())->GetDeformer().GetNormals();
    const int steps = static_cast<int>(std::lround(inSettings.mDuration / inSettings.mTimeStep));
    for (int step = 0; step < steps; ++step)
    {
        scene.Step();
        if (barrier)
        {
            // The barrier follows the engine step; once a piece is loose the car is let through.
            const Result<fem::TetStepResult> result = barrier->mSolver.Step(inSettings.mTimeStep);
            if (result.IsValid() && fem::HasEvent(result.Get().mEvents, fem::ETetStepEvent::Fractured) &&
                std::isnan(outcome.mBarrierBreachTime))
                for (const fem::TetFragment& fragment : barrier->mSolver.ComputeFragments())
                    if (!fragment.mAnchored)
                    {
                        outcome.mBarrierBreachTime = (step + 1) * inSettings.mTimeStep;
                        scene.RemoveBarrier();
                        break;
                    }
        }
    }
    scene.GetDamage().Flush();
    if (barrier)
    {
        scene.GetDamage().RemoveListener(barrier.get());
        outcome.mBarrierFragments = static_cast<int>(barrier->mSolver.ComputeFragments().size());
        outcome.mBarrierBrokenLinks = barrier->mSolver.GetBrokenLinkCount();
    }
    outcome.mEndVelocity = inVelocityOf(scene);
    outcome.mEndTransform = inTransformOf(scene);
    if (recorder)
        if (Status status = recorder->Close(); status.HasError())
            return status.GetError();

    for (const plugin::Collision& collision : scene.GetCounter().mLog)
    {
        const double impulse = collision.TotalImpulse();
        outcome.mCollisions.push_back({collision.mStartTime, collision.mEndTime, impulse,
                                       static_cast<int>(collision.mContacts.size())});
        outcome.mTotalImpulse += impulse;
        outcome.mPeakImpulse = std::max(outcome.mPeakImpulse, impulse);
    }
    const ffd::FfdDeformer& car = scene.GetDamage().GetObject(scene.GetCarObject())->GetDeformer();
    outcome.mRestMesh = car.GetRestMesh();
    outcome.mPositions = car.GetPositions();
    outcome.mNormals = car.GetNormals();
    for (EZone zone : {EZone::Any, EZone::Front, EZone::Rear, EZone::Left, EZone::Right, EZone::Roof})
        outcome.mResidualCrush[static_cast<int>(zone)] = ResidualCrush(outcome.mRestMesh, outcome.mPositions, zone);
    outcome.mFoldedVertices = FoldedVertices(outcome.mRestNormals, outcome.mNormals);
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
    }
    return std::numeric_limits<double>::quiet_NaN();
}

int FoldedVertices(std::span<const Vec3> inRestNormals, std::span<const Vec3> inNormals)
{
    int folded = 0;
    for (std::size_t vertex = 0; vertex < inNormals.size() && vertex < inRestNormals.size(); ++vertex)
        folded += inRestNormals[vertex].dot(inNormals[vertex]) < 0.0 ? 1 : 0;
    return folded;
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
    Result<common::EngineCrashSettings> settings = SceneSettings(inScenario);
    if (settings.HasError())
        return settings.GetError();
    switch (inScenario.mEngine)
    {
    case EEngine::Bullet:
#if defined(CRUMPLE_CRASH_BULLET)
        return RunScene<common::BulletWallCrash>(
            settings.Get(), inOptions, inScenario.mTarget,
            [](common::BulletWallCrash& inScene)
            {
                const btVector3 v = inScene.GetCar().getLinearVelocity();
                return Vec3(v.x(), v.y(), v.z());
            },
            [](common::BulletWallCrash& inScene)
            {
                const btTransform& t = inScene.GetCar().getWorldTransform();
                Transform transform;
                for (int row = 0; row < 3; ++row)
                    for (int col = 0; col < 3; ++col)
                        transform.mRotation(row, col) = t.getBasis()[row][col];
                transform.mTranslation = Vec3(t.getOrigin().x(), t.getOrigin().y(), t.getOrigin().z());
                return transform;
            });
#else
        return MakeError(EError::InvalidArgument, "crumple-crash was built without Bullet (libbullet-dev)");
#endif
    case EEngine::Ode:
#if defined(CRUMPLE_CRASH_ODE)
        return RunScene<common::OdeWallCrash>(
            settings.Get(), inOptions, inScenario.mTarget,
            [](common::OdeWallCrash& inScene)
            {
                const dReal* v = dBodyGetLinearVel(inScene.GetCar());
                return Vec3(v[0], v[1], v[2]);
            },
            [](common::OdeWallCrash& inScene)
            {
                const dReal* r = dBodyGetRotation(inScene.GetCar()); // 3 x 4, row major
                const dReal* p = dBodyGetPosition(inScene.GetCar());
                Transform transform;
                for (int row = 0; row < 3; ++row)
                    for (int col = 0; col < 3; ++col)
                        transform.mRotation(row, col) = r[4 * row + col];
                transform.mTranslation = Vec3(p[0], p[1], p[2]);
                return transform;
            });
#else
        return MakeError(EError::InvalidArgument, "crumple-crash was built without ODE (libode-dev)");
#endif
    }
    return MakeError(EError::InvalidArgument, "unknown engine");
}

} // namespace crumple::crash
