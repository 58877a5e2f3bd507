// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include "ScenePainter.h"

#include <crumple/plugin/ConvexBodySettings.h>
#include <crumple/plugin/DamageRecorder.h>
#include <crumple/plugin/DamageWorld.h>
#include <crumple/plugin/PropBodySettings.h>
#include <crumple/props/HeldPropBodies.h>
#include <crumple/props/PropWorld.h>

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace crumple::samples
{

/// What a racing sample's engine does for a destructible prop: its adapter's calls, whose arguments differ
/// between Bullet and ODE (ODE's need the world and the space).
struct RacePropEngine
{
    std::function<Result<plugin::BodyId>(const plugin::PropBodySettings&)> mMakePropBody; ///< CreatePropBody
    props::HeldPropEngine mHeld; ///< What props::HeldPropBodies calls after each step
};

/// The calls of props::HeldPropEngine that Bullet's and ODE's adapters take alike (SetPropPieces,
/// SetHeldVelocity, IsHeldPropBody), bound to inAdapter, with the piece bodies' maker the engine needs
/// (ODE's takes its world and space). Held bodies meet a contact with the whole prop's mass (no SetHeldMass:
/// a contact mass follows how many points each engine reports, and the engines part: README, known limits).
template <class Adapter>
props::HeldPropEngine
HeldPropCalls(Adapter& inAdapter,
              std::function<Result<plugin::BodyId>(const plugin::ConvexBodySettings&)> inCreatePieceBody)
{
    return {
        .mCreatePieceBody = std::move(inCreatePieceBody),
        .mSetPropPieces = [&inAdapter](plugin::BodyId inBody, const std::vector<std::vector<Vec3>>& inPieces)
        { return inAdapter.SetPropPieces(inBody, inPieces); },
        .mSetHeldVelocity = [&inAdapter](plugin::BodyId inBody, const Vec3& inVelocity)
        { return inAdapter.SetHeldVelocity(inBody, inVelocity); },
        .mSetHeldMass = nullptr,
        .mIsHeld = [&inAdapter](plugin::BodyId inBody) { return inAdapter.IsHeldPropBody(inBody); }};
}

/// A piece that broke loose from one of the course's props and became an engine body.
struct RaceNewPiece
{
    plugin::BodyId mBody;
    int mProp = 0; ///< Which prop it left (RaceProps::GetName)
};

/// The course's destructible props (RaceCourse): a wooden fence of posts and two rails (MakeTetFence) across
/// the road and a low garden wall of bricks at its edge before the barriers (RaceCourse::BrickWall), each a
/// held prop body in the engine whose FEM (crumple::props) takes the car's impulses, cracks (the wall between
/// its bricks), and sheds pieces that become engine bodies of their own and fly. All of them in one
/// props::PropWorld, so that one recording replays them together. What a game does for props after each
/// engine step is props::HeldPropBodies's (Step()); the rest is pictures and the summary.
class RaceProps
{
  public:
    /// Makes the props' bodies in the engine and their FEM in a PropWorld of ioDamage (which must outlive
    /// them), prepared for steps of inStepTime (s): the first hit does not factor an FEM in its frame. With
    /// inOffThread their FEM steps as a task of ioDamage's job system
    /// (props::PropWorldSettings::mStepOffThread).
    static Result<std::unique_ptr<RaceProps>> Create(plugin::DamageWorld& ioDamage, RacePropEngine inEngine,
                                                     double inStepTime, bool inOffThread = false);

    /// How many props: the fence (0), then the brick wall (1)
    int GetCount() const { return static_cast<int>(mProps.size()); }
    /// A prop's name ("fence", "brick wall"): the log's, the summary's and its OBJ's ("fence.obj",
    /// "brick_wall.obj")
    const std::string& GetName(int inProp) const { return mProps[static_cast<std::size_t>(inProp)].mName; }
    /// A prop's engine body
    plugin::BodyId GetBody(int inProp) const { return mProps[static_cast<std::size_t>(inProp)].mBody; }
    /// Records the props beside the collisions (before the first Step)
    Status AttachRecorder(plugin::DamageRecorder* ioRecorder) { return mWorld->AttachRecorder(ioRecorder); }

    /// After the engine's frame (and the damage world's Update): steps the props' FEM by inDeltaTime (s),
    /// gives the engine the struck members' velocity for the held bodies, makes the pieces that broke loose
    /// engine bodies, and hands the engine a prop's new shape when it changed. Bodies made this frame are
    /// appended to outNewPieces (for names in the log). Sleeping props cost one check each. Off the thread:
    /// lands the step started by the previous call, hands its outcome to the engine, and starts this one.
    Status Step(double inDeltaTime, std::vector<RaceNewPiece>& outNewPieces);

    /// Adds the props (without the pieces that left; coloured by how far their nodes moved) and every flying
    /// piece, where the engine has it, to a picture.
    void Paint(ScenePainter& ioPainter, const plugin::DamageWorld& inDamage) const;
    /// Writes each prop's FEM mesh as it is now, all elements, to inFolder / (its name, spaces as
    /// underscores) ".obj" (as crumple-replay writes a replayed prop: propN.obj is byte-identical to prop N's
    /// when the replay reproduces the run).
    Status WriteObjs(const std::filesystem::path& inFolder) const;
    /// A line per prop (links broken, pieces loose, bodies made, factorisations) and one for the FEM's steps
    /// (awake steps, the worst step's time, the steps split, given up and unconverged), each ending in a
    /// newline.
    std::string Summary() const;
    /// The longest Step() so far, in the game thread's CPU time (ms)
    double GetWorstStepMs() const { return mWorstStepMs; }
    /// Prop steps so far (summed over the props) that split to go through, were given up, were kept
    /// unconverged (PropStepReport)
    int GetSplitSteps() const { return mSplitSteps; }
    int GetGivenUpSteps() const { return mGivenUpSteps; }
    int GetUnconvergedSteps() const { return mUnconvergedSteps; }
    /// Where the props' hand-overs came from: worked out on their step's task or in the call (off the thread)
    const props::PropHandOverStats& GetHandOverStats() const { return mWorld->GetHandOverStats(); }
    /// Of the last Step(), the time spent making the drawing meshes of new pieces (the game's own work, not
    /// Crumple's: a game builds its render meshes its own way), game thread's CPU (ms)
    double GetLastStepDrawingMs() const { return mLastDrawingMs; }

  private:
    explicit RaceProps(plugin::DamageWorld& ioDamage) : mDamage(&ioDamage) {}

    // A piece that left a prop as a body: its surface in the body's frame when it was made.
    struct Piece
    {
        plugin::BodyId mBody;
        std::vector<Vec3> mPositions;
        std::vector<Vec3> mNormals;
        std::vector<std::array<std::uint32_t, 3>> mTriangles;
    };
    // One prop of the course.
    struct Prop
    {
        std::string mName;
        plugin::BodyId mBody;
        props::PropId mProp;
        Transform mBodyPose; ///< The held body's frame (the FEM's frame) in the world
        std::vector<Piece> mPieces;
    };
    void MakePiece(Prop& ioProp, const props::HeldPiece& inPiece);

    plugin::DamageWorld* mDamage = nullptr;
    std::unique_ptr<props::PropWorld> mWorld;
    std::optional<props::HeldPropBodies> mHeld;
    std::vector<Prop> mProps;
    int mSteps = 0, mAwakeSteps = 0;
    // Prop steps (summed over the props) that split to go through, were given up (restored), or kept
    // unconverged: PropStepReport's counts, printed so a session shows its solver trouble.
    int mSplitSteps = 0, mGivenUpSteps = 0, mUnconvergedSteps = 0;
    double mWorstStepMs = 0.0, mTotalStepMs = 0.0; ///< Step() in the game thread's CPU time
    double mLastDrawingMs = 0.0;                   ///< GetLastStepDrawingMs
};

} // namespace crumple::samples
