// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Result.h>
#include <crumple/plugin/BodyState.h>
#include <crumple/plugin/CampbellCrush.h>
#include <crumple/plugin/CollisionGrouper.h>
#include <crumple/plugin/ContactEvent.h>
#include <crumple/plugin/DamageListener.h>
#include <crumple/plugin/DamageState.h>
#include <crumple/plugin/DamageWorldSettings.h>
#include <crumple/plugin/DeformableObject.h>
#include <crumple/plugin/Ids.h>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <vector>

namespace crumple::plugin
{

/// What one DamageWorld::Update did.
struct CRUMPLE_API UpdateReport
{
    int mCollisionsDispatched = 0;     ///< Collisions whose window closed
    int mObjectsDented = 0;            ///< Object dents that moved at least one vertex
    std::uint64_t mVerticesMoved = 0;  ///< Vertex positions recomputed over all objects
    /// DamageWorldSettings::mDeferImpulses: steps' contacts whose impulses came out not finite on the task,
    /// dropped whole there, changing nothing (SubmitContacts refuses them when it solves them itself). Bodies
    /// within BodyState's ranges give finite impulses: a count above 0 is a defect to report.
    int mSubmissionsDropped = 0;
};

/// The damage layer of one physics world. It owns bodies' pre-solve states and deformable objects, turns
/// the engine's contacts into collisions with Baraff impulses, and dispatches closed collisions to the
/// objects (dents) and to listeners.
///
/// Per engine step an adapter calls SetBodyState (before the solver) for moving bodies, SubmitContacts
/// (after the step) with that step's contacts, then Update(time). A step without contacts and without open
/// collisions costs nothing per body or vertex. All calls are on one thread; the world holds no global state,
/// so several worlds may run on several threads. Every call that can fail validates all of its input first
/// and changes nothing when it refuses it.
class CRUMPLE_API DamageWorld
{
public:
    /// Validates the settings and makes the world on the heap. It never moves: adapters, recorders, prop
    /// worlds and deferred dents keep references to it (as Jolt's PhysicsSystem).
    static Result<std::unique_ptr<DamageWorld>> Create(const DamageWorldSettings& inSettings = {});
    /// Waits for deferred dents still running (they point into this world).
    ~DamageWorld();
    DamageWorld(DamageWorld&&) = delete;
    DamageWorld& operator=(DamageWorld&&) = delete;
    DamageWorld(const DamageWorld&) = delete;
    DamageWorld& operator=(const DamageWorld&) = delete;

    /// Registers a rigid body with its current state. Its id takes the slot of the body removed last (next
    /// generation), else a new slot: the same calls give the same ids.
    Result<BodyId> CreateBody(const BodyState& inState);
    /// Replaces a body's state (call before the engine's solver: impulses need pre-solve velocities).
    Status SetBodyState(BodyId inBody, const BodyState& inState);
    /// The body's last state.
    const BodyState* GetBodyState(BodyId inBody) const;
    /// The game set the body's velocities outside the engine's contact solve (held in place, teleported):
    /// the next contacts of its pairs are solved from the velocities the engine reports, not from what
    /// their last impulse left (DamageWorldSettings::mCountImpactOnce). With mDeferImpulses it waits, in
    /// order with the contacts submitted around it, for the task that solves them. Refused for an unknown
    /// body.
    Status ForgetImpacts(BodyId inBody);
    /// Collisions with the body are dispatched at the end of the step they happen in, not when the world's
    /// time window (CollisionGrouperSettings::mTimeWindow) has passed: a destructible prop's FEM must hear of
    /// a hit before the engine goes on (props::PropWorld sets it for props on bodies the engine moves). Off
    /// for every body at first. Refused for an unknown body.
    Status SetDispatchEachStep(BodyId inBody, bool inEachStep);
    /// Contacts between two quiet bodies are dropped by SubmitContacts once validated: no impulse, collision,
    /// listener call or recording (what is left is a check per contact). For what nothing dents and no
    /// listener needs: a prop's loose pieces and the static world they rattle on (props::HeldPropBodies makes
    /// its pieces quiet unless told otherwise; the game says which of its bodies are). A pair with one body
    /// that is not quiet (a car, a prop's held body) is solved as before, bit for bit. A prop on a quiet body
    /// hears nothing of its contacts with other quiet bodies. Off for every body at first. Takes effect
    /// from the next SubmitContacts: contacts submitted before (waiting for their task with
    /// DamageWorldSettings::mDeferImpulses) and a collision of the pair already open go on as usual. Refused
    /// for an unknown body.
    Status SetQuiet(BodyId inBody, bool inQuiet);
    /// Whether the body is quiet (SetQuiet); false for an unknown body.
    bool IsQuiet(BodyId inBody) const { return IsLive(inBody) && mBodies[inBody.mValue].mQuiet; }
    /// Removes a body, its deformable objects and its open collisions. Their ids are refused from then on
    /// (their slots are reused with the next generation).
    Status RemoveBody(BodyId inBody);

    /// Attaches a deformable object to a body; the object's mesh and zones are in that body's frame.
    Result<ObjectId> CreateDeformableObject(BodyId inBody, const DeformableObjectSettings& inSettings);
    /// The object, or nullptr for an invalid or removed id. Read-only: damage reaches an object of the world
    /// only through collisions and LoadDamage, so every dent passes the listeners and the recorder.
    const DeformableObject* GetObject(ObjectId inObject) const;
    /// The vertex ranges of an object's mesh that changed since the last call (for the game's buffer upload),
    /// then forgets them; empty for an invalid or removed id. See ffd::FfdDeformer::TakeDirtyRanges.
    std::vector<ffd::VertexRange> TakeDirtyRanges(ObjectId inObject);
    /// The body an object is attached to.
    BodyId GetObjectBody(ObjectId inObject) const;
    /// Ids of all live objects, ascending.
    std::vector<ObjectId> GetObjectIds() const;
    /// Slots the world holds for bodies and objects, live or free: at most the most bodies (objects) live at
    /// once, however many were created and removed.
    std::size_t GetBodySlotCount() const { return mBodies.size(); }
    std::size_t GetObjectSlotCount() const { return mObjects.size(); }

    /// Takes one engine step's contacts: validates all of them (known bodies, A != B, finite values, unit
    /// normal), drops those between two quiet bodies (SetQuiet), moves the others onto the surfaces, solves
    /// the impulses of each body pair's contacts of the same
    /// time (within 1e-9 s) together, and groups the closing ones into collisions. Submit a step's contacts
    /// in one call where you can: with a step and DamageWorldSettings::mCountImpactOnce, contacts of a pair
    /// for a step already submitted (a game that submits per manifold) are solved from what the earlier
    /// impulse left, as the same impact counted once, but apart from the first ones, not jointly with them.
    /// Refused whole on any bad contact, on an impulse that is not finite (NonFinite), and on a pair left
    /// unsolved by a job system whose parallel for skipped a piece (InvalidArgument). A step with many
    /// closing contacts solves its pairs on DamageWorldSettings::mJobs, to the same bits. With
    /// DamageWorldSettings::mDeferImpulses only the validation runs here: the contacts and their bodies'
    /// states (as now) wait for the task the next Update starts, which does the rest.
    /// @param[in] inTimeStep the engine step that produced them (s), or 0. With a step, a contact reported
    ///            before touching (negative penetration depth g) resolves only the approach beyond g/dt, as
    ///            the engine's speculative contacts do; without one, gap contacts resolve their whole
    ///            approach. With a step, a pair that took an impulse at the previous step is solved from the
    ///            velocities that impulse left (an impact is counted once, however many steps the engine
    ///            takes to stop it).
    Status SubmitContacts(std::span<const ContactEvent> inContacts, double inTimeStep = 0.0);

    /// Dispatches the collisions whose time window has closed at inTime (s): dents, then listeners. A time
    /// that is not finite closes no collision (Flush closes them all); work in flight still lands. With
    /// deferred dents it first lands the dents the previous Update started (their objects dented, vertices
    /// moved and OnCollision calls are in this report), then starts the new ones (counted as dispatched).
    /// With deferred impulses the landed task also solved the contacts submitted before the previous Update:
    /// this one closes collisions at that Update's time (what it would have closed had it solved them), and
    /// its task solves the contacts submitted since.
    UpdateReport Update(double inTime);
    /// Dispatches every open collision now and lands every dent (end of a run, before saving).
    UpdateReport Flush();
    /// Deferred dents: true while a started task has not landed yet.
    bool HasDentsInFlight() const { return mInFlight != nullptr && mInFlight->mActive; }
    /// Deferred dents: lands the dents in flight now (waits for the task, publishes, calls OnCollision)
    /// without closing any open collision. A recorder does so when it starts and closes, so that it sees
    /// every collision exactly once. Calls that read or change damage land by themselves; what they land is
    /// reported by the next Update or Flush.
    UpdateReport LandDents();

    /// Adds a listener (not owned; it must outlive the world or be removed). Adding one twice is a no-op.
    void AddListener(DamageListener* inListener);
    void RemoveListener(DamageListener* inListener);

    /// Restores every object's undeformed mesh.
    void ResetDamage();
    /// The damage of every object (control displacements), and its binary encoding.
    DamageState GetDamageState() const;
    std::vector<std::byte> SaveDamage() const;
    /// Restores a saved damage state. Refused, changing nothing, when it is corrupt, of another version,
    /// or does not match this world's objects (ids, zones, control counts).
    Status SetDamageState(const DamageState& inState);
    Status LoadDamage(std::span<const std::byte> inBytes);

    const DamageWorldSettings& GetSettings() const { return mSettings; }
    /// Collisions still waiting for their window to close (waits for a task in flight). With mDeferImpulses,
    /// those of contacts submitted since the last Update are not counted yet.
    std::size_t GetOpenCollisionCount() const
    {
        WaitForDents();
        return mGrouper.GetOpenCount();
    }
    /// Counts the changes of the objects' deformed shapes: each dispatch (or, with deferred dents, each
    /// landing) in which a dent moved vertices, each ResetDamage and each accepted SetDamageState/LoadDamage.
    /// An engine shape that follows the dents (BulletAdapter::CreateFollowingHull) compares it with the count it
    /// last saw, so that it follows a reset or a loaded state as well as a dent.
    std::uint64_t GetShapeRevision() const { return mShapeRevision; }

private:
    // The object for the world's own changes (dispatch, reset, load), or nullptr.
    DeformableObject* GetMutableObject(ObjectId inObject);

    DamageWorld(const DamageWorldSettings& inSettings, CollisionGrouper inGrouper)
        : mSettings(inSettings), mGrouper(std::move(inGrouper)) {}

    struct BodySlot
    {
        BodyState mState;
        bool mAlive = false;
        std::uint32_t mGeneration = 0; ///< Of the body that holds (or last held) the slot
        bool mDispatchEachStep = false;
        std::vector<ObjectId> mObjects;
        bool mQuiet = false;
    };
    struct ObjectSlot
    {
        BodyId mBody;
        std::uint32_t mGeneration = 0;         ///< Of the object that holds (or last held) the slot
        std::vector<DeformableObject> mObject; ///< Empty once removed (DeformableObject has no default state)
    };

    /// What the last impulse of a touching pair left its bodies moving at (world, m/s and rad/s): the
    /// next step's contacts of the pair are solved from these velocities rather than the engine's, so a
    /// collision's impulse depends on the bodies' state before it and not on how many steps the engine takes
    /// to resolve it (a soft ODE contact takes several, Bullet's one). External forces over one step (gravity,
    /// a car's drive) are neglected. Expires when the pair has no contact for cImpactMemorySteps steps.
    struct ImpactMemory
    {
        BodyId mA, mB;
        double mTime = 0.0;
        /// The velocities the impulse left: linear in the world, angular in each body's own frame (the engine
        /// turns the body between steps; a spin kept in the world frame would meet the next step's inertia
        /// turned under it, and its energy was not kept: a spinning rail on the ground gained it step after
        /// step)
        Vec3 mLinearA, mAngularBodyA, mLinearB, mAngularBodyB;
    };
    static constexpr double cImpactMemorySteps = 1.5; ///< In steps: only the immediately following step continues
    /// Contact times this close (s) are one engine step's: round-off apart, far below any engine's step
    static constexpr double cSameStepTime = 1.0e-9;
    /// Drops the memories of every pair the body is in
    void ForgetMemoriesOf(BodyId inBody);
    /// A step's pair solves go to the job system when its contacts that close number at least this many (a
    /// brick wall's burst: hundreds; resting pieces and a car's hit stay inline)
    static constexpr std::size_t cParallelClosingContacts = 64;
    /// Pieces per worker at most that a step's pair solves split into: several, as one pair's solve can cost
    /// a hundred others'
    static constexpr std::size_t cPiecesPerWorker = 4;

    bool IsLive(BodyId inBody) const
    {
        return inBody.mValue < mBodies.size() && mBodies[inBody.mValue].mAlive &&
               mBodies[inBody.mValue].mGeneration == inBody.mGeneration;
    }
    Status ValidateContact(const ContactEvent& inContact, std::size_t inIndex) const;

    /// A body named by one SubmitContacts call, as it was then: its state and dispatch flag.
    struct SubmittedBody
    {
        BodyId mBody;
        BodyState mState;
        bool mDispatchEachStep = false;
    };
    /// One SubmitContacts call, or a ForgetImpacts (mForget valid, no contacts), as the solve takes it.
    struct Submission
    {
        std::vector<ContactEvent> mContacts{};
        double mTimeStep = 0.0;
        std::vector<SubmittedBody> mBodies{}; ///< Every body the contacts name, by ascending id
        BodyId mForget{};
    };
    /// The bodies inContacts name (validated: live), by ascending id, as they are now.
    std::vector<SubmittedBody> SnapshotBodies(std::span<const ContactEvent> inContacts);
    /// inBody's entry in inBodies (by ascending id; it must be there)
    static const SubmittedBody& SubmittedBodyOf(std::span<const SubmittedBody> inBodies, BodyId inBody);
    /// Solves validated contacts' impulses into the grouper and the impact memories, reading the bodies only
    /// from inBodies (so a task can run it while the game moves on); refused whole, changing nothing, where
    /// an impulse is not finite or a pair was left unsolved. The pairs' solves split over inJobs' parallel
    /// for where given (null on the deferred task, which must not call back into the job system), to the same
    /// bits.
    Status SolveContacts(std::span<const ContactEvent> inContacts, double inTimeStep,
                         std::span<const SubmittedBody> inBodies, const JobSystem* inJobs);
    Status SolveSubmission(const Submission& inSubmission, const JobSystem* inJobs);
    /// Solves inSubmissions in order (on the task or, SolvePendingHere, on the caller's thread, with inJobs
    /// for the pairs' solves there); returns how many were dropped (an impulse not finite).
    int SolveSubmissions(std::span<const Submission> inSubmissions, const JobSystem* inJobs);
    /// mDeferImpulses: solves the submissions that wait for the next task here and now (calls that need the
    /// collisions and memories complete: Flush, RemoveBody). Call after Land().
    void SolvePendingHere();
    UpdateReport Dispatch(std::vector<Collision> inCollisions);
    CrushSide CrushSideOf(BodyId inBody) const;
    /// Listeners may remove themselves (or others) from their callbacks: a dispatch calls the ones
    /// registered when it began that are still registered.
    bool IsListening(const DamageListener* inListener) const;

    /// Deferred dents: the collisions of one dispatch, the objects each dents, and what the task made.
    struct DentTarget
    {
        ObjectId mObject;
        DeformableObject* mDeformable = nullptr;
        ECollisionSide mSide = ECollisionSide::A;
    };
    struct InFlight
    {
        DamageWorld* mWorld = nullptr;
        std::vector<Submission> mSubmissions; ///< mDeferImpulses: solved on the task, before the dents
        int mSubmissionsDropped = 0;          ///< Written by the task
        std::vector<Collision> mCollisions;
        std::vector<std::vector<DentTarget>> mTargets; ///< Per collision, in dispatch order
        std::vector<std::vector<ObjectDent>> mDents;   ///< Per collision, written by the task
        /// The listeners registered when the batch was dispatched (OnBeforeCollision): the landing's
        /// OnCollision goes to those still registered, not to one added since
        std::vector<DamageListener*> mListeners;
        std::uint64_t mTicket = 0;
        bool mActive = false;
    };
    static void RunDeferredDents(void* inInFlight);
    /// Waits for the task, publishes its objects and calls OnCollision; a no-op with nothing in flight. What it
    /// landed is kept for the next Update or Flush report.
    void Land();
    /// The landed work not reported yet, then forgotten.
    UpdateReport TakeLandedReport();
    /// Waits for the task without landing it (const readers of damage).
    void WaitForDents() const;

    DamageWorldSettings mSettings;
    CollisionGrouper mGrouper;
    std::vector<BodySlot> mBodies;
    std::vector<ObjectSlot> mObjects;
    std::vector<std::uint32_t> mFreeBodies;  ///< Slots of removed bodies, the last removed at the back
    std::vector<std::uint32_t> mFreeObjects; ///< Slots of removed objects, likewise
    std::vector<DamageListener*> mListeners;
    std::vector<ImpactMemory> mImpactMemories; ///< Pairs that touched at the last step, see ImpactMemory
    std::vector<Submission> mPending;          ///< mDeferImpulses: what the next Update's task solves
    std::vector<std::uint8_t> mNamedScratch;   ///< SnapshotBodies' flag per body slot, all 0 between calls
    std::size_t mQuietBodies = 0;              ///< Live bodies that are quiet: none, and nothing is checked
    std::vector<ContactEvent> mHeardScratch;   ///< SubmitContacts' contacts of pairs not both quiet
    /// mDeferImpulses: the time of the last Update (with a finite time), which handed its submissions to the
    /// task; the next Update closes collisions at it
    double mHandedOverAt = -std::numeric_limits<double>::infinity();
    std::unique_ptr<InFlight> mInFlight;        ///< Deferred dents (stable address for the task)
    UpdateReport mLanded;                       ///< Deferred dents landed and not reported yet
    std::uint64_t mShapeRevision = 0;           ///< GetShapeRevision
};

} // namespace crumple::plugin
