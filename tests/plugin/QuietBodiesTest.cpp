// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "ThreadJobSystem.h"
#include "WorldFixture.h"

#include <catch2/catch.hpp>

#include <vector>

using namespace crumple;
using namespace crumple::plugin;
using crumple::common::WorldFixture;

namespace
{

struct CollisionList : DamageListener
{
    void OnCollision(const Collision& inCollision, std::span<const ObjectDent>) override
    {
        mCollisions.push_back(inCollision);
    }
    std::vector<Collision> mCollisions;
};

// A 2 kg piece of debris, a 0.4 m cube centred at (6, 0, 0.2), falling onto the fixture's floor at 3 m/s.
BodyState FallingPiece()
{
    BodyState piece;
    piece.mMass = 2.0;
    const double inertia = 2.0 * (0.4 * 0.4 + 0.4 * 0.4) / 12.0;
    piece.mInverseInertiaWorld = Mat3::Identity() / inertia;
    piece.mTransform.mTranslation = Vec3(6.0, 0.0, 0.2);
    piece.mCenterOfMass = Vec3(6.0, 0.0, 0.2);
    piece.mLinearVelocity = Vec3(0.0, 0.0, -3.0);
    return piece;
}

// Two of the piece's bottom corners touching the floor (normal from the floor up into the piece).
std::vector<ContactEvent> PieceOnFloor(BodyId inPiece, BodyId inFloor, double inTime)
{
    std::vector<ContactEvent> contacts;
    for (double y : {-0.2, 0.2})
    {
        ContactEvent contact;
        contact.mBodyA = inPiece;
        contact.mBodyB = inFloor;
        contact.mPointOnA = Vec3(6.0, y, -0.01);
        contact.mPointOnB = Vec3(6.0, y, 0.0);
        contact.mNormal = Vec3::UnitZ();
        contact.mPenetrationDepth = 0.01;
        contact.mTime = inTime;
        contacts.push_back(contact);
    }
    return contacts;
}

std::vector<ContactEvent> CarOnWall(const WorldFixture& inFixture, double inTime)
{
    return {inFixture.FrontContact(-0.8, -0.6, inTime), inFixture.FrontContact(0.8, 0.6, inTime)};
}

// One step of the car hitting the wall and the piece landing, in one submission with the piece's contacts
// around the car's; the collisions it dispatches. With inQuiet the floor, the wall and the piece are quiet.
std::vector<Collision> CarAndPiece(bool inQuiet, const DamageWorldSettings& inSettings = {})
{
    WorldFixture fixture(4000, {8, 6, 6}, inSettings);
    CollisionList listener;
    fixture.mWorld.AddListener(&listener);
    const BodyId piece = fixture.mWorld.CreateBody(FallingPiece()).Get();
    if (inQuiet)
        for (BodyId body : {fixture.mFloor, fixture.mWall, piece})
            REQUIRE(fixture.mWorld.SetQuiet(body, true));
    REQUIRE(fixture.mWorld.SetBodyState(fixture.mCar, fixture.CarState(10.0)));
    const std::vector<ContactEvent> landing = PieceOnFloor(piece, fixture.mFloor, 0.0);
    std::vector<ContactEvent> contacts{landing[0]};
    for (const ContactEvent& contact : CarOnWall(fixture, 0.0))
        contacts.push_back(contact);
    contacts.push_back(landing[1]);
    REQUIRE(fixture.mWorld.SubmitContacts(contacts, 1.0 / 120.0));
    fixture.mWorld.Flush();
    fixture.mWorld.RemoveListener(&listener);
    return listener.mCollisions;
}

} // namespace

TEST_CASE("Quiet bodies: contacts between two make no collision, those with a body that is not quiet are "
          "solved bit for bit as before",
          "[plugin]")
{
    const std::vector<Collision> heard = CarAndPiece(false);
    const std::vector<Collision> quiet = CarAndPiece(true);
    // Heard: the car's hit and the piece's landing. Quiet: the piece and the floor are both quiet, so only
    // the car's hit, whose wall is quiet but whose car is not.
    REQUIRE(heard.size() == 2);
    REQUIRE(quiet.size() == 1);
    const BodyId car = WorldFixture().mCar; // the same id in every fixture
    const auto of_car = [&](const Collision& inCollision)
    { return inCollision.mBodyA == car || inCollision.mBodyB == car; };
    REQUIRE(of_car(heard[0]) != of_car(heard[1]));
    const Collision& car_hit = of_car(heard[0]) ? heard[0] : heard[1];
    REQUIRE(quiet[0].mBodyA == car_hit.mBodyA);
    REQUIRE(quiet[0].mBodyB == car_hit.mBodyB);
    REQUIRE(quiet[0].mContacts.size() == car_hit.mContacts.size());
    for (std::size_t i = 0; i < car_hit.mContacts.size(); ++i)
    {
        CHECK(quiet[0].mContacts[i].mImpulse == car_hit.mContacts[i].mImpulse);
        CHECK(quiet[0].mContacts[i].mAbsorbedEnergy == car_hit.mContacts[i].mAbsorbedEnergy);
    }
    CHECK(quiet[0].mCrushEnergyA == car_hit.mCrushEnergyA);
    CHECK(quiet[0].mCrushEnergyB == car_hit.mCrushEnergyB);

    // With the impulses solved on the dents' task (the quiet contacts are dropped before they wait for it):
    // the same one collision, the same bits.
    const common::ThreadJobSystem jobs(2);
    DamageWorldSettings deferred;
    deferred.mJobs = &jobs.Get();
    deferred.mDeferDents = true;
    deferred.mDeferImpulses = true;
    const std::vector<Collision> quiet_deferred = CarAndPiece(true, deferred);
    REQUIRE(quiet_deferred.size() == 1);
    REQUIRE(quiet_deferred[0].mContacts.size() == car_hit.mContacts.size());
    for (std::size_t i = 0; i < car_hit.mContacts.size(); ++i)
        CHECK(quiet_deferred[0].mContacts[i].mImpulse == car_hit.mContacts[i].mImpulse);
}

TEST_CASE("Quiet bodies: a step of quiet pairs only does nothing, and quietness is per live body", "[plugin]")
{
    WorldFixture fixture;
    CollisionList listener;
    fixture.mWorld.AddListener(&listener);
    CHECK_FALSE(fixture.mWorld.IsQuiet(fixture.mFloor)); // off at first
    const BodyId piece = fixture.mWorld.CreateBody(FallingPiece()).Get();
    REQUIRE(fixture.mWorld.SetQuiet(piece, true));
    REQUIRE(fixture.mWorld.SetQuiet(fixture.mFloor, true));
    CHECK(fixture.mWorld.IsQuiet(piece));
    REQUIRE(fixture.mWorld.SubmitContacts(PieceOnFloor(piece, fixture.mFloor, 0.0), 1.0 / 120.0));
    const UpdateReport report = fixture.mWorld.Flush();
    CHECK(report.mCollisionsDispatched == 0);
    CHECK(listener.mCollisions.empty());

    // A bad contact among quiet ones is still refused: validation comes first.
    std::vector<ContactEvent> bad = PieceOnFloor(piece, fixture.mFloor, 1.0);
    bad[1].mNormal = Vec3(0.0, 0.0, 2.0);
    CHECK(fixture.mWorld.SubmitContacts(bad, 1.0 / 120.0).HasError());

    // Loud again: the landing is a collision.
    REQUIRE(fixture.mWorld.SetQuiet(piece, false));
    REQUIRE(fixture.mWorld.SubmitContacts(PieceOnFloor(piece, fixture.mFloor, 2.0), 1.0 / 120.0));
    fixture.mWorld.Flush();
    CHECK(listener.mCollisions.size() == 1);

    // Refused for a body that does not exist; a removed body's slot comes back loud.
    CHECK(fixture.mWorld.SetQuiet(BodyId{99}, true).GetError().mCode == EError::OutOfRange);
    CHECK_FALSE(fixture.mWorld.IsQuiet(BodyId{99}));
    REQUIRE(fixture.mWorld.SetQuiet(piece, true));
    REQUIRE(fixture.mWorld.RemoveBody(piece));
    CHECK_FALSE(fixture.mWorld.IsQuiet(piece));
    CHECK(fixture.mWorld.SetQuiet(piece, true).GetError().mCode == EError::OutOfRange);
    const BodyId again = fixture.mWorld.CreateBody(FallingPiece()).Get();
    REQUIRE(again.mValue == piece.mValue);
    CHECK_FALSE(fixture.mWorld.IsQuiet(again));
    REQUIRE(fixture.mWorld.SubmitContacts(PieceOnFloor(again, fixture.mFloor, 3.0), 1.0 / 120.0));
    fixture.mWorld.Flush();
    CHECK(listener.mCollisions.size() == 2);
    fixture.mWorld.RemoveListener(&listener);
}
