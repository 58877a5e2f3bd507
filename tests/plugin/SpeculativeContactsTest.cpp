// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "WorldFixture.h"

#include <catch2/catch.hpp>

#include <vector>

using namespace crumple;
using namespace crumple::plugin;
using crumple::common::WorldFixture;

namespace
{

struct ImpulseListener : DamageListener
{
    void OnCollision(const Collision& inCollision, std::span<const ObjectDent>) override
    {
        mImpulse += inCollision.TotalImpulse();
        mEnergy += inCollision.mCrushEnergyA + inCollision.mCrushEnergyB;
        ++mCollisions;
    }
    double mImpulse = 0.0;
    double mEnergy = 0.0;
    int mCollisions = 0;
};

struct GapHit
{
    double mImpulse = 0.0; ///< N s, all collisions
    double mEnergy = 0.0;  ///< J, the crush energy of both sides
    int mCollisions = 0;
};

// The fixture's car at inSpeed, its front's four corners reported inGap (m) before the wall in one step of
// inStep (s).
GapHit HitFromGap(ESpeculativeContacts inModel, double inSpeed, double inGap, double inStep)
{
    DamageWorldSettings settings;
    settings.mSpeculativeContacts = inModel;
    WorldFixture fixture(2000, {8, 6, 6}, settings);
    ImpulseListener listener;
    fixture.mWorld.AddListener(&listener);
    REQUIRE(fixture.mWorld.SetBodyState(fixture.mCar, fixture.CarState(inSpeed)));
    std::vector<ContactEvent> contacts;
    for (double y : {-0.8, 0.8})
        for (double z : {-0.6, 0.6})
            contacts.push_back(fixture.FrontContact(y, z, inStep, -inGap));
    REQUIRE(fixture.mWorld.SubmitContacts(contacts, inStep));
    fixture.mWorld.Flush();
    return {listener.mImpulse, listener.mEnergy, listener.mCollisions};
}

} // namespace

// A car at v = 6 m/s whose front is reported g = 1 cm before the wall in a step of 1/100 s: the gap stands
// for s = g / dt = 1 m/s of its approach. An engine that stops it at the surface (Bullet) takes m (1 + e) (v
// - s) in this step and the rest with the next contact; one that resolves the predicted hit whole (Jolt,
// Box2D) takes m (1 + e) v now. A gap the approach does not close within the step is no hit under either.
TEST_CASE("A hit predicted from a gap is resolved as the engine's speculative contacts resolve it",
          "[plugin]")
{
    const double mass = 1200.0, e = DamageWorldSettings{}.mRestitution, dt = 0.01, gap = 0.01, s = gap / dt;
    for (double v : {6.0, 20.0})
    {
        INFO("approach " << v << " m/s");
        const GapHit stop = HitFromGap(ESpeculativeContacts::StopAtSurface, v, gap, dt);
        const GapHit whole = HitFromGap(ESpeculativeContacts::ResolveWhole, v, gap, dt);
        REQUIRE(stop.mCollisions == 1);
        REQUIRE(whole.mCollisions == 1);
        CHECK(stop.mImpulse == Approx(mass * (1.0 + e) * (v - s)).epsilon(1.0e-9));
        CHECK(whole.mImpulse == Approx(mass * (1.0 + e) * v).epsilon(1.0e-9));
        // The energy each leaves the pair with: a whole hit the kinetic energy the rebound does not give
        // back, (1 - e^2) m v^2 / 2; the stopped one J ((1 - e) v + (1 + e) s) / 2
        CHECK(whole.mEnergy == Approx(0.5 * (1.0 - e * e) * mass * v * v).epsilon(1.0e-9));
        CHECK(stop.mEnergy == Approx(0.5 * stop.mImpulse * ((1.0 - e) * v + (1.0 + e) * s)).epsilon(1.0e-9));
    }
    // 0.8 m/s does not close 1 cm in 1/100 s: no impulse, no collision, under either.
    for (ESpeculativeContacts model :
         {ESpeculativeContacts::StopAtSurface, ESpeculativeContacts::ResolveWhole})
    {
        const GapHit none = HitFromGap(model, 0.8, gap, dt);
        CHECK(none.mCollisions == 0);
        CHECK(none.mImpulse == 0.0);
    }
    // Touching contacts (no gap) are the same under both.
    CHECK(HitFromGap(ESpeculativeContacts::StopAtSurface, 6.0, 0.0, dt).mImpulse ==
          HitFromGap(ESpeculativeContacts::ResolveWhole, 6.0, 0.0, dt).mImpulse);
}

TEST_CASE("DamageWorld refuses a speculative-contact model that is not an ESpeculativeContacts value",
          "[plugin]")
{
    DamageWorldSettings settings;
    settings.mSpeculativeContacts = static_cast<ESpeculativeContacts>(7);
    const auto world = DamageWorld::Create(settings);
    REQUIRE_FALSE(world);
    CHECK(world.GetError().mCode == EError::InvalidArgument);
    CHECK(world.GetError().mMessage.find("mSpeculativeContacts") != std::string::npos);
}
