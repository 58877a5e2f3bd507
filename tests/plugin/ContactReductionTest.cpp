// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "WorldFixture.h"

#include <crumple/plugin/ContactReduction.h>

#include <catch2/catch.hpp>

#include <algorithm>

using namespace crumple;
using namespace crumple::plugin;
using crumple::common::WorldFixture;

namespace
{

// An n x n grid of contacts over the car's front face (y, z in [-0.8, 0.8] x [-0.6, 0.6]), one deeper.
std::vector<ContactEvent> FrontGrid(const WorldFixture& inFixture, int inSide)
{
    std::vector<ContactEvent> contacts;
    for (int i = 0; i < inSide; ++i)
        for (int k = 0; k < inSide; ++k)
        {
            const double y = -0.8 + 1.6 * i / (inSide - 1), z = -0.6 + 1.2 * k / (inSide - 1);
            contacts.push_back(inFixture.FrontContact(y, z, 0.0, i == inSide / 3 && k == inSide / 2 ? 0.05 : 0.01));
        }
    return contacts;
}

} // namespace

TEST_CASE("Contact reduction keeps the patch's extremes and the deepest point, deterministically", "[plugin]")
{
    WorldFixture fixture;
    std::vector<CollisionContact> contacts;
    for (const ContactEvent& event : FrontGrid(fixture, 40))
    {
        CollisionContact c;
        c.mPointOnA = event.mPointOnA;
        c.mPointOnB = event.mPointOnB;
        c.mNormal = event.mNormal;
        c.mPenetrationDepth = event.mPenetrationDepth;
        contacts.push_back(c);
    }
    const std::vector<CollisionContact> reduced = ReduceContacts(contacts, 16);
    REQUIRE(reduced.size() == 16);
    CHECK(ReduceContacts(contacts, 16).size() == reduced.size());
    for (std::size_t i = 0; i < reduced.size(); ++i)
        CHECK(reduced[i].mPointOnA == ReduceContacts(contacts, 16)[i].mPointOnA);
    // The four corners of the face (the extremes along the diagonals) and the deepest contact are kept.
    auto has = [&](double inY, double inZ) {
        return std::any_of(reduced.begin(), reduced.end(), [&](const CollisionContact& c) {
            return std::abs(c.mPointOnA.y() - inY) < 1.0e-9 && std::abs(c.mPointOnA.z() - inZ) < 1.0e-9;
        });
    };
    CHECK(has(-0.8, -0.6));
    CHECK(has(0.8, 0.6));
    CHECK(has(-0.8, 0.6));
    CHECK(has(0.8, -0.6));
    CHECK(std::any_of(reduced.begin(), reduced.end(), [](const CollisionContact& c) { return c.mPenetrationDepth == 0.05; }));
    // Small sets come back unchanged.
    contacts.resize(12);
    CHECK(ReduceContacts(contacts, 16).size() == 12);
}

TEST_CASE("A huge manifold costs linear time and keeps the impulse of the whole face", "[plugin]")
{
    // 10,000 contacts of one pair in one step (a mesh-mesh contact): reduced to 16 before the cubic solve,
    // the impulse is still (1 + e) m v, as with the four corners.
    WorldFixture fixture;
    REQUIRE(fixture.mWorld.SetBodyState(fixture.mCar, fixture.CarState(15.0)));
    const std::vector<ContactEvent> contacts = FrontGrid(fixture, 100);
    REQUIRE(fixture.mWorld.SubmitContacts(contacts)); // unreduced, 4,000 took 19.5 s (crumple-bench --only impulse)
    struct Listener : DamageListener
    {
        void OnCollision(const Collision& inCollision, std::span<const ObjectDent>) override { mImpulse += inCollision.TotalImpulse(); mContacts += inCollision.mContacts.size(); }
        double mImpulse = 0.0;
        std::size_t mContacts = 0;
    } listener;
    fixture.mWorld.AddListener(&listener);
    fixture.mWorld.Flush();
    const double e = fixture.mWorld.GetSettings().mRestitution;
    CHECK(listener.mContacts <= fixture.mWorld.GetSettings().mMaxContactsPerPair);
    CHECK(listener.mImpulse == Approx((1.0 + e) * fixture.mMass * 15.0).epsilon(1.0e-6));
}

TEST_CASE("Reducing a large manifold never drops its only closing contact", "[plugin]")
{
    // A car sliding at 10 m/s over 100 resting ground contacts hits a rock of the same ground body: the one
    // contact that closes must survive the reduction (the resting ones take no impulse anyway).
    WorldFixture fixture;
    REQUIRE(fixture.mWorld.SetBodyState(fixture.mCar, fixture.CarState(10.0)));
    std::vector<ContactEvent> contacts;
    for (int i = 0; i < 10; ++i)
        for (int k = 0; k < 10; ++k)
        {
            ContactEvent contact;
            contact.mBodyA = fixture.mCar;
            contact.mBodyB = fixture.mFloor;
            contact.mPointOnA = contact.mPointOnB = Vec3(-4.0 + 3.8 * i / 9.0, -0.8 + 1.6 * k / 9.0, -0.7);
            contact.mNormal = Vec3::UnitZ();
            contact.mPenetrationDepth = 0.02; // deeper than the rock: depth alone would not pick it
            contacts.push_back(contact);
        }
    ContactEvent rock;
    rock.mBodyA = fixture.mCar;
    rock.mBodyB = fixture.mFloor;
    rock.mPointOnA = rock.mPointOnB = Vec3(-0.9, 0.75, -0.7);
    rock.mNormal = Vec3(-1.0, 0.0, 1.0).normalized();
    rock.mPenetrationDepth = 0.005;
    contacts.insert(contacts.begin() + 57, rock);
    struct Listener : DamageListener
    {
        void OnCollision(const Collision& inCollision, std::span<const ObjectDent>) override { mImpulse += inCollision.TotalImpulse(); }
        double mImpulse = 0.0;
    } listener;
    fixture.mWorld.AddListener(&listener);
    REQUIRE(fixture.mWorld.SubmitContacts(contacts));
    fixture.mWorld.Flush();
    CHECK(listener.mImpulse > 0.0);
}
