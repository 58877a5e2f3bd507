// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "RaceScene.h"
#include "RaceProps.h"
#include "ThreadJobSystem.h"

#include <crumple/base/ThreadCpuClock.h>

namespace crumple::samples
{

using namespace crumple::plugin;

RaceScene::RaceScene(const RaceSceneSettings& inSettings) : mSettings(inSettings)
{
}

RaceScene::~RaceScene() = default;

Status RaceScene::CreateDamageWorld()
{
    mJobs = std::make_unique<common::ThreadJobSystem>(mSettings.mThreads);
    DamageWorldSettings damage;
    damage.mJobs = mSettings.mThreads > 1 || mSettings.mDeferDents || mSettings.mPropsOffThread ? &mJobs->Get() : nullptr;
    damage.mDeferDents = mSettings.mDeferDents;
    damage.mDeferImpulses = mSettings.mDeferImpulses;
    Result<std::unique_ptr<DamageWorld>> world = DamageWorld::Create(damage);
    if (!world)
        return world.GetError();
    mDamage = std::move(world).Get();
    return Status::Ok();
}

Result<const DeformableObject*> RaceScene::CreateCarObject(BodyId inBody, const ffd::TriangleMesh& inMesh)
{
    DeformableObjectSettings settings;
    settings.mMesh = inMesh;
    Result<ObjectId> object = mDamage->CreateDeformableObject(inBody, settings);
    if (!object)
        return object.GetError();
    return mDamage->GetObject(object.Get());
}

Status RaceScene::KeepProps(Result<std::unique_ptr<RaceProps>> inProps)
{
    if (!inProps)
        return inProps.GetError();
    mProps = std::move(inProps).Get();
    for (int prop = 0; prop < mProps->GetCount(); ++prop)
        mNames[mProps->GetBody(prop)] = mProps->GetName(prop);
    return Status::Ok();
}

Status RaceScene::StepProps(double inStep, const RaceNewBodies& inNewBodies)
{
    if (mProps == nullptr)
        return Status::Ok();
    mPieces.clear();
    const double start = ThreadCpuSeconds();
    const Status stepped = mProps->Step(inStep, mPieces);
    // intent: the sample's drawing meshes of new pieces are the game's work, not Crumple's
    mFrameCrumpleMs += 1.0e3 * (ThreadCpuSeconds() - start) - mProps->GetLastStepDrawingMs();
    if (inNewBodies && !mPieces.empty())
        inNewBodies(mPieces);
    return stepped;
}

} // namespace crumple::samples
