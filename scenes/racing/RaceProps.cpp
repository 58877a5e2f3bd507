// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "RaceProps.h"
#include "ObjWriter.h"
#include "RaceSession.h"
#include "TetSurface.h"
#include "ThreadCpuTime.h"

#include <crumple/fem/PropMaterialPreset.h>
#include <crumple/fem/TetFence.h>
#include <crumple/fem/TetGrid.h>
#include <crumple/props/HeldFemProp.h>
#include <crumple/props/PropBody.h>

#include <algorithm>
#include <cstdio>

namespace crumple::samples
{

using namespace crumple::plugin;

namespace
{

// The engine's shape of a prop: cubes of 0.25 m, so a rail is a few dozen convex pieces and a piece that
// breaks away takes its part of the shape with it.
constexpr double cShapeCell = 0.25;
// The shape follows the FEM to a centimetre (a rail swinging away lets the car through).
constexpr double cShapeTolerance = 0.01;
// Splinters lighter than this leave a prop without a body (kg).
constexpr double cMinPieceMass = 0.05;

// What a prop is, before it is in the game.
struct PropModel
{
    std::string mName;
    fem::TetMesh mMesh;
    fem::FemMaterialSettings mMaterial;
    std::vector<int> mGroundNodes; // anchored: the prop's footing
    Transform mPose;
};

Result<PropModel> FenceModel()
{
    Result<fem::TetFence> fence = fem::MakeTetFence(RaceCourse::FenceSettings());
    if (!fence)
        return fence.GetError();
    Result<fem::PropMaterialPreset> wood = fem::MakePropMaterialPreset(fem::EPropMaterial::Wood);
    if (!wood)
        return wood.GetError();
    return PropModel{"fence", std::move(fence.Get().mMesh), wood.Get().mMaterial,
                     std::move(fence.Get().mGroundNodes), RaceCourse::Fence()};
}

Result<PropModel> BrickWallModel()
{
    // Each grid cell a brick: the brick preset breaks the mortar between whole cells (DetachGroup).
    const fem::TetGridSettings grid = RaceCourse::BrickWallSettings();
    Result<fem::TetMesh> mesh = fem::TetGrid(grid);
    if (!mesh)
        return mesh.GetError();
    Result<fem::PropMaterialPreset> brick = fem::MakePropMaterialPreset(fem::EPropMaterial::Brick);
    if (!brick)
        return brick.GetError();
    std::vector<int> ground;
    for (int j = 0; j <= grid.mCellCount[1]; ++j)
        for (int i = 0; i <= grid.mCellCount[0]; ++i)
            ground.push_back(fem::TetGridNode(grid.mCellCount, i, j, 0));
    return PropModel{"brick wall", std::move(mesh).Get(), brick.Get().mMaterial, std::move(ground),
                     RaceCourse::BrickWall()};
}

} // namespace

Result<std::unique_ptr<RaceProps>> RaceProps::Create(DamageWorld& ioDamage, RacePropEngine inEngine,
                                                     double inStepTime, bool inOffThread)
{
    std::vector<PropModel> models;
    for (Result<PropModel> (*make)() : {&FenceModel, &BrickWallModel})
    {
        Result<PropModel> model = make();
        if (!model)
            return model.GetError();
        models.push_back(std::move(model).Get());
    }
    std::unique_ptr<RaceProps> result(new RaceProps(ioDamage));
    Result<std::unique_ptr<props::PropWorld>> world =
        props::PropWorld::Create(ioDamage, {.mStepOffThread = inOffThread});
    if (!world)
        return world.GetError();
    result->mWorld = std::move(world).Get();
    Result<props::HeldPropBodies> held = props::HeldPropBodies::Create(
        *result->mWorld, std::move(inEngine.mHeld),
        {.mShapeCellSize = cShapeCell, .mShapeTolerance = cShapeTolerance, .mMinPieceMass = cMinPieceMass});
    if (!held)
        return held.GetError();
    result->mHeld.emplace(std::move(held).Get());
    // Their footings anchored, under the world's gravity and on its ground (a part left hanging falls onto it
    // and comes to rest); each settles on its footing, sleeps, and wakes when the car hits it.
    fem::TetSolverSettings solver = props::HeldPropSolverSettings();
    solver.mGravity = RaceCourse::Gravity();
    solver.mGround = RaceCourse::PropGround();
    for (const PropModel& model : models)
    {
        Result<props::HeldProp> added =
            props::AddHeldProp(*result->mWorld, model.mMesh, model.mMaterial, model.mGroundNodes, model.mPose,
                               cShapeCell, inEngine.mMakePropBody, solver);
        if (!added)
            return MakeError(added.GetError().mCode, "the " + model.mName + ": " + added.GetError().mMessage);
        const plugin::PropBodySettings& body = added.Get().mMade.mBody;
        Prop prop;
        prop.mName = model.mName;
        prop.mBody = added.Get().mBody;
        prop.mProp = added.Get().mProp;
        prop.mBodyPose = {body.mOrientation, body.mPosition};
        result->mProps.push_back(std::move(prop));
    }
    if (Status prepared = result->mWorld->Prepare(inStepTime); !prepared)
        return prepared.GetError();
    return result;
}

Status RaceProps::Step(double inDeltaTime, std::vector<RaceNewPiece>& outNewPieces)
{
    const double start_ms = common::ThreadCpuMs();
    // intent: off the thread, the step started by the last call lands here, its outcome reaches the engine,
    // and this step starts only then (its collisions waited for it); otherwise the step runs here
    const bool off_thread = mWorld->GetSettings().mStepOffThread;
    Result<props::PropStepReport> stepped = off_thread ? mWorld->LandStep() : mWorld->Step(inDeltaTime);
    if (!stepped)
        return stepped.GetError();
    ++mSteps;
    mAwakeSteps += stepped.Get().mStepped > 0 ? 1 : 0;
    mSplitSteps += stepped.Get().mSplit;
    mGivenUpSteps += stepped.Get().mDiverged;
    mUnconvergedSteps += stepped.Get().mNotConverged;
    props::HeldPropUpdate update;
    const Status held = mHeld->Update(stepped.Get(), update);
    mLastDrawingMs = 0.0;
    for (const props::HeldPiece& piece : update.mPieces)
    {
        // intent: props are added in order, so a prop's PropId is its index
        const auto index = static_cast<std::size_t>(piece.mPiece.mProp.mValue);
        Prop& prop = mProps[index];
        if (!piece.mBody.IsValid())
            continue;
        const double drawing_start_ms = common::ThreadCpuMs();
        MakePiece(prop, piece);
        mLastDrawingMs += common::ThreadCpuMs() - drawing_start_ms;
        outNewPieces.push_back({piece.mBody, static_cast<int>(index)});
    }
    if (off_thread)
        if (Status started = mWorld->StartStep(inDeltaTime); !started)
            return started;
    const double step_ms = common::ThreadCpuMs() - start_ms;
    mWorstStepMs = std::max(mWorstStepMs, step_ms);
    mTotalStepMs += step_ms;
    return held;
}

void RaceProps::MakePiece(Prop& ioProp, const props::HeldPiece& inPiece)
{
    const props::LooseFragment& inLoose = inPiece.mPiece;
    // The piece's surface in its body's frame (centre of mass, principal axes) as it left: drawn where the
    // engine moves the body. Only its own nodes, renumbered in its node order.
    const fem::TetSolver& solver = *mWorld->GetProp(ioProp.mProp)->GetCpuSolver();
    const ConvexBodySettings& rigid = inLoose.mRigidBody.mBody;
    std::vector<int> local(solver.GetPositions().size(), -1);
    Piece piece;
    piece.mBody = inPiece.mBody;
    for (int node : inLoose.mNodes)
    {
        local[static_cast<std::size_t>(node)] = static_cast<int>(piece.mPositions.size());
        piece.mPositions.push_back(
            rigid.mOrientation.transpose() *
            (ioProp.mBodyPose.ToWorld(solver.GetPositions()[static_cast<std::size_t>(node)]) -
             rigid.mPosition));
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
    ioProp.mPieces.push_back(std::move(piece));
}

void RaceProps::Paint(ScenePainter& ioPainter, const DamageWorld& inDamage) const
{
    for (const Prop& prop : mProps)
    {
        const fem::TetSolver& solver = *mWorld->GetProp(prop.mProp)->GetCpuSolver();
        const common::TetSurface surface = common::MakeTetSurface(
            solver.GetPositions(), solver.GetElementNodes(), mWorld->GetTakenElements(prop.mProp));
        // Coloured as the cars are, by how far each node moved from its rest position (a crack's two sides
        // each from their own).
        ioPainter.Add(solver.GetPositions(), surface.mNormals, surface.mTriangles,
                      DentDepths(solver.GetPositions(), solver.GetNodeRestPositions()), prop.mBodyPose);
        for (const Piece& piece : prop.mPieces)
            if (const BodyState* state = inDamage.GetBodyState(piece.mBody); state != nullptr)
                ioPainter.Add(piece.mPositions, piece.mNormals, piece.mTriangles, {}, state->mTransform);
    }
}

Status RaceProps::WriteObjs(const std::filesystem::path& inFolder) const
{
    for (const Prop& prop : mProps)
    {
        const fem::TetSolver& solver = *mWorld->GetProp(prop.mProp)->GetCpuSolver();
        const common::TetSurface surface =
            common::MakeTetSurface(solver.GetPositions(), solver.GetElementNodes());
        std::string file = prop.mName;
        std::replace(file.begin(), file.end(), ' ', '_');
        if (Status written = common::WriteObj(inFolder / (file + ".obj"), solver.GetPositions(),
                                              surface.mNormals, surface.mTriangles);
            !written)
            return written;
    }
    return Status::Ok();
}

std::string RaceProps::Summary() const
{
    std::string summary;
    char line[320];
    for (const Prop& prop : mProps)
    {
        const fem::TetSolver& solver = *mWorld->GetProp(prop.mProp)->GetCpuSolver();
        std::snprintf(line, sizeof(line),
                      "%s: %zu tetrahedra, %d links broken, %llu pieces loose (%zu engine bodies), %d "
                      "factorisations and %d refreshes\n",
                      prop.mName.c_str(), solver.GetElementNodes().size(), solver.GetBrokenLinkCount(),
                      static_cast<unsigned long long>(mWorld->GetShapeRevision(prop.mProp)),
                      prop.mPieces.size(), solver.GetFactorizationCount(), solver.GetFactorRefreshCount());
        summary += line;
    }
    std::snprintf(
        line, sizeof(line),
        "props' FEM: awake %d of %d engine steps, worst step %.2f ms, %.1f ms in all (game-thread CPU); prop "
        "steps split to go through %d, given up %d, unconverged %d\n",
        mAwakeSteps, mSteps, mWorstStepMs, mTotalStepMs, mSplitSteps, mGivenUpSteps, mUnconvergedSteps);
    return summary + line;
}

} // namespace crumple::samples
