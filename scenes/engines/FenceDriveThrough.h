// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include "EngineCrash.h"
#include "ThreadCpuTime.h"

#include <crumple/fem/PropMaterialPreset.h>
#include <crumple/fem/TetFence.h>
#include <crumple/props/HeldFemProp.h>
#include <crumple/props/HeldPropBodies.h>
#include <crumple/props/PropBody.h>
#include <crumple/props/PropWorld.h>

#include <crumple/plugin/DamageRecorder.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace crumple::common
{

/// A car driven through a held wooden fence in an engine scene (BulletWallCrash, OdeWallCrash): the fence is a
/// prop body the adapter makes and holds, its FEM takes the car's impulses, its loose pieces become engine
/// bodies and its shape follows its FEM. Header-only (a template over the scene): whoever includes it links
/// crumple::props. The fence test and crumple-bench's props group run it.
struct FenceDriveSettings
{
    double mSpeed = 64.0 / 3.6;    ///< The car's speed (m/s)
    bool mBreakable = true;        ///< false: the same wood that cannot crack
    bool mMatchVelocity = true;    ///< The held body moves with the struck planks (false: put back at rest)
    bool mMatchMass = false;       ///< The held body weighs what the struck planks weigh over a step
                                   ///< (SetHeldMass; false: the whole fence's mass and inertia)
    bool mFence = true;            ///< false: no fence (the drive alone, the baseline of a cost)
    double mDuration = 0.6;        ///< Simulated time (s)
    fem::TetSolverSettings mSolver = props::HeldPropSolverSettings(); ///< The fence FEM's solver
    double mContactSpread = 0.0;   ///< The fence FEM's contact spread radius (m; FemProp::SetContactSpread)
    props::EFemBackend mBackend = props::EFemBackend::Cpu; ///< Where the fence's FEM runs (asked)
    gpu::ComputeDeviceProvider* mProvider = nullptr;       ///< The device for mBackend Gpu (none: the CPU)
    /// At this step (before the engine's), the fence goes as a restarted level's would and a fresh one takes
    /// its place: PropWorld::RemoveProp, the adapter's RemoveBody for its held body and its pieces' bodies,
    /// then the same fence added again (-1: never)
    int mRestartFenceAtStep = -1;
    /// Where to record the drive (a DamageRecorder, the props attached before the fence joins); empty: none.
    /// A drive that returns an error leaves the recording closed where it stopped: remove the file then.
    std::filesystem::path mRecordTo{};
};

/// What a drive through the fence did, and what it cost.
struct FenceRun
{
    double mSpeedBefore = 0.0, mSpeedAfter = 0.0; ///< The car's speed along x (m/s)
    double mCarX = 0.0;
    double mCarZ = 0.0;                          ///< The car's centre at the end (m)
    double mFenceMoved = 0.0;                    ///< How far the held fence body ended from its pose (m)
    double mFenceImpulse = 0.0;                  ///< Crumple's impulse on the fence body, along +x (N s)
    double mFenceMass = 0.0;                     ///< kg
    int mFenceTets = 0;
    int mBrokenLinks = 0;
    int mBodiesMade = 0;
    std::uint64_t mRevision = 0;
    std::size_t mPiecesBefore = 0, mPiecesAfter = 0; ///< Collision pieces made, and in the last shape given
    bool mPiecesAccepted = true;  ///< Every engine call of HeldPropBodies succeeded
    bool mFirstShapeGiven = false; ///< The first HeldPropBodies::Update gave the prop's shape
    int mShapeChanges = 0;        ///< Shapes given after the first
    int mLoose = 0;              ///< Pieces handed over, with or without a body
    double mCarImpulse = 0.0;    ///< Crumple's impulses on the car over the run, along x (N s)
    int mSteps = 0;
    double mStepCpuMs = 0.0, mWorstStepCpuMs = 0.0; ///< Whole steps (engine, Crumple, props), game-thread CPU
    double mPropsCpuMs = 0.0;    ///< Of it PropWorld::Step
    double mHandOverCpuMs = 0.0; ///< Of it HeldPropBodies::Update: velocity, pieces and their bodies, shape
    double mWallMs = 0.0;        ///< Wall time of the steps
    double mPrepareCpuMs = 0.0;  ///< PropWorld::Prepare before the drive (level load; not in the steps)
    props::EFemBackend mBackend = props::EFemBackend::Cpu; ///< Where the fence's FEM ran
    int mNotConverged = 0; ///< Steps whose implicit solve stopped at its iteration limits
    /// #L of the fence's links, 1 where one broke (empty on the GPU backend)
    std::vector<std::uint8_t> mBroken;
    /// mRestartFenceAtStep: the bodies removed (the fence's and its pieces'), and whether each of them, and
    /// the removed prop, was gone from the damage world and the prop world afterwards; the fresh fence is the
    /// one the other figures are of
    int mRemovedBodies = 0;
    bool mRemovedGone = false;
    /// mRestartFenceAtStep: what the restart cost on the game's thread, the removal and the fresh fence with
    /// its Prepare (thread CPU and wall, ms)
    double mRestartCpuMs = 0.0, mRestartWallMs = 0.0;
};

/// A 4 m wooden fence across the car's path: 5 cm planks in cubes of 2.5 cm (two across each plank: fracture
/// reads a cube's mean stress, and one cube across a bent member reads none), posts at y = -1.95, 0 and 1.95,
/// two rails 0.1 m tall at 0.4 and 0.8 m, its face at x = 0 (the fence runs along +x in its own frame: turned a
/// quarter about z).
inline fem::TetFenceSettings DriveThroughFenceSettings()
{
    fem::TetFenceSettings fence;
    fence.mLength = 4.0;
    fence.mHeight = 1.2;
    fence.mThickness = 0.05;
    fence.mCellSize = 0.025;
    return fence;
}

inline Transform DriveThroughFencePose()
{
    Transform pose;
    pose.mRotation = Eigen::AngleAxisd(0.5 * M_PI, Vec3::UnitZ()).toRotationMatrix(); // fence x -> world y
    pose.mTranslation = Vec3(0.05, -2.0, 0.01); // fence y in [0, 0.05] -> world x in [0, 0.05]; just off the ground
    return pose;
}

template <class Scene>
Result<FenceRun> DriveThroughFence(const FenceDriveSettings& inSettings)
{
    constexpr double cShapeSize = 0.25;      // collision pieces: a few dozen cubes each
    constexpr double cMinBodyMass = 0.05;    // kg: lighter splinters leave without a body
    constexpr double cShapeTolerance = 0.01; // m: the engine's shape follows the FEM to a centimetre
    EngineCrashSettings settings;
    settings.mDriveOnly = true;
    settings.mSpeed = inSettings.mSpeed;
    settings.mDuration = inSettings.mDuration;
    settings.mGap = 0.3;
    settings.mTriangles = 2000;
    Scene scene(settings);
    // intent: declared before the prop world, so destroyed after it on every return (an error return
    // included)
    std::unique_ptr<plugin::DamageRecorder> recorder;
    Result<std::unique_ptr<props::PropWorld>> props_made =
        props::PropWorld::Create(scene.GetDamage(), {.mContactMass = inSettings.mMatchMass});
    if (!props_made)
        return props_made.GetError();
    props::PropWorld& props = *props_made.Get();
    if (!inSettings.mRecordTo.empty())
    {
        Result<std::unique_ptr<plugin::DamageRecorder>> made =
            plugin::DamageRecorder::Create(inSettings.mRecordTo, scene.GetDamage());
        if (!made)
            return made.GetError();
        recorder = std::move(made).Get();
        if (Status attached = props.AttachRecorder(recorder.get()); !attached)
            return attached.GetError();
    }

    FenceRun run;
    plugin::BodyId fence_body;
    props::PropId fence_prop;
    Vec3 fence_position = Vec3::Zero();
    props::HeldPropEngine engine{
        .mCreatePieceBody = [&](const plugin::ConvexBodySettings& inBody)
        { return scene.MakeDebrisBody(inBody); },
        .mSetPropPieces =
            [&](plugin::BodyId inBody, const std::vector<std::vector<Vec3>>& inPieces)
        {
            run.mPiecesAfter = inPieces.size();
            return scene.GetAdapter().SetPropPieces(inBody, inPieces);
        },
        .mSetHeldVelocity = nullptr,
        .mSetHeldMass = nullptr,
        .mIsHeld = [&](plugin::BodyId inBody) { return scene.GetAdapter().IsHeldPropBody(inBody); }};
    if (inSettings.mMatchVelocity)
        engine.mSetHeldVelocity = [&](plugin::BodyId inBody, const Vec3& inVelocity) { return scene.GetAdapter().SetHeldVelocity(inBody, inVelocity); };
    if (inSettings.mMatchMass)
        engine.mSetHeldMass = [&](plugin::BodyId inBody, double inMass)
        { return scene.GetAdapter().SetHeldMass(inBody, inMass); };
    Result<props::HeldPropBodies> held = props::HeldPropBodies::Create(
        props, std::move(engine), {.mShapeCellSize = cShapeSize, .mShapeTolerance = cShapeTolerance, .mMinPieceMass = cMinBodyMass});
    if (!held)
        return held.GetError();
    // The fence: its held body (the adapter's), its FEM and the prop world's prop, prepared as a game does at
    // level load (the first hit does not factor the fence's implicit system).
    const auto add_fence = [&]() -> Status
    {
        Result<fem::TetFence> fence = fem::MakeTetFence(DriveThroughFenceSettings());
        Result<fem::PropMaterialPreset> wood = fem::MakePropMaterialPreset(fem::EPropMaterial::Wood);
        if (!fence || !wood)
            return fence ? wood.GetError() : fence.GetError();
        if (!inSettings.mBreakable)
            wood.Get().mMaterial.mTensileStrength = std::numeric_limits<double>::infinity();
        Result<props::HeldProp> added = props::AddHeldProp(
            props, fence.Get().mMesh, wood.Get().mMaterial, fence.Get().mGroundNodes, DriveThroughFencePose(),
            cShapeSize, [&](const plugin::PropBodySettings& inBody) { return scene.MakePropBody(inBody); },
            inSettings.mSolver, inSettings.mContactSpread, {.mBackend = inSettings.mBackend, .mLog = nullptr},
            inSettings.mProvider);
        if (!added)
            return added.GetError();
        fence_body = added.Get().mBody;
        fence_prop = added.Get().mProp;
        const props::PropBody& made = added.Get().mMade;
        const double prepare_start = ThreadCpuMs();
        if (Status prepared = props.Prepare(settings.mTimeStep); !prepared)
            return prepared;
        run.mPrepareCpuMs = ThreadCpuMs() - prepare_start;
        run.mFenceMass = made.mBody.mMass;
        run.mFenceTets = static_cast<int>(made.mMesh.GetTets().size());
        run.mPiecesBefore = made.mBody.mPieces.size();
        fence_position = made.mBody.mPosition;
        return Status::Ok();
    };
    if (inSettings.mFence)
        if (Status added = add_fence(); !added)
            return added.GetError();
    std::vector<plugin::BodyId> piece_bodies; // the loose pieces' bodies made so far
    // A restarted level: the fence, its body and its pieces' bodies go; a fresh fence takes its place.
    const auto restart_fence = [&]() -> Status
    {
        const props::PropId removed_prop = fence_prop;
        std::vector<plugin::BodyId> removed = piece_bodies;
        removed.push_back(fence_body);
        if (Status gone = props.RemoveProp(removed_prop); !gone)
            return gone;
        for (const plugin::BodyId body : removed)
            if (Status gone = scene.RemoveMadeBody(body); !gone)
                return gone;
        piece_bodies.clear();
        run.mRemovedBodies = static_cast<int>(removed.size());
        run.mRemovedGone = props.GetProp(removed_prop) == nullptr;
        for (const plugin::BodyId body : removed)
            run.mRemovedGone = run.mRemovedGone && scene.GetDamage().GetBodyState(body) == nullptr;
        return add_fence();
    };

    run.mSpeedBefore = scene.GetCarState().mLinearVelocity.x();
    run.mSteps = static_cast<int>(std::lround(settings.mDuration / settings.mTimeStep));
    const auto wall_start = std::chrono::steady_clock::now();
    for (int i = 0; i < run.mSteps; ++i)
    {
        const double step_start = ThreadCpuMs();
        if (inSettings.mFence && i == inSettings.mRestartFenceAtStep)
        {
            const auto restart_wall = std::chrono::steady_clock::now();
            if (Status restarted = restart_fence(); !restarted)
                return restarted.GetError();
            run.mRestartCpuMs = ThreadCpuMs() - step_start;
            run.mRestartWallMs =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - restart_wall)
                    .count();
        }
        scene.Step();
        if (inSettings.mFence)
        {
            const double props_start = ThreadCpuMs();
            Result<props::PropStepReport> stepped = props.Step(settings.mTimeStep);
            if (!stepped)
                return stepped.GetError();
            const double hand_over_start = ThreadCpuMs();
            run.mPropsCpuMs += hand_over_start - props_start;
            run.mNotConverged += stepped.Get().mNotConverged;
            props::HeldPropUpdate update;
            run.mPiecesAccepted = held.Get().Update(stepped.Get(), update).IsValid() && run.mPiecesAccepted;
            run.mHandOverCpuMs += ThreadCpuMs() - hand_over_start;
            run.mFirstShapeGiven = run.mFirstShapeGiven || (i == 0 && update.mShapesGiven == 1);
            run.mShapeChanges += i == 0 ? 0 : update.mShapesGiven;
            for (const props::HeldPiece& piece : update.mPieces)
            {
                ++run.mLoose;
                run.mBodiesMade += piece.mBody.IsValid() ? 1 : 0;
                if (piece.mBody.IsValid())
                    piece_bodies.push_back(piece.mBody);
            }
        }
        const double step_ms = ThreadCpuMs() - step_start;
        run.mStepCpuMs += step_ms;
        run.mWorstStepCpuMs = std::max(run.mWorstStepCpuMs, step_ms);
    }
    run.mWallMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - wall_start).count();
    scene.GetDamage().Flush();
    if (recorder)
    {
        if (Status detached = props.AttachRecorder(nullptr); !detached)
            return detached.GetError();
        if (Status closed = recorder->Close(); !closed)
            return closed.GetError();
    }
    const plugin::BodyState car = scene.GetCarState();
    run.mSpeedAfter = car.mLinearVelocity.x();
    run.mCarX = car.mCenterOfMass.x();
    run.mCarZ = car.mCenterOfMass.z();
    run.mCarImpulse = ImpulseOnBody(scene.GetCounter().mLog, scene.GetDamage().GetObjectBody(scene.GetCarObject())).x();
    if (inSettings.mFence)
    {
        run.mFenceMoved = (scene.GetDamage().GetBodyState(fence_body)->mCenterOfMass - fence_position).norm();
        run.mFenceImpulse = ImpulseOnBody(scene.GetCounter().mLog, fence_body).x();
        run.mBrokenLinks = props.GetProp(fence_prop)->GetBrokenLinkCount();
        if (const fem::TetSolver* cpu = props.GetProp(fence_prop)->GetCpuSolver())
            run.mBroken = cpu->GetBrokenLinks();
        run.mBackend = props.GetProp(fence_prop)->GetBackend();
        run.mRevision = props.GetShapeRevision(fence_prop);
    }
    return run;
}

} // namespace crumple::common
