// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// Collision -> nodal impulses: the total impulse and its moment are kept, the prop's side of the collision
// decides the sign, bad collisions change nothing, and a collision dispatched by a DamageWorld reaches a prop.
#include "PropMomentum.h"
#include "WallPanelMesh.h"
#include "WorldFixture.h"

#include <crumple/props/CollisionImpulses.h>
#include <crumple/fem/TetSolver.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace crumple;
using namespace crumple::fem;
using namespace crumple::plugin;
using namespace crumple::props;

namespace
{

// A free 2 m x 0.2 m x 2 m wall panel, x in [0, 0.2], y and z in [-1, 1] (the prop's body frame).
TetSolver Panel(double inDensity = FemMaterialSettings{}.mDensity)
{
    TetSolverSettings settings;
    settings.mGravity = Vec3::Zero();
    FemMaterialSettings material;
    material.mDensity = inDensity;
    return TetSolver::Create(test::WallPanelMesh({1, 10, 10}), material, settings).Get();
}

Collision TwoContacts(BodyId inA, BodyId inB)
{
    Collision collision;
    collision.mBodyA = inA;
    collision.mBodyB = inB;
    for (const Vec3& point : {Vec3(0.05, 0.33, -0.21), Vec3(0.0, -0.5, 0.7)}) // inside, and on the face x = 0
    {
        CollisionContact contact;
        contact.mLocalPointOnA = point;
        contact.mLocalPointOnB = point + Vec3(1.0, 2.0, 3.0);
        contact.mLocalNormalOnA = Vec3(1.0, 0.2, -0.1).normalized();
        contact.mLocalNormalOnB = Vec3(-1.0, 0.0, 0.0);
        contact.mImpulse = 250.0;
        collision.mContacts.push_back(contact);
    }
    return collision;
}

} // namespace

TEST_CASE("CollisionNodalImpulses keeps each contact's impulse and its moment", "[props]")
{
    const TetSolver panel = Panel();
    const Collision collision = TwoContacts(BodyId{3}, BodyId{7});
    const Result<std::vector<NodalImpulse>> impulses =
        CollisionNodalImpulses(collision, BodyId{3}, panel.GetElementNodes(), panel.GetPositions());
    REQUIRE(impulses.IsValid());
    REQUIRE(impulses.Get().size() == 8u);
    for (std::size_t contact = 0; contact < 2; ++contact)
    {
        const Vec3 expected = 250.0 * collision.mContacts[contact].mLocalNormalOnA;
        const Vec3 point = collision.mContacts[contact].mLocalPointOnA;
        Vec3 total = Vec3::Zero(), moment = Vec3::Zero(), expected_moment = point.cross(expected);
        for (std::size_t corner = 0; corner < 4; ++corner)
        {
            const NodalImpulse& impulse = impulses.Get()[4 * contact + corner];
            total += impulse.mImpulse;
            moment += panel.GetPositions()[impulse.mNode].cross(impulse.mImpulse);
        }
        CHECK((total - expected).norm() < 1e-12 * expected.norm());
        CHECK((moment - expected_moment).norm() < 1e-12 * 250.0);
    }

    // As body B the prop takes -j n in its own frame.
    const Result<std::vector<NodalImpulse>> as_b =
        CollisionNodalImpulses(TwoContacts(BodyId{1}, BodyId{3}), BodyId{3}, panel.GetElementNodes(), panel.GetPositions());
    REQUIRE(as_b.IsValid());
    Vec3 total = Vec3::Zero();
    for (const NodalImpulse& impulse : as_b.Get())
        total += impulse.mImpulse;
    CHECK((total - Vec3(500.0, 0.0, 0.0)).norm() < 1e-12 * 500.0);
}

TEST_CASE("ApplyCollision refuses a collision the prop is not in, or a NaN contact, and changes nothing", "[props]")
{
    TetSolver panel = Panel();
    const std::vector<Vec3> velocities = panel.GetVelocities();
    const Status stranger = ApplyCollision(panel, TwoContacts(BodyId{1}, BodyId{2}), BodyId{3});
    CHECK(stranger.HasError());
    Collision broken = TwoContacts(BodyId{3}, BodyId{4});
    broken.mContacts[1].mImpulse = std::numeric_limits<double>::quiet_NaN();
    const Status nan = ApplyCollision(panel, broken, BodyId{3});
    REQUIRE(nan.HasError());
    CHECK(nan.GetError().mMessage.find("contact 1") != std::string::npos);
    CHECK(panel.GetVelocities() == velocities);
}

TEST_CASE("Nodal impulses refuse an element naming a node that is not there, and an impulse no velocity holds, "
          "changing nothing",
          "[props]")
{
    TetSolver panel = Panel();
    const std::vector<Vec3> velocities = panel.GetVelocities();
    std::vector<TetIndices> elements = panel.GetElementNodes();
    elements[3][2] = 100000000;
    const Result<std::vector<NodalImpulse>> outside =
        CollisionNodalImpulses(TwoContacts(BodyId{3}, BodyId{7}), BodyId{3}, elements, panel.GetPositions());
    REQUIRE(outside.HasError());
    CHECK(outside.GetError().mCode == EError::OutOfRange);

    // Finite impulses that overflow a light node's velocity (grams at 1 kg/m^3): refused whole, before any lands.
    panel = Panel(1.0);
    Collision huge = TwoContacts(BodyId{3}, BodyId{7});
    huge.mContacts[1].mImpulse = 1.0e308;
    const Status refused = ApplyCollision(panel, huge, BodyId{3});
    REQUIRE(refused.HasError());
    CHECK(refused.GetError().mCode == EError::NonFinite);
    CHECK(panel.GetVelocities() == velocities);
    CHECK(panel.ApplyImpulse(0, Vec3(1.0e308, 0.0, 0.0)).GetError().mCode == EError::NonFinite);
    CHECK(panel.GetVelocities() == velocities);
}

TEST_CASE(
    "Nodal impulses that pass a node's velocity limit on the way are refused whole, even if the last pulls "
    "it back",
    "[props]")
{
    // Three contacts on one node, each 0.6e100 m/s of its velocity: +x, +x, then -x. The sum (0.6e100 m/s) is
    // within the solver's 1e100 m/s, the second step (1.2e100) is not, and the solver refuses that impulse
    // once the first has landed: found by a bad-input audit, where node 1 was left at 6e99 m/s.
    TetSolver panel = Panel();
    const std::vector<Vec3> velocities = panel.GetVelocities();
    const int node = 1;
    const double mass = 1.0 / panel.GetInverseMasses()[node];
    Collision pushes;
    pushes.mBodyA = BodyId{3};
    pushes.mBodyB = BodyId{7};
    for (const double sign : {1.0, 1.0, -1.0})
    {
        CollisionContact contact;
        contact.mLocalPointOnA = panel.GetPositions()[node];
        contact.mLocalNormalOnA = sign * Vec3::UnitX();
        contact.mImpulse = 0.6e100 * mass;
        pushes.mContacts.push_back(contact);
    }
    const Result<std::vector<NodalImpulse>> impulses =
        CollisionNodalImpulses(pushes, BodyId{3}, panel.GetElementNodes(), panel.GetPositions());
    REQUIRE(impulses);
    const Status checked = CheckNodalImpulses(impulses.Get(), panel.GetVelocities(), panel.GetInverseMasses(),
                                              TetSolver::cMaxStateMagnitude);
    CHECK(checked.HasError());
    const Status refused = ApplyCollision(panel, pushes, BodyId{3});
    REQUIRE(refused.HasError());
    CHECK(refused.GetError().mCode == EError::OutOfRange);
    CHECK(panel.GetVelocities() == velocities);
}

TEST_CASE("A collision dispatched by a DamageWorld moves a free prop by exactly its impulse", "[props]")
{
    // The fixture's car hits its static wall; a listener hands the wall's side of every collision to a FEM
    // panel standing in for the wall (same body frame). A free panel takes all of it as momentum.
    struct PropListener : DamageListener
    {
        TetSolver* mProp = nullptr;
        BodyId mBody;
        double mTotal = 0.0;
        void OnCollision(const Collision& inCollision, std::span<const ObjectDent>) override
        {
            REQUIRE(ApplyCollision(*mProp, inCollision, mBody).IsValid());
            mTotal += inCollision.TotalImpulse();
        }
    };
    common::WorldFixture fixture;
    TetSolver panel = Panel();
    PropListener listener;
    listener.mProp = &panel;
    listener.mBody = fixture.mWall;
    fixture.mWorld.AddListener(&listener);

    REQUIRE(fixture.mWorld.SetBodyState(fixture.mCar, fixture.CarState(15.0)));
    REQUIRE(fixture.mWorld.SubmitContacts(std::vector<ContactEvent>{fixture.FrontContact(0.3, 0.2, 0.0),
                                                                    fixture.FrontContact(-0.4, -0.1, 0.0)}));
    fixture.mWorld.Flush();
    REQUIRE(listener.mTotal > 0.0);
    // The car pushes the wall along +x with the collision's total impulse.
    CHECK((test::PropMomentum(panel) - Vec3(listener.mTotal, 0.0, 0.0)).norm() < 1e-9 * listener.mTotal);
}
