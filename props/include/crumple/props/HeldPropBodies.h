// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Result.h>
#include <crumple/plugin/ConvexBodySettings.h>
#include <crumple/plugin/Ids.h>
#include <crumple/props/PropWorld.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace crumple::props
{

/// The engine calls HeldPropBodies makes: an adapter's, bound by the game (ODE's need its world and space).
struct CRUMPLE_API HeldPropEngine
{
    /// BulletAdapter / OdeAdapter::CreateConvexBody: a loose piece's rigid body, a body of the prop world's
    /// damage world (as the adapters' are: HeldPropSettings::mQuietPieces makes it quiet there). Required.
    std::function<Result<plugin::BodyId>(const plugin::ConvexBodySettings&)> mCreatePieceBody;
    /// SetPropPieces: a held body's new collision shape (body frame). Required.
    std::function<Status(plugin::BodyId, const std::vector<std::vector<Vec3>>&)> mSetPropPieces;
    /// SetHeldVelocity: how fast the struck members move (world frame, m/s). Empty: held bodies are put back at
    /// rest after every step, and meet each contact with the whole prop's mass at rest (far too stiff for a
    /// fence; for comparison only).
    std::function<Status(plugin::BodyId, const Vec3&)> mSetHeldVelocity;
    /// SetHeldMass: the mass the struck members meet a contact with (kg; 0: the body's own). Empty: held bodies
    /// meet every contact with the whole prop's mass and inertia, whatever they strike (a rail half-way between
    /// its posts weighs about half the fence over a step, one beside a post many times it). Opt-in and
    /// experimental, not bound by the samples: the FEM's effective mass is exact for the nodes a contact's
    /// impulse lands on, but one held body has one mass for all its contacts, and how many nodes a contact
    /// reaches follows how many points the engine reports (README, known limits: on the 64 km/h fence
    /// drive-through Bullet's car loses 1.96 m/s instead of 2.36, ODE's 12.1 instead of 2.29).
    std::function<Status(plugin::BodyId, double)> mSetHeldMass;
    /// BulletAdapter / OdeAdapter::IsHeldPropBody: which props' bodies are held. Empty: every prop's. A prop
    /// whose body is not held (a free crate, a static sign) gets no held velocity; its pieces and its shape
    /// are handled as a held prop's.
    std::function<bool(plugin::BodyId)> mIsHeld;
};

/// How HeldPropBodies keeps the engine's bodies in step with the props' FEM.
struct CRUMPLE_API HeldPropSettings
{
    double mShapeCellSize = 0.25;  ///< Collision pieces' cell (m, > 0): PropWorld::GetCollisionPieces
    double mShapeTolerance = 0.01; ///< A held body's shape follows its FEM to this (m, >= 0): TakeChangedShape
    double mMinPieceMass = 0.05;   ///< Lighter loose pieces leave without a body (kg, >= 0): TakeLooseFragments
    /// Loose pieces' bodies are quiet (plugin::DamageWorld::SetQuiet): their contacts with each other and
    /// with the game's quiet bodies (mark the ground and the static course so) make no collision (in the
    /// threaded Bullet racing session 831 of its 984 collisions were such pairs). Off: every such contact is
    /// solved and reaches the listeners (game audio of rattling debris). A piece meeting a body that is not
    /// quiet (a car, a prop) makes its collision either way.
    bool mQuietPieces = true;
};

/// A piece HeldPropBodies handed over.
struct CRUMPLE_API HeldPiece
{
    LooseFragment mPiece; ///< What left the prop (its elements: stop drawing them there)
    plugin::BodyId mBody; ///< Its engine body; invalid when it left without one (mPiece.mDropped, or refused)
};

/// What one HeldPropBodies::Update did.
struct CRUMPLE_API HeldPropUpdate
{
    std::vector<HeldPiece> mPieces; ///< Pieces handed over, PropWorld::TakeLooseFragments order
    int mShapesGiven = 0;           ///< SetPropPieces calls
    int mVelocitiesGiven = 0;       ///< SetHeldVelocity calls
    int mMassesGiven = 0;           ///< SetHeldMass calls
};

/// Everything a game does for the held prop bodies of a PropWorld after each engine step, once, in the
/// library: each prop's body is a held body of the engine (the adapter's CreatePropBody, with the shape of
/// props::MakePropBody), its FEM takes the car's impulses (PropWorld), and after PropWorld::Step this
///   1. gives each held body the velocity of the members its latest collisions struck (GetContactVelocity)
///      and the mass they meet a contact with over a step (GetContactMass), so the engine's next contact
///      meets them moving as the FEM moves them and takes from the car what the FEM then gives them;
///   2. makes the pieces that broke loose engine bodies of their own (TakeLooseFragments);
///   3. hands the engine a prop's new collision shape when it changed (TakeChangedShape; the first Update
///      gives every prop's shape, so a body made with another cell size is set right at once).
/// A world whose props all sleep costs one comparison per prop: a velocity goes to the engine only when it
/// changed, and pieces and shapes are looked at only after a step in which some prop moved (or a prop joined).
///
/// Threading: the game's thread, after PropWorld::Step (the engine must not be stepping).
class CRUMPLE_API HeldPropBodies
{
public:
    /// Keeps ioProps' held bodies (ioProps must outlive the object). Refused for a missing required engine
    /// call, mSetHeldMass on a world that does not work out contact masses (PropWorldSettings::mContactMass),
    /// or a setting that is not finite or out of its range.
    static Result<HeldPropBodies> Create(PropWorld& ioProps, HeldPropEngine inEngine, const HeldPropSettings& inSettings = {});

    /// After each PropWorld::Step (inStepped is its report; once per step: pieces and shapes are looked at
    /// only after a step in which a prop moved): the three things above, in PropId order; outUpdate says what
    /// was done. An engine call that fails does not stop the others (a piece already left its prop and the
    /// engine holds what it made): the first failure is returned, its piece left without a body (a body the
    /// damage world does not know, which SetQuiet refuses, stays the piece's, not quiet); a refused
    /// shape is given again at the next Update. Every prop of the world must be a prop body of the engine;
    /// one that is not held (a free or static prop body) must be named by HeldPropEngine::mIsHeld, or the
    /// engine refuses its held velocity at every step. A prop removed (PropWorld::RemoveProp) whose held body
    /// the game keeps in the engine gets that body put back at rest with its own mass at the next Update (one
    /// call each, where a velocity or mass had been given): a fresh prop on the body starts from it as made.
    Status Update(const PropStepReport& inStepped, HeldPropUpdate& outUpdate);

private:
    HeldPropBodies(PropWorld& ioProps, HeldPropEngine inEngine, const HeldPropSettings& inSettings)
        : mProps(&ioProps), mEngine(std::move(inEngine)), mSettings(inSettings) {}

    PropWorld* mProps = nullptr;
    HeldPropEngine mEngine;
    HeldPropSettings mSettings;
    std::vector<Vec3> mGivenVelocity; ///< Per prop: the last SetHeldVelocity (zero: at rest, as made)
    std::vector<double> mGivenMass;   ///< Per prop: the last SetHeldMass (zero: its own, as made)
    std::vector<plugin::BodyId> mGivenBody; ///< Per prop: the body those went to (invalid: none given)
    std::size_t mPropsSeen = 0;       ///< Props whose first shape was given (they join in PropId order)
    std::vector<std::uint8_t> mShapePending; ///< Per prop: the engine refused its last shape (retried)
};

} // namespace crumple::props
