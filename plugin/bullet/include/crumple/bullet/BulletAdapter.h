// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Result.h>
#include <crumple/plugin/ConvexBodySettings.h>
#include <crumple/plugin/DamageWorld.h>
#include <crumple/plugin/PropBodySettings.h>

#include <LinearMath/btScalar.h>
#include <LinearMath/btTransform.h>

#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

class btCollisionObject;
class btCompoundShape;
class btConvexHullShape;
class btDefaultMotionState;
class btRigidBody;
class btDiscreteDynamicsWorld;
class btDynamicsWorld;

namespace crumple::bullet
{

class ReplaceableHull; // a prop piece's hull (private to the adapter)

/// Settings of a BulletAdapter.
struct CRUMPLE_API BulletAdapterSettings
{
    double mMaxSeparation = 0.05; ///< Manifold points further apart than this (m) are not reported. Points with a
                                  ///< small gap are reported as speculative contacts (their gap/dt of approach
                                  ///< is left to the next step), because Bullet's solver already acts on them
    /// Measure the game thread's CPU time in the adapter's callbacks (BulletStepStats::mSeconds, Crumple's share of
    /// a sub-step for a profiler or a frame budget). Off by default: the thread's CPU clock is a system call on
    /// Linux, read four times per sub-step (6-9 us per sub-step on this project's test host, a quarter of a bare
    /// step with nothing in contact), a cost a game that does not ask for the figure should not pay.
    bool mMeasureCpuTime = false;
};

/// What the adapter did in the last internal sub-step.
struct CRUMPLE_API BulletStepStats
{
    int mBodiesSnapshotted = 0; ///< Active mapped bodies whose pre-solve state was taken
    int mContactsReported = 0;  ///< Manifold points submitted
    int mContactsRefused = 0;   ///< Points of a batch the damage world refused (non-finite engine output)
    plugin::UpdateReport mUpdate; ///< What the damage world dispatched
    double mSeconds = 0.0;        ///< The game thread's CPU time in the adapter's two callbacks, the damage
                                  ///< world's Update included (s, ThreadCpuSeconds): Crumple's share of the
                                  ///< sub-step, waits for deferred dents left out; 0 unless
                                  ///< BulletAdapterSettings::mMeasureCpuTime
};

/// Connects a btDiscreteDynamicsWorld to a crumple::plugin::DamageWorld.
///
/// It installs Bullet's per-world internal tick callbacks (never the process-wide gContactAddedCallback):
/// before each internal sub-step it snapshots the state of every awake mapped body (impulses need
/// pre-solve velocities), after it reads the contact manifolds of mapped pairs, submits them and updates
/// the damage world with the sub-step's time. Callbacks the game installed before are kept and called
/// (with the game's own world user pointer restored around the call); the destructor puts them back.
/// Bodies are mapped in a table, so the game keeps btCollisionObject user pointers for itself. Several
/// adapters on several worlds are independent. Not thread-safe: one adapter per world, stepped on one thread.
///
/// Each point's friction is the coefficient Bullet's solver uses for it (btManifoldPoint::m_combinedFriction,
/// the product of the two objects' frictions), and Crumple's impulse solves it on Coulomb's isotropic cone.
/// Bullet's default solver works along one tangent per contact (the slip's direction when the point
/// appeared), so after an offset or corner hit whose contact then slips across that tangent the engine's
/// sideways momentum change can differ from Crumple's impulse (tests/engines/CrossEngineTest.cpp measures it;
/// ODE's friction pyramid agrees to 0.1 %). SOLVER_USE_2_FRICTION_DIRECTIONS (with
/// SOLVER_DISABLE_VELOCITY_DEPENDENT_FRICTION_DIRECTION: ODE's pyramid) in the world's solver mode brings
/// Bullet closer: the crash scenes set both, and 27 of their 28 frictional crashes agree within 3 % (25
/// without).
class CRUMPLE_API BulletAdapter
{
public:
    /// Attaches to inWorld. Both worlds must outlive the adapter.
    static Result<std::unique_ptr<BulletAdapter>> Create(btDiscreteDynamicsWorld& inWorld, plugin::DamageWorld& inDamage,
                                                         const BulletAdapterSettings& inSettings = {});
    ~BulletAdapter();
    BulletAdapter(const BulletAdapter&) = delete;
    BulletAdapter& operator=(const BulletAdapter&) = delete;

    /// Registers a rigid body or static collision object with the damage world (its current state).
    /// Contacts between unregistered objects are ignored. Refused when already registered. The adapter reads
    /// a registered object at every step: unregister it (RemoveBody) before the game destroys it.
    Result<plugin::BodyId> AddBody(btCollisionObject& inObject);
    /// Unregisters an object and removes its body, deformable objects and open collisions from the damage
    /// world. (A body the game removes from the damage world itself, DamageWorld::RemoveBody, stays
    /// registered here and its contacts are left out, as an unregistered object's.)
    Status RemoveBody(const btCollisionObject& inObject);
    /// The damage body of an object, invalid when not registered.
    plugin::BodyId FindBody(const btCollisionObject& inObject) const;

    /// Makes the physical shape follow a deformable object's dents: returns a convex hull over (up to
    /// inMaxPoints) vertices of the object's mesh, in the body frame, owned by the adapter. Use it as the
    /// body's collision shape or as a direct child of its btCompoundShape; after each step in which the
    /// objects' shapes changed (a dent landed, DamageWorld::ResetDamage, an accepted LoadDamage or
    /// SetDamageState: DamageWorld::GetShapeRevision) the adapter moves its points to the deformed vertices
    /// and refreshes its bounds, the compound's (its child bounds and its own) and the body's broadphase entry.
    Result<btConvexHullShape*> CreateFollowingHull(plugin::ObjectId inObject, int inMaxPoints = 256);

    /// Creates a rigid body for Crumple (debris: a prop's loose fragment, props::FragmentBody) and registers it
    /// with the damage world: a btRigidBody with the settings' mass, principal inertia (its local inertia), pose
    /// and velocities, and a btConvexHullShape of the hull points with a collision margin of at most 1 cm (and
    /// at most a tenth of the hull's smallest half extent: Bullet inflates convex shapes by their margin). It
    /// is added to the world with the default group and mask; friction and restitution are Bullet's defaults
    /// (set them on GetConvexBody). The adapter owns it: RemoveBody takes it out of the world and deletes it,
    /// and so does the adapter's destructor for those left. Refused, creating nothing, on invalid settings.
    Result<plugin::BodyId> CreateConvexBody(const plugin::ConvexBodySettings& inSettings);
    /// The Bullet body of a convex or prop body this adapter created, nullptr for any other id
    btRigidBody* GetConvexBody(plugin::BodyId inBody) const;

    /// Creates the body of a destructible prop (plugin::PropBodySettings, props::MakePropBody) and registers
    /// it with the damage world: a btRigidBody with the settings' mass, principal inertia and pose, at rest,
    /// whose shape is a btCompoundShape of one btConvexHullShape per piece (margins as CreateConvexBody's).
    /// A held body has no gravity and is put back at its pose, at rest, after every internal sub-step, once
    /// the sub-step's contacts have gone to the damage world (whose memory of its last impulses it clears:
    /// DamageWorld::ForgetImpacts). Owned as CreateConvexBody's bodies are. Refused, creating nothing, on
    /// invalid settings.
    Result<plugin::BodyId> CreatePropBody(const plugin::PropBodySettings& inSettings);
    /// Replaces the pieces of a prop body's shape (body frame): what is left of the prop once pieces broke
    /// loose (props::PropWorld::GetCollisionPieces). The body leaves the world and comes back with the new
    /// shape, so no contact with a piece that left survives. Mass and inertia stay. Refused, changing
    /// nothing, for a body that is not a prop body of this adapter or for invalid pieces.
    Status SetPropPieces(plugin::BodyId inBody, const std::vector<std::vector<Vec3>>& inPieces);
    /// Sets the velocity of a held prop body now, at its pose, and the one it gets when it is put back at its
    /// pose after each step (world frame, m/s; zero until set): how fast the prop's struck material moves
    /// (props::PropWorld::GetContactVelocity), so that the very next step's contacts meet the members a car
    /// already pushes at their own speed, not at rest (set only at the put-back, it would reach the contacts
    /// a step late, and the car would meet the prop at rest every other step).
    /// Refused, changing nothing, for a body that is not a held prop body of this adapter or a velocity that is
    /// not finite or beyond plugin::cMaxBodySpeed.
    Status SetHeldVelocity(plugin::BodyId inBody, const Vec3& inVelocity);
    /// Sets the mass (kg) a held prop body meets the next steps' contacts with, as a point mass that does not
    /// turn (zero inverse inertia): the prop's effective mass at the material the car strikes
    /// (props::PropWorld::GetContactMass), so that the engine takes from the car what the prop's FEM then
    /// gives the struck members; 0: the body's own mass and inertia again (as made: the whole prop, turning
    /// about its centre of mass). Crumple's impulses see the same mass (the pre-solve snapshot reads it).
    /// Refused, changing nothing, for a body that is not a held prop body of this adapter or a mass that is
    /// not 0 or in [1e-12, plugin::cMaxBodyMass].
    Status SetHeldMass(plugin::BodyId inBody, double inMass);
    /// True for a held prop body this adapter made (CreatePropBody with mHeld): what SetHeldVelocity takes,
    /// and props::HeldPropEngine::mIsHeld asks.
    bool IsHeldPropBody(plugin::BodyId inBody) const;
    /// Simulated time (s) the adapter has seen: the sum of internal sub-steps.
    double GetTime() const { return mTime; }
    const BulletStepStats& GetLastStepStats() const { return mLastStats; }
    plugin::DamageWorld& GetDamageWorld() { return mDamage; }

private:
    BulletAdapter(btDiscreteDynamicsWorld& inWorld, plugin::DamageWorld& inDamage, const BulletAdapterSettings& inSettings);

    friend struct BulletTickCallbacks;
    void PreTick(double inTimeStep);
    void PostTick(double inTimeStep);
    void UpdateHulls();
    void HoldProps();

    struct MappedBody
    {
        btCollisionObject* mObject = nullptr;
        plugin::BodyId mBody;
    };
    struct FollowingHull
    {
        plugin::ObjectId mObject;
        btCollisionObject* mOwner = nullptr;
        std::unique_ptr<btConvexHullShape> mShape;
        std::vector<std::uint32_t> mVertices; ///< Mesh vertex per hull point
    };

    btDiscreteDynamicsWorld& mWorld;
    plugin::DamageWorld& mDamage;
    BulletAdapterSettings mSettings;
    std::vector<MappedBody> mBodies; ///< In registration order: deterministic snapshot order
    std::unordered_map<const btCollisionObject*, plugin::BodyId> mLookup; ///< Lookup only, never iterated
    std::vector<FollowingHull> mHulls;
    std::uint64_t mHullRevision = 0; ///< DamageWorld::GetShapeRevision the hulls were last moved at
    struct OwnedBody
    {
        plugin::BodyId mBody;
        std::unique_ptr<btConvexHullShape> mShape;
        std::unique_ptr<btCompoundShape> mCompound;                ///< A prop body's shape, else null
        std::vector<std::unique_ptr<ReplaceableHull>>
            mPieces; ///< Its children's hulls, kept from shape to shape
        std::unique_ptr<btDefaultMotionState> mMotion;
        std::unique_ptr<btRigidBody> mRigidBody;
        bool mHeld = false;
        btTransform mHome; ///< A held body's pose
        btVector3 mHeldVelocity{0, 0, 0}; ///< A held body's velocity at its pose (SetHeldVelocity)
        btScalar mOwnMass = 0;            ///< As made (SetHeldMass 0 restores it)
        btVector3 mOwnInertia{0, 0, 0};
    };
    std::vector<OwnedBody> mOwned; ///< Bodies CreateConvexBody and CreatePropBody made, in creation order
    /// Adds a body made here to both worlds and keeps it; on refusal takes it out again
    Result<plugin::BodyId> Own(OwnedBody&& ioOwned);
    std::vector<plugin::ContactEvent> mEvents; ///< Scratch, reused every sub-step

    // The game's callbacks and user pointer, chained and restored.
    void (*mPreviousPreTick)(btDynamicsWorld*, btScalar) = nullptr;
    void (*mPreviousPostTick)(btDynamicsWorld*, btScalar) = nullptr;
    void* mPreviousUserInfo = nullptr;

    double mTime = 0.0;
    BulletStepStats mLastStats;
};

} // namespace crumple::bullet
