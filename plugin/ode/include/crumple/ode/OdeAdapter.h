// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Result.h>
#include <crumple/plugin/ConvexBodySettings.h>
#include <crumple/plugin/DamageWorld.h>
#include <crumple/plugin/PropBodySettings.h>

#include <ode/common.h>
#include <ode/contact.h>

#include <memory>
#include <span>
#include <unordered_map>
#include <vector>

namespace crumple::ode
{

/// Settings of an OdeAdapter.
struct CRUMPLE_API OdeAdapterSettings
{
    /// Measure the game thread's CPU time in the adapter's calls (OdeStepStats::mSeconds, Crumple's share of a
    /// step for a profiler or a frame budget). Off by default: the thread's CPU clock is a system call on Linux
    /// (about a microsecond, read twice per registered colliding pair and twice in AfterStep), a cost a game
    /// that does not ask for the figure should not pay.
    bool mMeasureCpuTime = false;
};

/// What the adapter did in the last step.
struct CRUMPLE_API OdeStepStats
{
    int mBodiesSnapshotted = 0;   ///< Bodies whose pre-solve state was taken (only bodies in contact)
    int mContactsReported = 0;    ///< Contacts submitted
    int mContactsRefused = 0;     ///< Contacts in a batch the damage world refused (non-finite engine output)
    plugin::UpdateReport mUpdate; ///< What the damage world dispatched
    double mSeconds = 0.0;        ///< The game thread's CPU time in OnCollide and AfterStep, the damage world's
                                  ///< Update included (s, ThreadCpuSeconds): Crumple's share of the step,
                                  ///< waits for deferred dents left out; 0 unless mMeasureCpuTime
};

/// Connects an ODE world to a crumple::plugin::DamageWorld with two calls per step:
///
///   near callback:  n = dCollide(o1, o2, ...); adapter.OnCollide(o1, o2, {contacts, std::size_t(n)});
///                   ...create joints...
///   after step:     dWorldStep(world, dt);  adapter.AfterStep(dt);
///
/// OnCollide snapshots the bodies involved the first time they appear in a step (before dWorldStep, so the
/// velocities are pre-solve) and buffers the contacts; AfterStep submits them and updates the damage world.
/// Geoms without a body (the static environment) map to one static damage body unless registered with
/// AddStaticGeom. Bodies are mapped in a table: the game keeps ODE's user data pointers. Single-threaded,
/// one adapter per ODE world; no global state.
class CRUMPLE_API OdeAdapter
{
public:
    /// Creates the adapter and the static environment body in inDamage (which must outlive it).
    static Result<std::unique_ptr<OdeAdapter>> Create(plugin::DamageWorld& inDamage, const OdeAdapterSettings& inSettings = {});

    /// Registers a dynamic or kinematic body. Refused when already registered. The adapter reads a registered
    /// body when its geoms collide: unregister it (RemoveBody) before the game destroys it.
    Result<plugin::BodyId> AddBody(dBodyID inBody);
    /// Registers a body-less geom as its own static damage body (e.g. a wall that can carry dents).
    Result<plugin::BodyId> AddStaticGeom(dGeomID inGeom);
    /// Unregisters a body and removes it from the damage world. (A body the game removes from the damage
    /// world itself, DamageWorld::RemoveBody, stays registered here and its contacts are left out, as an
    /// unregistered body's.)
    Status RemoveBody(dBodyID inBody);
    /// Creates a rigid body for Crumple (debris: a prop's loose fragment, props::FragmentBody) in inWorld and
    /// registers it with the damage world: a dBody with the settings' mass and principal inertia (its centre of
    /// mass at the body origin, as ODE requires), pose and velocities, and as its geom in inSpace the box that
    /// bounds the hull points along the principal axes (ODE's convex geom needs the hull's faces; the box is
    /// what ODE collides robustly, at most the hull's bounding box larger than it). Contact parameters are the
    /// game's near callback's, as for its own geoms. The adapter owns body and geom: RemoveBody destroys them,
    /// and so does the adapter's destructor for those left, so inWorld and inSpace must outlive the adapter.
    /// Refused, creating nothing, on invalid settings or a null world or space.
    Result<plugin::BodyId> CreateConvexBody(dWorldID inWorld, dSpaceID inSpace, const plugin::ConvexBodySettings& inSettings);
    /// The ODE body of a convex or prop body this adapter created, nullptr for any other id
    dBodyID GetConvexBody(plugin::BodyId inBody) const;

    /// Creates the body of a destructible prop (plugin::PropBodySettings, props::MakePropBody) in inWorld and
    /// registers it with the damage world: a dBody with the settings' mass, principal inertia and pose, at
    /// rest, and in inSpace one box geom per piece, the piece's bounding box along the body axes (as
    /// CreateConvexBody's). A held body ignores gravity and is put back at its pose, at rest, by AfterStep,
    /// once the step's contacts have gone to the damage world (whose memory of its last impulses it clears:
    /// DamageWorld::ForgetImpacts). Owned as CreateConvexBody's bodies are. Refused, creating nothing, on
    /// invalid settings or a null world or space.
    Result<plugin::BodyId> CreatePropBody(dWorldID inWorld, dSpaceID inSpace, const plugin::PropBodySettings& inSettings);
    /// Replaces the pieces of a prop body's shape (body frame): its box geoms are destroyed and new ones made
    /// in the same space. Mass and inertia stay. Refused, changing nothing, for a body that is not a prop body
    /// of this adapter or for invalid pieces.
    Status SetPropPieces(plugin::BodyId inBody, const std::vector<std::vector<Vec3>>& inPieces);
    /// Sets the velocity of a held prop body now, at its pose, and the one it gets when it is put back at its
    /// pose after each step (world frame, m/s; zero until set): how fast the prop's struck material moves
    /// (props::PropWorld::GetContactVelocity), so that the very next step's contacts meet the members a car
    /// already pushes at their own speed, not at rest (set only at the put-back, it would reach the contacts
    /// a step late, and the car would meet the prop at rest every other step).
    /// Refused, changing nothing, for a body that is not a held prop body of this adapter or a velocity that is
    /// not finite or beyond plugin::cMaxBodySpeed.
    Status SetHeldVelocity(plugin::BodyId inBody, const Vec3& inVelocity);
    /// Sets the mass (kg) a held prop body meets the next steps' contacts with, as a point mass that hardly
    /// turns: the prop's effective mass at the material the car strikes (props::PropWorld::GetContactMass),
    /// so that the engine takes from the car what the prop's FEM then gives the struck members; 0: the body's
    /// own mass and inertia again (as made). ODE needs a positive definite inertia: it is inMass times 100
    /// R^2 about each axis (R^2 = (I_x + I_y + I_z) / m of the body as made), so a contact within R of the
    /// centre of mass meets inMass within 1 % (more would upset dWorldStep's LCP). Crumple's impulses see the
    /// same mass and inertia (the pre-solve snapshot reads them). Refused, changing nothing, for a body that
    /// is not a held prop body of this adapter or a mass that is not 0 or in [1e-12, plugin::cMaxBodyMass].
    Status SetHeldMass(plugin::BodyId inBody, double inMass);
    /// True for a held prop body this adapter made (CreatePropBody with mHeld): what SetHeldVelocity takes,
    /// and props::HeldPropEngine::mIsHeld asks.
    bool IsHeldPropBody(plugin::BodyId inBody) const;
    ~OdeAdapter();
    OdeAdapter(const OdeAdapter&) = delete;
    OdeAdapter& operator=(const OdeAdapter&) = delete;
    /// The damage body of an ODE body, invalid when not registered.
    plugin::BodyId FindBody(dBodyID inBody) const;
    /// The damage body standing for every unregistered body-less geom.
    plugin::BodyId GetEnvironment() const { return mEnvironment; }

    /// Takes the contacts dCollide returned for (inGeom1, inGeom2). Contacts involving an unregistered body
    /// are ignored. ODE's normal points from geom 2 into geom 1, which is Crumple's B-to-A convention.
    /// inFriction: the Coulomb coefficient the game's contact joints use for the pair (>= 0, dInfinity for
    /// no sliding; 0: frictionless impulses).
    void OnCollide(dGeomID inGeom1, dGeomID inGeom2, std::span<const dContactGeom> inContacts, double inFriction = 0.0);
    /// The same for the dContact array a near callback gave dCollide (its geoms at stride sizeof(dContact)),
    /// so the callback passes its contacts as they are, with no copy of their geoms. Call it after filling
    /// their surface parameters: each contact's friction is its surface.mu where surface.mode has
    /// dContactApprox1_1 (ODE's friction pyramid, mu a coefficient as in Crumple); without it ODE reads mu as a
    /// force limit in newtons, which no coefficient matches, and Crumple's impulse for the contact is frictionless.
    void OnCollide(dGeomID inGeom1, dGeomID inGeom2, std::span<const dContact> inContacts);

    /// Submits the step's contacts and dispatches closed collisions; call after dWorldStep/dWorldQuickStep.
    void AfterStep(double inTimeStep);

    double GetTime() const { return mTime; }
    const OdeStepStats& GetLastStepStats() const { return mLastStats; }
    plugin::DamageWorld& GetDamageWorld() { return mDamage; }

private:
    // OnCollide's work: inCount contact geoms from inFirst, inStride bytes apart (as dCollide writes them).
    // inFull: the dContact array inFirst's geoms belong to, whose surfaces give the friction; null: inFriction.
    void CollectContacts(dGeomID inGeom1, dGeomID inGeom2, const dContactGeom* inFirst, std::size_t inCount, std::size_t inStride,
                         const dContact* inFull, double inFriction);
    OdeAdapter(plugin::DamageWorld& inDamage, plugin::BodyId inEnvironment, const OdeAdapterSettings& inSettings)
        : mDamage(inDamage), mEnvironment(inEnvironment), mSettings(inSettings)
    {
    }
    // The thread's CPU time where the settings ask for it, else 0 (no clock read).
    double CpuSeconds() const;
    // The damage body of a geom, with no side effect: a registered body's, a registered static geom's, the
    // environment for any other geom without a body; invalid for a body the adapter was not given.
    plugin::BodyId FindBodyOfGeom(dGeomID inGeom) const;
    // The pre-solve snapshot of a geom's registered body, once per step (only bodies in contact are taken).
    void SnapshotOnce(dGeomID inGeom, plugin::BodyId inId);

    plugin::DamageWorld& mDamage;
    plugin::BodyId mEnvironment;
    OdeAdapterSettings mSettings;
    std::unordered_map<dBodyID, plugin::BodyId> mBodies;      ///< Lookup only, never iterated
    std::unordered_map<dGeomID, plugin::BodyId> mStaticGeoms; ///< Lookup only, never iterated
    std::vector<std::uint8_t> mSnapshotted;                   ///< Per BodyId: state taken this step
    std::vector<plugin::BodyId> mSnapshottedList;
    std::vector<plugin::ContactEvent> mEvents;
    struct OwnedBody
    {
        plugin::BodyId mBody;
        dBodyID mOdeBody = nullptr;
        std::vector<dGeomID> mGeoms;
        dSpaceID mSpace = nullptr;
        bool mProp = false;                     ///< Made by CreatePropBody
        bool mHeld = false;
        Vec3 mHomePosition = Vec3::Zero();      ///< A held body's pose
        Mat3 mHomeOrientation = Mat3::Identity();
        Vec3 mHeldVelocity = Vec3::Zero(); ///< A held body's velocity at its pose (SetHeldVelocity)
        double mOwnMass = 0.0;             ///< As made (SetHeldMass 0 restores it)
        Vec3 mOwnInertia = Vec3::Zero();   ///< Principal, body axes
    };
    std::vector<OwnedBody> mOwned; ///< Bodies CreateConvexBody and CreatePropBody made, in creation order
    void HoldProps();
    Result<plugin::BodyId> Own(OwnedBody&& ioOwned);
    double mTime = 0.0;
    OdeStepStats mCurrent;   ///< The step being collected
    OdeStepStats mLastStats; ///< The last finished step
};

} // namespace crumple::ode
