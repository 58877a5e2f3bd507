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

/// The course's destructible fence (RaceCourse::Fence): a wooden fence of posts and two rails (MakeTetFence)
/// across the road, a held prop body in the engine whose FEM (crumple::props) takes the car's impulses,
/// cracks, and sheds pieces that become engine bodies of their own and fly. What a game does for a prop
/// after each engine step is props::HeldPropBodies's (Step()); the rest is pictures and the summary.
class RaceFence
{
public:
    /// Makes the fence's body in the engine and its prop in a PropWorld of ioDamage (which must outlive it),
    /// prepared for steps of inStepTime (s): the first hit does not factor its FEM in its frame. With
    /// inOffThread its FEM steps as a task of ioDamage's job system (props::PropWorldSettings::mStepOffThread).
    static Result<std::unique_ptr<RaceFence>> Create(plugin::DamageWorld& ioDamage, RacePropEngine inEngine, double inStepTime,
                                                     bool inOffThread = false);

    /// The fence's engine body
    plugin::BodyId GetBody() const { return mBody; }
    /// Records the fence beside the collisions (before the first Step)
    Status AttachRecorder(plugin::DamageRecorder* ioRecorder) { return mProps->AttachRecorder(ioRecorder); }

    /// After the engine's frame (and the damage world's Update): steps the fence's FEM by inDeltaTime (s),
    /// gives the engine the struck planks' velocity for the held body, makes the pieces that broke loose
    /// engine bodies, and hands the engine the fence's new shape when it changed. Bodies made this frame are
    /// appended to outNewBodies (for names in the log). A sleeping fence costs one check. Off the thread:
    /// lands the step started by the previous call, hands its outcome to the engine, and starts this one.
    Status Step(double inDeltaTime, std::vector<plugin::BodyId>& outNewBodies);

    /// Adds the fence (without the pieces that left; coloured by how far its nodes moved) and every flying
    /// piece, where the engine has it, to a picture.
    void Paint(ScenePainter& ioPainter, const plugin::DamageWorld& inDamage) const;
    /// Writes the fence's FEM mesh as it is now, all elements (as crumple-replay writes a replayed prop: the
    /// two files are byte-identical when the replay reproduces the run).
    Status WriteObj(const std::filesystem::path& inPath) const;
    /// One line: links broken, pieces loose, bodies made, the FEM's steps and its worst step time.
    std::string Summary() const;
    /// The longest Step() so far, in the game thread's CPU time (ms)
    double GetWorstStepMs() const { return mWorstStepMs; }
    /// Where the fence's hand-overs came from: worked out on its step's task or in the call (off the thread)
    const props::PropHandOverStats& GetHandOverStats() const { return mProps->GetHandOverStats(); }
    /// Of the last Step(), the time spent making the drawing meshes of new pieces (the game's own work, not
    /// Crumple's: a game builds its render meshes its own way), game thread's CPU (ms)
    double GetLastStepDrawingMs() const { return mLastDrawingMs; }

private:
    explicit RaceFence(plugin::DamageWorld& ioDamage) : mDamage(&ioDamage) {}

    // A piece that left the fence as a body: its surface in the body's frame when it was made.
    struct Piece
    {
        plugin::BodyId mBody;
        std::vector<Vec3> mPositions;
        std::vector<Vec3> mNormals;
        std::vector<std::array<std::uint32_t, 3>> mTriangles;
    };
    void MakePiece(const props::HeldPiece& inPiece);

    plugin::DamageWorld* mDamage = nullptr;
    std::unique_ptr<props::PropWorld> mProps;
    std::optional<props::HeldPropBodies> mHeld;
    props::PropId mProp;
    plugin::BodyId mBody;
    Transform mBodyPose;                  ///< The held body's frame (the FEM's frame) in the world
    std::vector<std::uint8_t> mLeftOut;   ///< Per element: left the fence with a piece (not drawn with it)
    std::vector<Piece> mPieces;
    int mLoose = 0;                       ///< Pieces handed over, with a body or without (too light)
    int mSteps = 0, mAwakeSteps = 0;
    double mWorstStepMs = 0.0, mTotalStepMs = 0.0; ///< Step() in the game thread's CPU time
    double mLastDrawingMs = 0.0;                    ///< GetLastStepDrawingMs
};

} // namespace crumple::samples
