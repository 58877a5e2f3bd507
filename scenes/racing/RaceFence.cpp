// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "RaceFence.h"
#include "ObjWriter.h"
#include "RaceSession.h"
#include "TetSurface.h"
#include "ThreadCpuTime.h"

#include <crumple/fem/PropMaterialPreset.h>
#include <crumple/fem/TetFence.h>
#include <crumple/props/HeldFemProp.h>
#include <crumple/props/PropBody.h>

#include <algorithm>
#include <cstdio>

namespace crumple::samples
{

using namespace crumple::plugin;

namespace
{

// The engine's shape of the fence: cubes of 0.25 m, so a rail is a few dozen convex pieces and a piece that
// breaks away takes its part of the shape with it.
constexpr double cShapeCell = 0.25;
// The shape follows the FEM to a centimetre (a rail swinging away lets the car through).
constexpr double cShapeTolerance = 0.01;
// Splinters lighter than this leave the fence without a body (kg).
constexpr double cMinPieceMass = 0.05;

} // namespace

Result<std::unique_ptr<RaceFence>> RaceFence::Create(DamageWorld& ioDamage, RacePropEngine inEngine, double inStepTime, bool inOffThread)
{
    Result<fem::TetFence> fence = fem::MakeTetFence(RaceCourse::FenceSettings());
    if (!fence)
        return fence.GetError();
    Result<fem::PropMaterialPreset> wood = fem::MakePropMaterialPreset(fem::EPropMaterial::Wood);
    if (!wood)
        return wood.GetError();
    std::unique_ptr<RaceFence> result(new RaceFence(ioDamage));
    Result<std::unique_ptr<props::PropWorld>> props = props::PropWorld::Create(ioDamage, {.mStepOffThread = inOffThread});
    if (!props)
        return props.GetError();
    result->mProps = std::move(props).Get();
    Result<props::HeldPropBodies> held = props::HeldPropBodies::Create(
        *result->mProps, std::move(inEngine.mHeld),
        {.mShapeCellSize = cShapeCell, .mShapeTolerance = cShapeTolerance, .mMinPieceMass = cMinPieceMass});
    if (!held)
        return held.GetError();
    result->mHeld.emplace(std::move(held).Get());
    // Its posts' footings anchored; it sleeps until the car hits it.
    Result<props::HeldProp> added = props::AddHeldProp(*result->mProps, fence.Get().mMesh, wood.Get().mMaterial,
                                                       fence.Get().mGroundNodes, RaceCourse::Fence(), cShapeCell, inEngine.mMakePropBody);
    if (!added)
        return added.GetError();
    result->mBody = added.Get().mBody;
    result->mProp = added.Get().mProp;
    const plugin::PropBodySettings& body = added.Get().mMade.mBody;
    result->mBodyPose = {body.mOrientation, body.mPosition};
    result->mLeftOut.assign(added.Get().mMade.mMesh.GetTets().size(), 0);
    if (Status prepared = result->mProps->Prepare(inStepTime); !prepared)
        return prepared.GetError();
    return result;
}

Status RaceFence::Step(double inDeltaTime, std::vector<BodyId>& outNewBodies)
{
    const double start_ms = common::ThreadCpuMs();
    // intent: off the thread, the step started by the last call lands here, its outcome reaches the engine,
    // and this step starts only then (its collisions waited for it); otherwise the step runs here
    const bool off_thread = mProps->GetSettings().mStepOffThread;
    Result<props::PropStepReport> stepped = off_thread ? mProps->LandStep() : mProps->Step(inDeltaTime);
    if (!stepped)
        return stepped.GetError();
    ++mSteps;
    mAwakeSteps += stepped.Get().mStepped > 0 ? 1 : 0;
    props::HeldPropUpdate update;
    const Status held = mHeld->Update(stepped.Get(), update);
    mLastDrawingMs = 0.0;
    for (const props::HeldPiece& piece : update.mPieces)
    {
        ++mLoose;
        for (int element : piece.mPiece.mElements)
            mLeftOut[static_cast<std::size_t>(element)] = 1;
        if (!piece.mBody.IsValid())
            continue;
        const double drawing_start_ms = common::ThreadCpuMs();
        MakePiece(piece);
        mLastDrawingMs += common::ThreadCpuMs() - drawing_start_ms;
        outNewBodies.push_back(piece.mBody);
    }
    if (off_thread)
        if (Status started = mProps->StartStep(inDeltaTime); !started)
            return started;
    const double step_ms = common::ThreadCpuMs() - start_ms;
    mWorstStepMs = std::max(mWorstStepMs, step_ms);
    mTotalStepMs += step_ms;
    return held;
}

void RaceFence::MakePiece(const props::HeldPiece& inPiece)
{
    const props::LooseFragment& inLoose = inPiece.mPiece;
    // The piece's surface in its body's frame (centre of mass, principal axes) as it left: drawn where the
    // engine moves the body. Only its own nodes, renumbered in its node order.
    const fem::TetSolver& solver = *mProps->GetProp(mProp)->GetCpuSolver();
    const ConvexBodySettings& rigid = inLoose.mRigidBody.mBody;
    std::vector<int> local(solver.GetPositions().size(), -1);
    Piece piece;
    piece.mBody = inPiece.mBody;
    for (int node : inLoose.mNodes)
    {
        local[static_cast<std::size_t>(node)] = static_cast<int>(piece.mPositions.size());
        piece.mPositions.push_back(rigid.mOrientation.transpose() *
                                   (mBodyPose.ToWorld(solver.GetPositions()[static_cast<std::size_t>(node)]) - rigid.mPosition));
    }
    std::vector<fem::TetIndices> elements;
    for (int element : inLoose.mElements)
    {
        fem::TetIndices corners = solver.GetElementNodes()[static_cast<std::size_t>(element)];
        for (int& corner : corners)
            corner = local[static_cast<std::size_t>(corner)];
        elements.push_back(corners);
    }
    common::TetSurface surface = common::MakeTetSurface(piece.mPositions, elements);
    piece.mNormals = std::move(surface.mNormals);
    piece.mTriangles = std::move(surface.mTriangles);
    mPieces.push_back(std::move(piece));
}

void RaceFence::Paint(ScenePainter& ioPainter, const DamageWorld& inDamage) const
{
    const fem::TetSolver& solver = *mProps->GetProp(mProp)->GetCpuSolver();
    const common::TetSurface surface = common::MakeTetSurface(solver.GetPositions(), solver.GetElementNodes(), mLeftOut);
    // Coloured as the cars are, by how far each node moved from its rest position (a crack's two sides each
    // from their own).
    ioPainter.Add(solver.GetPositions(), surface.mNormals, surface.mTriangles, DentDepths(solver.GetPositions(), solver.GetNodeRestPositions()),
                  mBodyPose);
    for (const Piece& piece : mPieces)
        if (const BodyState* state = inDamage.GetBodyState(piece.mBody); state != nullptr)
            ioPainter.Add(piece.mPositions, piece.mNormals, piece.mTriangles, {}, state->mTransform);
}

Status RaceFence::WriteObj(const std::filesystem::path& inPath) const
{
    const fem::TetSolver& solver = *mProps->GetProp(mProp)->GetCpuSolver();
    const common::TetSurface surface = common::MakeTetSurface(solver.GetPositions(), solver.GetElementNodes());
    return common::WriteObj(inPath, solver.GetPositions(), surface.mNormals, surface.mTriangles);
}

std::string RaceFence::Summary() const
{
    const fem::TetSolver& solver = *mProps->GetProp(mProp)->GetCpuSolver();
    char line[320];
    std::snprintf(line, sizeof(line),
                  "fence: %zu tetrahedra, %d links broken, %d pieces loose (%zu engine bodies); FEM awake %d of %d "
                  "engine steps, %d factorisations and %d refreshes, worst step %.2f ms, %.1f ms in all (game-thread CPU)",
                  solver.GetElementNodes().size(), solver.GetBrokenLinkCount(), mLoose, mPieces.size(), mAwakeSteps, mSteps,
                  solver.GetFactorizationCount(), solver.GetFactorRefreshCount(), mWorstStepMs, mTotalStepMs);
    return line;
}

} // namespace crumple::samples
