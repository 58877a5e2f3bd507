// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Result.h>
#include <crumple/plugin/DamageListener.h>
#include <crumple/plugin/DamageRecorder.h>
#include <crumple/plugin/DamageWorld.h>
#include <crumple/props/FemProp.h>
#include <crumple/props/FragmentBody.h>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace crumple::props
{

/// A prop's handle in its PropWorld: index in order of AddProp.
struct CRUMPLE_API PropId
{
    static constexpr std::uint32_t cInvalid = 0xFFFFFFFFu;
    std::uint32_t mValue = cInvalid; ///< Index in creation order

    bool IsValid() const { return mValue != cInvalid; }
    bool operator==(const PropId&) const = default;
};

/// What one PropWorld::Step did.
struct CRUMPLE_API PropStepReport
{
    int mStepped = 0;    ///< Props that integrated (awake)
    int mSleeping = 0;   ///< Props that were asleep and did nothing (no element work)
    int mFractured = 0;  ///< Props in which links broke this step
    int mDiverged = 0;   ///< Props whose step diverged and was restored (fem::ETetStepEvent::Diverged)
    int mSplit = 0;      ///< Props whose step diverged in one piece and went through in 2, 4, ... pieces
                         ///< (fem::ETetStepEvent::Split without Diverged): kept, at several times its cost
    int mNotConverged = 0; ///< Props whose implicit solve stopped at its iteration limits and was kept
                           ///< (fem::ETetStepEvent::SolverNotConverged)
};

/// Where the hand-over's answers came from (PropWorld::GetHandOverStats). Off the game's thread the step's
/// task also works out, for each prop it stepped, the pieces TakeLooseFragments and the shape TakeChangedShape
/// will ask for next, with the state it used; a call whose prop is still in that state takes them instead of
/// working them out on the game's thread (the same answer, bit for bit: the same function of the same state).
struct CRUMPLE_API PropHandOverStats
{
    std::uint64_t mFragmentsForecast = 0; ///< A prop's fragments (TakeLooseFragments) worked out on the task
    std::uint64_t mFragmentsComputed = 0; ///< ... worked out in the call
    std::uint64_t mShapesForecast = 0;    ///< A changed shape (TakeChangedShape) built on the task
    std::uint64_t mShapesComputed = 0;    ///< ... built in the call
    std::uint64_t mForecastsMade = 0;     ///< Hand-overs the tasks worked out: one per awake prop per step (a
                                          ///< sleeping prop's state, and so its last one, is unchanged)
};

/// How a PropWorld steps its props.
struct CRUMPLE_API PropWorldSettings
{
    /// Off the game's thread (issue 12's "no hitch"): StartStep hands the props' step to a task of the damage
    /// world's job system (DamageWorldSettings::mJobs, mStartTask; inline where it has none) and returns at
    /// once; LandStep, after the engine's next step, waits for it and hands over what it did. A hit's FEM
    /// step then costs the game's thread nothing but the wait, and its outcome (the held body's velocity,
    /// loose pieces, the new shape) reaches the engine one step later. The collisions the world dispatches
    /// (in flight or not) wait in a queue and reach the props that existed when they were dispatched, in
    /// dispatch order, at the next StartStep (as they would have when dispatched unless the game took loose
    /// pieces in between: nothing else changes a prop between its steps). Results do not depend on the job
    /// system or its thread count: the same calls give bitwise the same props and recording. GPU props take
    /// their collisions and step on the game's thread in StartStep (their context is current there); CPU
    /// props on the task, their element passes on it alone (a task does not call back into the job system).
    /// The task also works out the hand-over that follows its step (PropHandOverStats).
    bool mStepOffThread = false;
    /// Work out GetContactMass after each step (with the step, on its task off the thread): one linear solve
    /// per awake CPU prop that something struck, with its factored implicit system where it holds one (1.3 ms
    /// on the racing fence's 4,000 tetrahedra, 6.5 ms on the drive-through fence's 16,000; crumple-bench
    /// contact_mass), else block Jacobi (a hundred times that). Off: GetContactMass is 0 and costs nothing.
    /// HeldPropBodies needs it on to give SetHeldMass.
    bool mContactMass = false;
};

/// A piece of a prop that broke loose, handed to the game as a rigid body (PropWorld::TakeLooseFragments).
struct CRUMPLE_API LooseFragment
{
    PropId mProp;                 ///< The prop it broke from
    std::vector<int> mElements;   ///< The prop's elements it holds: the game stops drawing them there
    std::vector<int> mNodes;      ///< The prop's nodes it holds, now fixed in the prop's solver
    bool mDropped = false;        ///< Lighter than the minimum mass: no body, it just leaves the prop
    FragmentRigidBody mRigidBody; ///< World frame, for an adapter's CreateConvexBody (unless dropped)
};

/// Destructible props in a DamageWorld's damage flow. Each prop (a FemProp, CPU or GPU) is bound to a body of
/// the world, whose frame its solver works in; every collision the world dispatches with that body gets onto
/// the prop's nodes as the Baraff impulses the world computed (CollisionNodalImpulses: +j n on body A, -j n
/// on body B), so a prop takes exactly the opposite of what the body that hit it took. Step() integrates the
/// props; a sleeping prop costs nothing.
///
/// The game keeps the bodies (static, kinematic or dynamic, in its engine and in the DamageWorld through the
/// adapter); the prop is the deformable structure of one of them. A DamageListener of its world (registered
/// by Create, removed by the destructor), so it takes collisions in the world's dispatch order, when they are
/// dispatched (OnBeforeCollision: a prop needs no dent), so deferred dents (DamageWorldSettings::mDeferDents)
/// change nothing for props: the same Update hands them the same hits either way. With a DamageRecorder (AttachRecorder) every prop and every step goes into the recording as
/// extension records beside the world's collisions, and ReplayProps (PropRecording.h) reproduces the
/// props bit for bit without an engine (GPU props on a device with the same driver).
///
/// Threading: the world calls it from DamageWorld::Update/Flush on the game's thread; Step() runs there too.
/// A CPU prop's element passes (forces, stiffness products) are split over the world's job system
/// (DamageWorldSettings::mJobs) when it has one, each piece writing only its own nodes' sums, so the props'
/// results are bitwise the same for any number of workers (fem::TetSolver::SetJobSystem). With
/// PropWorldSettings::mStepOffThread the step runs as a task instead (StartStep, LandStep). Every call is the
/// game's: those that read or change a prop (GetProp, AddProp, Prepare, AttachRecorder, TakeLooseFragments,
/// GetCollisionPieces, TakeChangedShape) first wait for a step in flight; the inline getters (GetBody,
/// FindProp, GetContactVelocity, GetShapeRevision, the collision counts) read only what the task does not
/// write, and show the last landed step's values.
class CRUMPLE_API PropWorld final : public plugin::DamageListener
{
public:
    /// Registers with ioWorld, which must outlive this object.
    static Result<std::unique_ptr<PropWorld>> Create(plugin::DamageWorld& ioWorld, const PropWorldSettings& inSettings = {});
    /// Waits for a step in flight (its task points into this object).
    ~PropWorld() override;
    PropWorld(const PropWorld&) = delete;
    PropWorld& operator=(const PropWorld&) = delete;

    /// Binds inProp to body inBody of the world (one prop per body) and hands a CPU prop the world's job
    /// system. Refused, and inProp left as it was, when the prop is empty (a FemProp moved from), the body
    /// does not exist or already has a prop, or, while recording, when the prop cannot be recorded (one that
    /// has already stepped). A prop stays until RemoveProp: one whose body the game removes from the world
    /// without it keeps its FEM stepping until it sleeps (its pieces are no longer taken).
    Result<PropId> AddProp(plugin::BodyId inBody, FemProp&& ioProp);
    /// Removes a prop (a race restarted, a prop streamed out): it steps no more and takes no collision, its
    /// FEM's memory (a GPU prop's device buffers too) is freed, and its id answers as an unknown prop's from
    /// then on (GetProp nullptr, GetBody invalid). Ids are not reused: GetPropCount still counts it, so a
    /// stale id never names another prop. The body stays the game's, in its engine and in the damage world
    /// (its collisions are no longer dispatched every step), and so do the pieces HeldPropBodies or
    /// TakeLooseFragments handed over; remove those through the adapter. A fresh prop may then be added, on
    /// the same body or another. Collisions the world has not dispatched yet (a static prop body's, within
    /// the time window) reach whatever prop the body has when they are: a fresh prop added at once may take
    /// the last hits of the old one. The body's dispatch at every step (DamageWorld::SetDispatchEachStep) is
    /// set back to off, whoever set it. HeldPropBodies puts a held body the game keeps back at rest with its
    /// own mass. While recording, the removal is recorded (EPropRecord::Removed) and ReplayProps stops the
    /// prop there. Refused, changing nothing, for an unknown or removed prop, while a step is in flight
    /// (LandStep first), and on the recorder's write error (a failed or closed recorder: detach it first).
    Status RemoveProp(PropId inProp);
    /// What AddProp would refuse of inProp itself, before its body exists: an empty prop, and while
    /// recording, a prop that cannot be recorded or a recorder that has failed or closed. (AddProp then
    /// refuses only a body that is not in the world or already has a prop, and a write error.) Changes
    /// nothing.
    Status CheckCanAdd(const FemProp& inProp) const;

    /// Records the props (those added so far now, later ones when added) and every Step() into ioRecorder,
    /// which must be recording the same world and outlive this object or be detached (nullptr) first.
    /// Refused, recording nothing, when a recorder is attached already (detach it first), the recorder has
    /// failed or is closed, a prop added so far cannot be recorded (one that has stepped), a prop was removed
    /// (a replay numbers the props in the order the recording adds them: it would not know the ids after it),
    /// or collisions wait for a step (mStepOffThread; the recording would not hold them): attach the recorder
    /// before the first Step(), the first hit and the first RemoveProp. With mStepOffThread the recording
    /// says so first (EPropRecord::Queued).
    Status AttachRecorder(plugin::DamageRecorder* ioRecorder);
    /// The prop, or nullptr for an unknown id
    FemProp* GetProp(PropId inProp);
    const FemProp* GetProp(PropId inProp) const;
    /// The body inProp is bound to, or an invalid id for an unknown prop
    plugin::BodyId GetBody(PropId inProp) const
    {
        return inProp.mValue < mProps.size() ? mProps[inProp.mValue].mBody : plugin::BodyId();
    }
    /// The damage world the props are in
    const plugin::DamageWorld& GetWorld() const { return *mWorld; }
    plugin::DamageWorld& GetWorld() { return *mWorld; }
    /// The prop bound to inBody, or an invalid id
    PropId FindProp(plugin::BodyId inBody) const;
    /// Number of props added so far, removed ones included (the next AddProp's id)
    int GetPropCount() const { return static_cast<int>(mProps.size()); }

    /// Steps every prop by inDeltaTime (s, finite, > 0), in PropId order. A step some prop would refuse (a
    /// symplectic prop that would need more sub-steps than allowed: FemProp::CheckStep) is an error naming the
    /// prop, and no prop steps and nothing is recorded. StartStep then LandStep; refused, as StartStep, while a
    /// step is in flight.
    Result<PropStepReport> Step(double inDeltaTime);
    /// Starts the step Step(inDeltaTime) does: the collisions waiting (mStepOffThread) reach the props, the
    /// step is recorded, and the props step, on a task of the world's job system with mStepOffThread (inline
    /// without it, or where the job system cannot start tasks). Refused, changing nothing, as Step refuses,
    /// and while a step is in flight (LandStep first). A collision the props refuse when it reaches them is
    /// counted (GetRefusedCount) and does not stop the step.
    Status StartStep(double inDeltaTime);
    /// Waits for the step StartStep started and hands over its report; the struck members' velocities
    /// (GetContactVelocity) and the collision counts are this step's from now on. An empty report when no
    /// step is in flight. The error of a prop that failed to step (cannot happen after StartStep accepted the
    /// step; kept for a backend's failure) names the prop; on the game's thread the props before it stepped,
    /// off it the GPU props step first, then the CPU props up to the failing one.
    Result<PropStepReport> LandStep();
    /// True between StartStep and LandStep
    bool HasStepInFlight() const { return mInFlight != nullptr && mInFlight->mActive; }
    /// The settings it was made with
    const PropWorldSettings& GetSettings() const { return mSettings; }
    /// Collisions waiting for the next StartStep (mStepOffThread)
    std::size_t GetQueuedCollisionCount() const { return mQueued.size(); }
    /// FemProp::Prepare for every prop (the props added so far): at level load, with the step the game will
    /// use, so that the first hit does not factor a prop's implicit system in its frame. Changes no state.
    /// Refused, preparing nothing, for a bad step length.
    Status Prepare(double inDeltaTime);

    /// Hands over the pieces of the props that broke loose since the last call, each once, in PropId order
    /// and then fragment order: a piece with no fixed node, except, in a prop with no fixed node at all, the
    /// piece holding its first element group (the prop's body carries that one). Each becomes a rigid body in
    /// the world frame (FragmentBody: its exact mass and inertia, the nodes' momentum and rigid spin) for the
    /// game to create in its engine (BulletAdapter / OdeAdapter::CreateConvexBody), and leaves the prop: its
    /// nodes are fixed where they are, so the FEM neither moves nor wakes for them again while the rest of the
    /// prop goes on. Pieces lighter than inMinMass (kg, >= 0) leave the same way without a body (mDropped).
    /// A piece no rigid body can stand for (crushed flat) leaves without one too. Props whose body left the
    /// world are skipped. While recording, the fixed nodes are recorded, so replays drop the pieces at the same
    /// point; a recorder's write error does not stop the hand-over (DamageRecorder::GetStatus keeps it).
    /// Refused, changing nothing, for a non-finite or negative minimum.
    Result<std::vector<LooseFragment>> TakeLooseFragments(double inMinMass = 0.0);
    /// The collision shape of what is left of a prop (props::PropCollisionPieces of its current node positions,
    /// without the elements of the pieces TakeLooseFragments handed over), body frame: for the adapter's
    /// SetPropPieces once pieces have left (GetShapeRevision). Refused for an unknown prop, or as
    /// PropCollisionPieces refuses (a cell size that is not finite and > 0, or too small for the prop's extent).
    Result<std::vector<std::vector<Vec3>>> GetCollisionPieces(PropId inProp, double inCellSize) const;
    /// The prop's collision shape (GetCollisionPieces) when it changed since the last call: pieces were handed
    /// over, or a node moved more than inTolerance (m, finite, >= 0) from where it was at the last shape taken
    /// (the first call always gives it); otherwise nothing. For a held prop body, whose shape must follow
    /// what its FEM does (a rail swinging away lets the car through), call it after each Step() and pass a
    /// shape to the adapter's SetPropPieces. Refused as GetCollisionPieces, or for a bad tolerance.
    Result<std::optional<std::vector<std::vector<Vec3>>>> TakeChangedShape(PropId inProp, double inCellSize, double inTolerance);
    /// How many pieces TakeLooseFragments has taken from the prop: its collision shape changed when this did
    /// (0 for an unknown prop)
    std::uint64_t GetShapeRevision(PropId inProp) const
    {
        return inProp.mValue < mProps.size() ? mProps[inProp.mValue].mPiecesTaken : 0;
    }
    /// Per element of the prop, 1 where TakeLooseFragments handed the element's piece over (what is left of
    /// the prop is the other elements); empty before any piece left, and for an unknown prop
    std::span<const std::uint8_t> GetTakenElements(PropId inProp) const
    {
        return inProp.mValue < mProps.size()
                   ? std::span<const std::uint8_t>(mProps[inProp.mValue].mTakenElements)
                   : std::span<const std::uint8_t>();
    }
    /// How fast the prop's material that the latest collisions struck is moving after the step, along the
    /// direction it was struck (world frame, m/s): the mean velocity of the nodes that took the impulses of
    /// the latest step that had any, weighted by each node's share (nodes of pieces handed over left out),
    /// projected on the direction of their total impulse (the held body stands for the whole prop: moved
    /// sideways or up with a timber flung so, it would carry the car with it); zero before anything struck it
    /// and while it sleeps (or for an unknown prop). Collisions reach a prop when the world dispatches them,
    /// which may be steps after the contact, so the latest hits stand until new ones arrive. A held prop body
    /// stands for the whole prop but a car meets only the members it touches: give this to the adapter's
    /// SetHeldVelocity after each Step (LandStep publishes a step's), so that the engine's next contact sees
    /// the struck timbers moving as the FEM moves them (a timber already pushed to the car's speed takes no
    /// new impulse; one its posts hold back takes what holds it back). Its speed is bounded by how fast the
    /// fastest striker of those hits pushed on along its push when its collision was dispatched: the engine
    /// met the struck members with the whole prop's mass, the FEM hands those impulses to the few nodes they
    /// landed on, and where those outran their striker (300 m/s for a car at 2 m/s against an 8 kg panel,
    /// tests/props) the held body would carry the whole prop at their speed into the next contact.
    Vec3 GetContactVelocity(PropId inProp) const
    {
        return inProp.mValue < mProps.size() ? mProps[inProp.mValue].mContactVelocity : Vec3::Zero();
    }
    /// The mass the struck material meets a contact with over the next step (kg): the prop's FEM's effective
    /// mass (fem::TetSolver::ContactEffectiveMass) at the nodes GetContactVelocity follows less the anchored
    /// ones, weighted as it weighs them, along the direction they were struck, at the state after the last
    /// landed step and for that step's length. 0 while PropWorldSettings::mContactMass is off, where
    /// GetContactVelocity is zero for want of struck nodes (nothing struck the prop yet, it sleeps, the
    /// struck nodes left with a piece or are anchored), for a GPU prop (the effective-mass solve is the CPU
    /// solver's), where the solve did not converge, or for an unknown prop. A held prop body stands for the
    /// whole prop: give this to the adapter's SetHeldMass after each Step, with the velocity, so that the
    /// engine's next contact takes from the car what the FEM's step will give the struck members. A rail
    /// half-way between posts weighs a fraction of the fence; one beside a post, many times the fence.
    double GetContactMass(PropId inProp) const
    {
        return inProp.mValue < mProps.size() ? mProps[inProp.mValue].mContactMass : 0.0;
    }
    /// Collisions that reached a prop so far, and those a prop refused (cannot happen for collisions the
    /// world validated; kept for diagnosis with the first refusal's reason)
    /// (mStepOffThread: counted when they reach the props, on the step's task, and published by LandStep)
    std::uint64_t GetCollisionCount() const { return mTally.mCollisions; }
    std::uint64_t GetRefusedCount() const { return mTally.mRefused; }
    const Status& GetFirstRefusal() const { return mTally.mFirstRefusal; }
    /// Where the hand-over's answers came from so far (mStepOffThread)
    const PropHandOverStats& GetHandOverStats() const { return mHandOverStats; }

    /// Takes the collision's impulses onto the props of its bodies.
    void OnBeforeCollision(const plugin::Collision& inCollision) override;
    /// Nothing: the props took the collision when it was dispatched.
    void OnCollision(const plugin::Collision& inCollision, std::span<const plugin::ObjectDent> inDents) override;

private:
    PropWorld(plugin::DamageWorld& ioWorld, const PropWorldSettings& inSettings) : mWorld(&ioWorld), mSettings(inSettings) {}

    // What a step's task worked out for the hand-over after it (mStepOffThread, a prop stepped on a task),
    // and the state it worked it out from: the prop's broken links and elements' nodes, node positions (bit
    // for bit) and inverse masses (its fixed nodes), and for the shape the cell size and the pieces and
    // elements taken once TakeLooseFragments has handed over the loose pieces it foresaw. A call uses it only
    // while the prop is in that state (the game may have changed the prop since: GetProp), once.
    struct HandOverForecast
    {
        int mBrokenLinks = 0;
        std::vector<fem::TetIndices> mElements;
        std::vector<Vec3> mPositions;
        std::vector<double> mInverseMasses;
        bool mHasFragments = false; ///< The prop was not settled: its fragments
        std::vector<fem::TetFragment> mFragments;
        bool mHasPieces = false;    ///< Its shape had changed (or pieces were to leave): the new shape
        std::vector<std::vector<Vec3>> mPieces;
        double mCellSize = 0.0;
        std::uint64_t mPiecesTaken = 0;   ///< Pieces taken once the fragments' loose pieces are
        std::vector<std::uint8_t> mTakenElements; ///< Elements taken once they are (Prop::mTakenElements)
    };

    struct Prop
    {
        /// RemoveProp leaves no body (a live prop's is in the world: AddProp checks) and an empty FemProp:
        /// call none of its methods
        bool IsRemoved() const { return !mBody.IsValid(); }

        plugin::BodyId mBody;
        FemProp mProp;
        /// Per element: of a piece TakeLooseFragments handed over (its nodes fixed). By element, as element
        /// indices never change while fracture renumbers the nodes it splits (a node index kept from before
        /// a later crack can name another node)
        std::vector<std::uint8_t> mTakenElements{};
        /// What decided the pieces when TakeLooseFragments last looked and left none behind: while the links
        /// broken and the fixed nodes are the same, no piece can be loose (ComputeFragments is skipped)
        int mSettledBrokenLinks = -1;
        std::vector<std::uint8_t> mSettledFixed{};
        std::uint64_t mPiecesTaken = 0;   ///< Pieces handed over
        std::uint64_t mShapeRevision = ~std::uint64_t{0}; ///< mPiecesTaken at the last TakeChangedShape
        std::vector<Vec3> mShapePositions{}; ///< Node positions at the last TakeChangedShape
        std::vector<NodalImpulse> mHits{};   ///< Nodal impulses of the collisions since the last Step
        std::vector<NodalImpulse> mStruck{}; ///< Those of the latest step that had any (GetContactVelocity)
        double mHitsStrikerSpeed = 0.0;   ///< Fastest striker of mHits' collisions along its push (m/s, >= 0)
        double mStruckStrikerSpeed = 0.0; ///< ... of mStruck's (GetContactVelocity's bound)
        Vec3 mContactVelocity = Vec3::Zero(); ///< GetContactVelocity (world frame, m/s)
        Vec3 mSteppedVelocity = Vec3::Zero(); ///< The step's, until LandStep publishes it
        double mContactMass = 0.0;            ///< GetContactMass (kg; 0: none)
        double mSteppedMass = 0.0;            ///< The step's, until LandStep publishes it
        std::vector<int> mMassNodes{};        ///< UpdateContactMass's scratch: struck free nodes ...
        std::vector<double> mMassShares{};    ///< ... and their shares (kept: no allocation per step)
        double mShapeCellSize = 0.0;   ///< The last TakeChangedShape's cell size, for the forecast
        double mShapeTolerance = -1.0; ///< ... and tolerance; < 0 before the first call
        HandOverForecast mForecast{};  ///< What the last step's task worked out for the hand-over
        // A step's task writes mProp, mHits, mStruck, mSteppedVelocity, mSteppedMass, the mass scratch and
        // mForecast of the props it steps, nothing else.
    };
    // Collisions that reached props, and those refused (the first one's reason kept).
    struct CollisionTally
    {
        std::uint64_t mCollisions = 0;
        std::uint64_t mRefused = 0;
        Status mFirstRefusal;
    };
    // How fast each body of a collision pushes the other on, along the collision's normal impulses on that
    // other (m/s, >= 0): [0] how fast B pushes A, [1] how fast A pushes B. UpdateContactVelocity's bound for
    // a prop on that body.
    using StrikerSpeeds = std::array<double, 2>;
    // A collision waiting for the next step, and how many props there were when it was dispatched (those it
    // reaches, as it would have when dispatched).
    struct QueuedCollision
    {
        plugin::Collision mCollision;
        std::size_t mPropCount = 0;
        StrikerSpeeds mStrikerSpeeds{}; ///< Taken at dispatch, on the game's thread
    };
    // A step from StartStep to LandStep: what the task needs and what it made. Stable address for the task.
    struct InFlight
    {
        PropWorld* mOwner = nullptr;
        double mDeltaTime = 0.0;
        std::vector<std::uint8_t> mOnTask;        ///< Per prop: steps on the task (else in StartStep, before it)
        std::vector<std::optional<Mat3>> mBodyRotations; ///< Per prop, at StartStep: its body's frame (none: gone)
        std::vector<QueuedCollision> mCollisions; ///< mStepOffThread: what waited, applied before the step
        CollisionTally mTally;                    ///< What the step's collisions did, until LandStep adds it
        PropStepReport mReport;
        std::uint64_t mForecastsMade = 0;          ///< On the task, until LandStep adds them to the stats
        Status mStatus = Status::Ok();            ///< The first prop that failed to step
        std::uint64_t mTicket = 0;
        bool mOnJobs = false;                     ///< Started with mStartTask (LandStep waits)
        bool mActive = false;
        bool mWaited = false;                     ///< LandStep or a read waited for the task
    };
    // Steps prop inIndex by the flight's step: report, status and the struck members' velocity. True when the
    // prop integrated (it was awake and did not fail).
    bool StepProp(InFlight& ioFlight, std::size_t inIndex);
    static void RunStep(void* inFlight);
    // The flight's collisions onto, then the step of, the props on the task (inOnTask) or off it, in PropId
    // order, stopping at a prop that fails.
    void RunPart(InFlight& ioFlight, bool inOnTask);
    // Applies a collision to the props of its bodies among the first inPropCount for which inWhich(prop
    // index) holds (hits kept for the contact velocity), counted in ioTally. A collision's StrikerSpeeds from
    // the world's states now (at the contacts' impulse-weighted point; 0 for a static or unknown body). Reads
    // the world: the game's thread only.
    StrikerSpeeds MeasureStrikerSpeeds(const plugin::Collision& inCollision) const;
    template <class Which>
    void ApplyToProps(const plugin::Collision& inCollision, std::size_t inPropCount, const Which& inWhich,
                      const StrikerSpeeds& inStrikerSpeeds, CollisionTally& ioTally);
    // Returns when no task is writing the props (a const call may read them then).
    void WaitForStep() const;
    // mStepOffThread with a job system that can start tasks: steps run as tasks.
    bool StepsOnTasks() const;
    // The recording of a prop about to join, or an error when it cannot be recorded.
    Result<std::vector<std::byte>> RecordedSetup(plugin::BodyId inBody, const FemProp& inProp) const;
    // True when inProp's links broken and fixed nodes are those TakeLooseFragments last settled: none can leave.
    static bool IsSettled(const Prop& inProp);
    // Remembers what settled inProp (after TakeLooseFragments handed over all its loose pieces).
    static void Settle(Prop& ioProp);
    // The struck members' velocity from the latest hits and the nodes' velocities now (world frame, by the
    // body's rotation, zero without one); moves new hits to mStruck.
    // inTakenNodes: TakenNodes of the prop (empty when none is taken).
    static Vec3 UpdateContactVelocity(Prop& ioProp, bool inSleeping,
                                      const std::optional<Mat3>& inBodyRotation,
                                      std::span<const std::uint8_t> inTakenNodes);
    // GetContactMass's figure after a step of inDeltaTime (s), from the struck nodes UpdateContactVelocity
    // kept (0 where there are none, or for a GPU prop).
    static double UpdateContactMass(Prop& ioProp, double inDeltaTime,
                                    std::span<const std::uint8_t> inTakenNodes);
    // The fragments of inFragments (inProp's) that TakeLooseFragments hands over, ascending.
    static std::vector<std::size_t> LeavingFragments(const Prop& inProp, const std::vector<fem::TetFragment>& inFragments);
    // TakeChangedShape's test: pieces were taken since the last shape, or a node moved more than inTolerance.
    static bool ShapeChanged(const Prop& inProp, std::span<const Vec3> inPositions, double inTolerance);
    // On the task, after inProp stepped: its HandOverForecast.
    static void ForecastHandOver(Prop& ioProp);
    // The forecast (one that has fragments or a shape) holds for inProp at inPositions (read now): the prop is in
    // the state it was made from, the same links broken, elements and node positions, and with inSameFixedNodes
    // the same fixed nodes (what the fragments depend on; the shape does not, and TakeLooseFragments fixes the
    // nodes of the pieces it takes).
    static bool ForecastHolds(const Prop& inProp, std::span<const Vec3> inPositions, bool inSameFixedNodes);
    // The forecast's shape holds for a TakeChangedShape of inProp at inPositions with inCellSize: it has one,
    // for that cell size, the pieces and elements taken since are those it foresaw, and ForecastHolds.
    static bool ShapeForecastHolds(const Prop& inProp, std::span<const Vec3> inPositions, double inCellSize);
    // Per current node of inProp: a node of a taken element (a piece handed over); empty when none is. O(#T).
    static std::vector<std::uint8_t> TakenNodes(const Prop& inProp);
    // The same elements taken (one byte each), an element past the end of either counting as not taken.
    static bool SameTaken(std::span<const std::uint8_t> inA, std::span<const std::uint8_t> inB);
    // GetCollisionPieces of inProp at inPositions; with inTaken, as if those elements were taken (one byte
    // each).
    static Result<std::vector<std::vector<Vec3>>> PiecesOf(const Prop& inProp, std::span<const Vec3> inPositions, double inCellSize);
    static Result<std::vector<std::vector<Vec3>>> PiecesOf(const Prop& inProp, std::span<const std::uint8_t> inTaken,
                                                           std::span<const Vec3> inPositions, double inCellSize);
    Status ValidateShapeQuery(PropId inProp, double inCellSize, const char* inWhat) const;

    plugin::DamageWorld* mWorld = nullptr;
    PropWorldSettings mSettings;
    plugin::DamageRecorder* mRecorder = nullptr;
    std::vector<Prop> mProps;
    std::vector<QueuedCollision> mQueued;     ///< mStepOffThread: dispatched, waiting for the next StartStep
    std::unique_ptr<InFlight> mInFlight;
    CollisionTally mTally;
    PropHandOverStats mHandOverStats;
};

} // namespace crumple::props
