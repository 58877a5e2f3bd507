// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/plugin/CollisionGrouper.h>

#include <catch2/catch.hpp>

#include <limits>

using namespace crumple;
using namespace crumple::plugin;

namespace
{

CollisionContact At(double inTime, const Vec3& inLocalOnA, double inImpulse = 1.0)
{
    CollisionContact contact;
    contact.mTime = inTime;
    contact.mLocalPointOnA = inLocalOnA;
    contact.mImpulse = inImpulse;
    return contact;
}

void Add(CollisionGrouper& ioGrouper, BodyId inA, BodyId inB, const CollisionContact& inContact)
{
    ioGrouper.Add(inA, inB, std::span(&inContact, 1));
}

} // namespace

TEST_CASE("Contacts within the window and distance form one collision", "[plugin]")
{
    CollisionGrouper grouper = CollisionGrouper::Create({0.05, 0.5}).Get();
    const BodyId a{0}, b{1};
    Add(grouper, a, b, At(0.000, Vec3(2.0, 0.0, 0.0)));
    Add(grouper, a, b, At(0.016, Vec3(2.0, 0.3, 0.0)));
    Add(grouper, a, b, At(0.033, Vec3(2.0, 0.6, 0.0))); // chained: near the second contact
    Add(grouper, a, b, At(0.040, Vec3(-2.0, 0.0, 0.0))); // far away: its own collision
    Add(grouper, a, b, At(0.070, Vec3(2.0, 0.0, 0.0))); // after the window: a new collision
    CHECK(grouper.GetOpenCount() == 3);

    CHECK(grouper.TakeClosed(0.049).empty());
    const std::vector<Collision> first = grouper.TakeClosed(0.05);
    REQUIRE(first.size() == 1);
    CHECK(first[0].mContacts.size() == 3);
    CHECK(first[0].mStartTime == 0.0);
    CHECK(first[0].mEndTime == 0.033);
    CHECK(first[0].TotalImpulse() == 3.0);
    CHECK(grouper.TakeClosed(1.0).size() == 2);
    CHECK_FALSE(grouper.HasOpen());
}

TEST_CASE("Collisions come out in deterministic order", "[plugin]")
{
    CollisionGrouper grouper = CollisionGrouper::Create({}).Get();
    // Inserted out of order; dispatched by (start time, body A, body B, sequence).
    Add(grouper, BodyId{3}, BodyId{4}, At(0.01, Vec3::Zero()));
    Add(grouper, BodyId{1}, BodyId{5}, At(0.01, Vec3::Zero()));
    Add(grouper, BodyId{1}, BodyId{2}, At(0.02, Vec3::Zero()));
    Add(grouper, BodyId{1}, BodyId{2}, At(0.00, Vec3::Zero()));
    Add(grouper, BodyId{1}, BodyId{5}, At(0.01, Vec3(10.0, 0.0, 0.0)));
    const std::vector<Collision> all = grouper.TakeAll();
    REQUIRE(all.size() == 5);
    CHECK((all[0].mBodyA.mValue == 1 && all[0].mBodyB.mValue == 2 && all[0].mStartTime == 0.00));
    CHECK((all[1].mBodyA.mValue == 1 && all[1].mBodyB.mValue == 5 && all[1].mContacts[0].mLocalPointOnA.x() == 0.0));
    CHECK((all[2].mBodyA.mValue == 1 && all[2].mBodyB.mValue == 5 && all[2].mContacts[0].mLocalPointOnA.x() == 10.0));
    CHECK((all[3].mBodyA.mValue == 3 && all[3].mBodyB.mValue == 4));
    CHECK((all[4].mBodyA.mValue == 1 && all[4].mStartTime == 0.02));
}

TEST_CASE("Contacts of one step stay together however far apart", "[plugin]")
{
    CollisionGrouper grouper = CollisionGrouper::Create({0.05, 0.5}).Get();
    // A box face's four corners, 1.6 m apart, reported in one step.
    const std::vector<CollisionContact> corners{At(0.0, Vec3(2.0, -0.8, -0.6)), At(0.0, Vec3(2.0, 0.8, -0.6)),
                                                At(0.0, Vec3(2.0, -0.8, 0.6)), At(0.0, Vec3(2.0, 0.8, 0.6))};
    grouper.Add(BodyId{0}, BodyId{1}, corners);
    // The next step's contact near one corner joins them.
    Add(grouper, BodyId{0}, BodyId{1}, At(0.016, Vec3(2.0, 0.7, 0.6)));
    const std::vector<Collision> all = grouper.TakeAll();
    REQUIRE(all.size() == 1);
    CHECK(all[0].mContacts.size() == 5);
}

TEST_CASE("CollisionGrouper refuses bad settings", "[plugin]")
{
    CHECK(CollisionGrouper::Create({0.0, 0.5}).HasError());
    CHECK(CollisionGrouper::Create({0.05, -1.0}).HasError());
    CHECK(CollisionGrouper::Create({std::numeric_limits<double>::quiet_NaN(), 0.5}).HasError());
}

TEST_CASE("Forget drops a removed body's open collisions", "[plugin]")
{
    CollisionGrouper grouper = CollisionGrouper::Create({}).Get();
    Add(grouper, BodyId{0}, BodyId{1}, At(0.0, Vec3::Zero()));
    Add(grouper, BodyId{2}, BodyId{3}, At(0.0, Vec3::Zero()));
    grouper.Forget(BodyId{1});
    CHECK(grouper.GetOpenCount() == 1);
}

TEST_CASE("Each-step contacts close at their own time and join nothing later", "[plugin]")
{
    CollisionGrouper grouper = CollisionGrouper::Create({0.05, 0.5}).Get();
    const BodyId a{0}, b{1}, c{2};
    const CollisionContact first = At(0.0, Vec3(2.0, 0.0, 0.0));
    const CollisionContact second = At(0.01, Vec3(2.0, 0.0, 0.0));
    grouper.Add(a, b, std::span(&first, 1), true);
    Add(grouper, a, c, first); // a pair with the window
    const std::vector<Collision> now = grouper.TakeClosed(0.0);
    REQUIRE(now.size() == 1);
    CHECK(now[0].mBodyB == b);
    CHECK(grouper.GetOpenCount() == 1);
    // The next step's contacts of the each-step pair make a collision of their own, the windowed pair's join.
    grouper.Add(a, b, std::span(&second, 1), true);
    Add(grouper, a, c, second);
    CHECK(grouper.GetOpenCount() == 2);
    const std::vector<Collision> next = grouper.TakeClosed(0.01);
    REQUIRE(next.size() == 1);
    CHECK(next[0].mBodyB == b);
    CHECK(next[0].mContacts.size() == 1);
    const std::vector<Collision> later = grouper.TakeClosed(0.05);
    REQUIRE(later.size() == 1);
    CHECK(later[0].mContacts.size() == 2);
}
