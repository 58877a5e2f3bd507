// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// HeldPropBodies: what a game does for held prop bodies after each step (the struck members' velocity, loose
// pieces as bodies, the shape that follows the FEM), against an engine that only counts the calls.
#include "BrittlePanel.h"
#include "WorldFixture.h"

#include <crumple/props/HeldPropBodies.h>
#include <crumple/props/PropWorld.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <utility>

using namespace crumple;
using namespace crumple::plugin;
using namespace crumple::props;

namespace
{

// The engine's side: every call counted and kept; each piece body is a body of the damage world, made from
// the piece's settings as an adapter's CreateConvexBody does. A body refused when mRefuseBodies.
struct CountingEngine
{
    explicit CountingEngine(DamageWorld& ioWorld) : mWorld(&ioWorld) {}

    DamageWorld* mWorld;
    std::vector<ConvexBodySettings> mBodies;
    std::vector<BodyId> mBodyIds; // the world's id of each body made
    std::vector<std::vector<std::vector<Vec3>>> mShapes;
    std::vector<Vec3> mVelocities;
    std::vector<BodyId> mVelocityBodies; // the body of each velocity given
    std::vector<double> mMasses;         // each contact mass given
    bool mRefuseBodies = false;
    bool mRefuseShapes = false;

    const ConvexBodySettings& BodyMade(BodyId inBody) const
    {
        const auto found = std::find(mBodyIds.begin(), mBodyIds.end(), inBody);
        REQUIRE(found != mBodyIds.end());
        return mBodies[static_cast<std::size_t>(found - mBodyIds.begin())];
    }

    HeldPropEngine Calls()
    {
        return {.mCreatePieceBody =
                    [this](const ConvexBodySettings& inBody) -> Result<BodyId> {
                        if (mRefuseBodies)
                            return MakeError(EError::InvalidArgument, "the engine refused the piece");
                        BodyState state;
                        state.mMass = inBody.mMass;
                        state.mInverseInertiaWorld = inBody.WorldInertia().inverse();
                        state.mTransform.mTranslation = inBody.mPosition;
                        state.mTransform.mRotation = inBody.mOrientation;
                        state.mCenterOfMass = inBody.mPosition;
                        state.mLinearVelocity = inBody.mLinearVelocity;
                        state.mAngularVelocity = inBody.mAngularVelocity;
                        Result<BodyId> made = mWorld->CreateBody(state);
                        if (made)
                        {
                            mBodies.push_back(inBody);
                            mBodyIds.push_back(made.Get());
                        }
                        return made;
                    },
                .mSetPropPieces =
                    [this](BodyId, const std::vector<std::vector<Vec3>>& inPieces) -> Status {
                        if (mRefuseShapes)
                            return MakeError(EError::InvalidArgument, "the engine refused the shape");
                        mShapes.push_back(inPieces);
                        return Status::Ok();
                    },
                .mSetHeldVelocity =
                    [this](BodyId inBody, const Vec3& inVelocity) {
                        mVelocities.push_back(inVelocity);
                        mVelocityBodies.push_back(inBody);
                        return Status::Ok();
                    },
                .mSetHeldMass =
                    [this](BodyId, double inMass) {
                        mMasses.push_back(inMass);
                        return Status::Ok();
                    },
                .mIsHeld = nullptr};
    }
    std::size_t CallCount() const { return mBodies.size() + mShapes.size() + mVelocities.size() + mMasses.size(); }
};

// One hard hit of the car at (y, z) of the panel, dispatched at once.
void Hit(common::WorldFixture& ioFixture, int inHit)
{
    REQUIRE(ioFixture.mWorld.SetBodyState(ioFixture.mCar, ioFixture.CarState(40.0)));
    const double y = -0.6 + 0.4 * (inHit % 4), z = 0.6 - 0.4 * (inHit / 4);
    REQUIRE(ioFixture.mWorld.SubmitContacts(std::vector<ContactEvent>{ioFixture.FrontContact(y, z, 0.2 * inHit),
                                                                      ioFixture.FrontContact(y + 0.1, z - 0.1, 0.2 * inHit)}));
    ioFixture.mWorld.Flush();
}

} // namespace

TEST_CASE("HeldPropBodies: the struck members' velocity, loose pieces as bodies with their FEM mass, the shape "
          "that follows, and no engine call for a prop at rest",
          "[props]")
{
    common::WorldFixture fixture;
    std::unique_ptr<PropWorld> props = PropWorld::Create(fixture.mWorld, {.mContactMass = true}).Get();
    const PropId wall = props->AddProp(fixture.mWall, test::WeakPanel()).Get();
    CountingEngine engine(fixture.mWorld);
    HeldPropBodies held = HeldPropBodies::Create(*props, engine.Calls(), {.mShapeCellSize = 0.5, .mShapeTolerance = 0.005, .mMinPieceMass = 0.0}).Get();

    // The first update gives the prop's shape, whatever the step did.
    HeldPropUpdate update;
    REQUIRE(held.Update(props->Step(1.0 / 120.0).Get(), update).IsValid());
    REQUIRE(engine.mShapes.size() == 1u);
    CHECK(update.mShapesGiven == 1);
    CHECK(engine.mShapes[0] == props->GetCollisionPieces(wall, 0.5).Get());

    // Hard hits until pieces leave; after every step the engine learns what the FEM did.
    int pieces = 0;
    int masses_seen = 0;
    for (int hit = 0; hit < 12 && pieces == 0; ++hit)
    {
        Hit(fixture, hit);
        for (int step = 0; step < 10; ++step)
        {
            const PropStepReport stepped = props->Step(1.0 / 120.0).Get();
            const std::size_t shapes_before = engine.mShapes.size();
            REQUIRE(held.Update(stepped, update).IsValid());
            // The held body moves as the struck members do, given after every step the prop moved.
            if (stepped.mStepped == 1)
            {
                REQUIRE(update.mVelocitiesGiven == 1);
                CHECK(engine.mVelocities.back() == props->GetContactVelocity(wall));
                // ... and weighs what they weigh over a step (none once the struck nodes left with a piece),
                // given when it changed
                CHECK((props->GetContactMass(wall) > 0.0) == !props->GetContactVelocity(wall).isZero(0.0));
                if (!engine.mMasses.empty())
                    CHECK(engine.mMasses.back() == props->GetContactMass(wall));
                CHECK(update.mMassesGiven <= 1);
                masses_seen += props->GetContactMass(wall) > 0.0 ? 1 : 0;
            }
            const FemProp& prop = *props->GetProp(wall);
            for (const HeldPiece& piece : update.mPieces)
            {
                ++pieces;
                REQUIRE(piece.mBody.IsValid());
                // The body has the piece's FEM mass: its nodes' lumped masses (no node is shared between pieces).
                double mass = 0.0;
                for (int node : piece.mPiece.mNodes)
                    mass += prop.GetMasses()[static_cast<std::size_t>(node)];
                const ConvexBodySettings& body = engine.BodyMade(piece.mBody);
                CHECK(fixture.mWorld.IsQuiet(piece.mBody)); // HeldPropSettings::mQuietPieces' default
                CHECK(body.mMass == Approx(mass).epsilon(1e-9));
                CHECK(body.mMass == piece.mPiece.mRigidBody.mBody.mMass);
            }
            // Pieces that left change the shape: a new one goes to the engine in the same update.
            if (!update.mPieces.empty())
                CHECK(engine.mShapes.size() == shapes_before + 1);
            CHECK(update.mShapesGiven == static_cast<int>(engine.mShapes.size() - shapes_before));
        }
    }
    REQUIRE(pieces > 0); // the hits knocked pieces out: the checks above ran
    REQUIRE(masses_seen > 0);
    // The engine's shape is the prop's without the pieces that left (its points follow to the tolerance).
    CHECK(engine.mShapes.back().size() == props->GetCollisionPieces(wall, 0.5).Get().size());

    // Left alone, the panel falls asleep (the update gives zero once), and from then on costs no engine call.
    bool asleep = false;
    for (int step = 0; step < 4000 && !asleep; ++step)
    {
        const PropStepReport stepped = props->Step(1.0 / 120.0).Get();
        REQUIRE(held.Update(stepped, update).IsValid());
        asleep = stepped.mStepped == 0;
    }
    REQUIRE(asleep);
    CHECK(engine.mVelocities.back() == Vec3::Zero());
    CHECK(engine.mMasses.back() == 0.0); // its own mass again
    const std::size_t calls = engine.CallCount();
    for (int step = 0; step < 100; ++step)
    {
        const PropStepReport stepped = props->Step(1.0 / 120.0).Get();
        REQUIRE(stepped.mSleeping == 1);
        REQUIRE(held.Update(stepped, update).IsValid());
        CHECK(update.mPieces.empty());
        CHECK(update.mShapesGiven + update.mVelocitiesGiven + update.mMassesGiven == 0);
    }
    CHECK(engine.CallCount() == calls);
}

TEST_CASE("HeldPropBodies refuses missing engine calls and bad settings, an engine that refuses a piece gets "
          "the rest done and the refusal back",
          "[props]")
{
    common::WorldFixture fixture;
    std::unique_ptr<PropWorld> props = PropWorld::Create(fixture.mWorld, {.mContactMass = true}).Get();
    const PropId wall = props->AddProp(fixture.mWall, test::WeakPanel()).Get();
    CountingEngine engine(fixture.mWorld);

    HeldPropEngine no_bodies = engine.Calls();
    no_bodies.mCreatePieceBody = nullptr;
    CHECK(HeldPropBodies::Create(*props, no_bodies).GetError().mCode == EError::InvalidArgument);
    HeldPropEngine no_shapes = engine.Calls();
    no_shapes.mSetPropPieces = nullptr;
    CHECK(HeldPropBodies::Create(*props, no_shapes).GetError().mCode == EError::InvalidArgument);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    CHECK_FALSE(HeldPropBodies::Create(*props, engine.Calls(), {.mShapeCellSize = 0.0}).IsValid());
    CHECK_FALSE(HeldPropBodies::Create(*props, engine.Calls(), {.mShapeCellSize = nan}).IsValid());
    CHECK_FALSE(HeldPropBodies::Create(*props, engine.Calls(), {.mShapeTolerance = -0.01}).IsValid());
    CHECK_FALSE(HeldPropBodies::Create(*props, engine.Calls(), {.mMinPieceMass = -1.0}).IsValid());
    CHECK_FALSE(HeldPropBodies::Create(*props, engine.Calls(), {.mMinPieceMass = std::numeric_limits<double>::infinity()}).IsValid());
    // A contact mass needs a world that works it out.
    {
        common::WorldFixture other;
        std::unique_ptr<PropWorld> plain = PropWorld::Create(other.mWorld).Get();
        CHECK(HeldPropBodies::Create(*plain, engine.Calls()).GetError().mCode == EError::InvalidArgument);
        HeldPropEngine no_mass = engine.Calls();
        no_mass.mSetHeldMass = nullptr;
        CHECK(HeldPropBodies::Create(*plain, no_mass).IsValid());
    }
    CHECK(engine.CallCount() == 0u);

    // Without SetHeldVelocity the held body is put back at rest: no velocity is ever given.
    HeldPropEngine at_rest = engine.Calls();
    at_rest.mSetHeldVelocity = nullptr;
    HeldPropBodies held = HeldPropBodies::Create(*props, at_rest, {.mMinPieceMass = 0.0}).Get();
    engine.mRefuseBodies = true;
    HeldPropUpdate update;
    bool refused = false;
    for (int hit = 0; hit < 12 && !refused; ++hit)
    {
        Hit(fixture, hit);
        for (int step = 0; step < 10 && !refused; ++step)
        {
            const std::size_t shapes_before = engine.mShapes.size();
            const Status status = held.Update(props->Step(1.0 / 120.0).Get(), update);
            if (update.mPieces.empty())
            {
                REQUIRE(status.IsValid());
                continue;
            }
            refused = true;
            REQUIRE_FALSE(status.IsValid());
            CHECK(status.GetError().mMessage == "the engine refused the piece");
            for (const HeldPiece& piece : update.mPieces)
                CHECK_FALSE(piece.mBody.IsValid());
            // The pieces left the prop all the same (their nodes fixed), and the new shape went to the engine.
            for (const HeldPiece& piece : update.mPieces)
                for (int node : piece.mPiece.mNodes)
                    CHECK(props->GetProp(wall)->GetCpuSolver()->GetInverseMasses()[static_cast<std::size_t>(node)] == 0.0);
            CHECK(engine.mShapes.size() == shapes_before + 1);
        }
    }
    REQUIRE(refused);
    CHECK(engine.mVelocities.empty());
    CHECK(engine.mBodies.empty());
}

TEST_CASE("HeldPropBodies gives a shape the engine refused again at the next update, even at rest", "[props]")
{
    common::WorldFixture fixture;
    std::unique_ptr<PropWorld> props = PropWorld::Create(fixture.mWorld, {.mContactMass = true}).Get();
    const PropId wall = props->AddProp(fixture.mWall, test::WeakPanel()).Get();
    CountingEngine engine(fixture.mWorld);
    HeldPropBodies held = HeldPropBodies::Create(*props, engine.Calls()).Get();
    engine.mRefuseShapes = true;
    HeldPropUpdate update;
    const PropStepReport first = props->Step(1.0 / 120.0).Get();
    CHECK(first.mStepped == 0); // at rest without gravity: asleep from its first step
    CHECK(held.Update(first, update).GetError().mMessage == "the engine refused the shape");
    CHECK(engine.mShapes.empty());

    // Nothing moved since, yet the refused shape goes again; once taken, it is not given again.
    engine.mRefuseShapes = false;
    REQUIRE(held.Update(props->Step(1.0 / 120.0).Get(), update).IsValid());
    CHECK(update.mShapesGiven == 1);
    REQUIRE(engine.mShapes.size() == 1u);
    CHECK(engine.mShapes[0] == props->GetCollisionPieces(wall, HeldPropSettings{}.mShapeCellSize).Get());
    REQUIRE(held.Update(props->Step(1.0 / 120.0).Get(), update).IsValid());
    CHECK(update.mShapesGiven == 0);
    CHECK(engine.mShapes.size() == 1u);
}

TEST_CASE("HeldPropBodies gives held velocities to held props only (mIsHeld), and shapes to every prop", "[props]")
{
    // The wall's prop is held; a second prop on the floor body stands for a free crate the engine moves.
    common::WorldFixture fixture;
    std::unique_ptr<PropWorld> props = PropWorld::Create(fixture.mWorld, {.mContactMass = true}).Get();
    const PropId wall = props->AddProp(fixture.mWall, test::WeakPanel()).Get();
    const PropId crate = props->AddProp(fixture.mFloor, test::WeakPanel()).Get();
    CountingEngine engine(fixture.mWorld);
    HeldPropEngine calls = engine.Calls();
    calls.mIsHeld = [&](BodyId inBody) { return inBody == fixture.mWall; };
    HeldPropBodies held = HeldPropBodies::Create(*props, std::move(calls), {.mShapeCellSize = 0.5}).Get();

    HeldPropUpdate update;
    REQUIRE(held.Update(props->Step(1.0 / 120.0).Get(), update).IsValid());
    CHECK(update.mShapesGiven == 2); // both props' first shapes
    // Both struck: only the held wall's body takes the struck members' velocity.
    REQUIRE(props->GetProp(crate)->ApplyImpulse(0, Vec3(0.0, 0.0, 0.5)).IsValid());
    Hit(fixture, 5);
    for (int step = 0; step < 5; ++step)
        REQUIRE(held.Update(props->Step(1.0 / 120.0).Get(), update).IsValid());
    REQUIRE_FALSE(engine.mVelocityBodies.empty());
    for (const BodyId& body : engine.mVelocityBodies)
        CHECK(body == fixture.mWall);
    CHECK(engine.mVelocities.back() == props->GetContactVelocity(wall));
}

namespace
{

// A weak panel on the fixture's wall, its held bodies kept with inSettings by a counting engine whose piece
// bodies inCreateBody makes (none given: bodies of the fixture's world), hit hard until an Update hands
// pieces over: that Update's status and pieces.
std::pair<Status, std::vector<HeldPiece>>
PanelPieces(common::WorldFixture& ioFixture, const HeldPropSettings& inSettings,
            std::function<Result<BodyId>(const ConvexBodySettings&)> inCreateBody = nullptr)
{
    std::unique_ptr<PropWorld> props = PropWorld::Create(ioFixture.mWorld).Get();
    (void)props->AddProp(ioFixture.mWall, test::WeakPanel()).Get();
    CountingEngine engine(ioFixture.mWorld);
    HeldPropEngine calls = engine.Calls();
    calls.mSetHeldMass = nullptr;
    if (inCreateBody)
        calls.mCreatePieceBody = std::move(inCreateBody);
    HeldPropBodies held = HeldPropBodies::Create(*props, calls, inSettings).Get();
    HeldPropUpdate update;
    for (int hit = 0; hit < 12; ++hit)
    {
        Hit(ioFixture, hit);
        for (int step = 0; step < 10; ++step)
        {
            const Status status = held.Update(props->Step(1.0 / 120.0).Get(), update);
            if (!update.mPieces.empty())
                return {status, update.mPieces};
        }
    }
    return {Status::Ok(), {}};
}

} // namespace

TEST_CASE(
    "HeldPropBodies: pieces stay loud with mQuietPieces off, and a piece body the world does not know is "
    "kept, loud, with the refusal returned",
    "[props]")
{
    {
        common::WorldFixture fixture;
        const auto [status, pieces] = PanelPieces(fixture, {.mMinPieceMass = 0.0, .mQuietPieces = false});
        REQUIRE(status.IsValid());
        REQUIRE_FALSE(pieces.empty());
        for (const HeldPiece& piece : pieces)
        {
            REQUIRE(piece.mBody.IsValid());
            CHECK_FALSE(fixture.mWorld.IsQuiet(piece.mBody));
        }
    }
    {
        // The engine's bodies are numbered past the world's: SetQuiet refuses them.
        common::WorldFixture fixture;
        std::uint32_t made = 0;
        const auto [status, pieces] = PanelPieces(fixture, {.mMinPieceMass = 0.0},
                                                  [&](const ConvexBodySettings&) -> Result<BodyId> {
                                                      return BodyId{1000 + made++, 0};
                                                  });
        REQUIRE_FALSE(pieces.empty());
        CHECK(status.GetError().mCode == EError::OutOfRange);
        for (const HeldPiece& piece : pieces)
        {
            CHECK(piece.mBody.mValue >= 1000u);
            CHECK_FALSE(fixture.mWorld.IsQuiet(piece.mBody));
        }
    }
}
