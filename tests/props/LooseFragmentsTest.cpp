// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// Pieces that break loose from a prop leave it as rigid bodies: momentum kept, handed over once, replayed.
#include "BrittlePanel.h"
#include "ScratchDirectory.h"
#include "WorldFixture.h"

#include <crumple/base/ByteReader.h>
#include <crumple/base/ByteWriter.h>
#include <crumple/base/FileBytes.h>
#include <crumple/plugin/DamageRecorder.h>
#include <crumple/props/PropBody.h>
#include <crumple/props/PropRecording.h>
#include <crumple/props/PropWorld.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

using namespace crumple;
using namespace crumple::fem;
using namespace crumple::plugin;
using namespace crumple::props;

namespace
{

// Momentum of the prop's free nodes, world frame.
Vec3 FreeMomentum(const TetSolver& inSolver, const Mat3& inRotation)
{
    Vec3 momentum = Vec3::Zero();
    for (int node = 0; node < inSolver.GetNodeCount(); ++node)
        if (inSolver.GetInverseMasses()[static_cast<std::size_t>(node)] > 0.0)
            momentum += inSolver.GetMasses()[static_cast<std::size_t>(node)] * inSolver.GetVelocities()[static_cast<std::size_t>(node)];
    return inRotation * momentum;
}

// Hard hits across the panel until pieces are loose (at most inHits), the props stepping in between.
void Smash(common::WorldFixture& ioFixture, PropWorld& ioProps, const PropId& inWall, int inHits)
{
    for (int hit = 0; hit < inHits; ++hit)
    {
        REQUIRE(ioFixture.mWorld.SetBodyState(ioFixture.mCar, ioFixture.CarState(40.0)));
        const double y = -0.6 + 0.4 * (hit % 4), z = 0.6 - 0.4 * (hit / 4);
        REQUIRE(ioFixture.mWorld.SubmitContacts(std::vector<ContactEvent>{ioFixture.FrontContact(y, z, 0.2 * hit),
                                                                          ioFixture.FrontContact(y + 0.1, z - 0.1, 0.2 * hit)}));
        ioFixture.mWorld.Flush();
        for (int step = 0; step < 10; ++step)
            REQUIRE(ioProps.Step(1.0 / 120.0));
        const std::vector<TetFragment> pieces = ioProps.GetProp(inWall)->ComputeFragments();
        if (std::any_of(pieces.begin(), pieces.end(), [](const TetFragment& p) { return !p.mAnchored; }))
            return;
    }
}

} // namespace

TEST_CASE("Loose pieces leave a prop as rigid bodies once, keeping its momentum, and replay", "[props][replay]")
{
    const std::filesystem::path path = common::ScratchDirectory() / "loose.crumple";
    common::WorldFixture fixture;
    std::unique_ptr<DamageRecorder> recorder = std::move(DamageRecorder::Create(path, fixture.mWorld).Get());
    std::unique_ptr<PropWorld> props = PropWorld::Create(fixture.mWorld).Get();
    REQUIRE(props->AttachRecorder(recorder.get()).IsValid());
    const PropId wall = props->AddProp(fixture.mWall, test::WeakPanel()).Get();
    Smash(fixture, *props, wall, 12);

    const TetSolver& solver = *props->GetProp(wall)->GetCpuSolver();
    const std::vector<TetFragment> before = solver.ComputeFragments();
    int loose_before = 0;
    for (const TetFragment& piece : before)
        loose_before += piece.mAnchored ? 0 : 1;
    REQUIRE(loose_before > 0); // the hits knocked pieces out: the rest of the test is not vacuous
    const Mat3 rotation = fixture.mWorld.GetBodyState(fixture.mWall)->mTransform.mRotation;
    const Vec3 momentum_before = FreeMomentum(solver, rotation);

    CHECK_FALSE(props->TakeLooseFragments(-1.0));
    CHECK_FALSE(props->TakeLooseFragments(std::numeric_limits<double>::quiet_NaN()));
    const std::vector<LooseFragment> loose = props->TakeLooseFragments().Get();
    REQUIRE(static_cast<int>(loose.size()) == loose_before);
    Vec3 momentum_after = FreeMomentum(solver, rotation);
    for (const LooseFragment& piece : loose)
    {
        CHECK(piece.mProp == wall);
        CHECK_FALSE(piece.mDropped);
        // The piece's body carries its exact mass, and no more kinetic energy than its nodes had.
        const auto same = std::find_if(before.begin(), before.end(), [&](const TetFragment& f) { return f.mElements == piece.mElements; });
        REQUIRE(same != before.end());
        CHECK(piece.mRigidBody.mBody.mMass == same->mMass);
        CHECK(piece.mRigidBody.mRigidKineticEnergy <= piece.mRigidBody.mNodalKineticEnergy);
        momentum_after += piece.mRigidBody.mBody.mMass * piece.mRigidBody.mBody.mLinearVelocity;
    }
    CHECK((momentum_after - momentum_before).norm() <= 1.0e-9 * std::max(momentum_before.norm(), 1.0));
    // The prop says which elements left with them (GetTakenElements), exactly those.
    std::vector<std::uint8_t> taken(solver.GetElementNodes().size(), 0);
    for (const LooseFragment& piece : loose)
        for (int element : piece.mElements)
            taken[static_cast<std::size_t>(element)] = 1;
    const std::span<const std::uint8_t> reported = props->GetTakenElements(wall);
    CHECK(std::vector<std::uint8_t>(reported.begin(), reported.end()) == taken);
    CHECK(props->GetTakenElements(PropId{99}).empty());
    // They left the prop: every piece now holds a fixed node, and a second call hands over nothing.
    for (const TetFragment& piece : solver.ComputeFragments())
        CHECK(piece.mAnchored);
    CHECK(props->TakeLooseFragments().Get().empty());

    // The run goes on (the props step), then the recording replays bit for bit with the pieces dropped.
    for (int step = 0; step < 6; ++step)
        REQUIRE(props->Step(1.0 / 120.0));
    REQUIRE(props->AttachRecorder(nullptr).IsValid());
    REQUIRE(recorder->Close().IsValid());
    const std::vector<ReplayedProp> replayed = ReplayProps(DecodeReplay(ReadFileBytes(path).Get()).Get()).Get();
    REQUIRE(replayed.size() == 1u);
    REQUIRE(replayed[0].mProp.GetCpuSolver() != nullptr);
    CHECK(replayed[0].mProp.GetCpuSolver()->GetPositions() == solver.GetPositions());
    CHECK(replayed[0].mProp.GetCpuSolver()->GetVelocities() == solver.GetVelocities());
    CHECK(replayed[0].mProp.GetCpuSolver()->GetInverseMasses() == solver.GetInverseMasses());

    // A recording whose props broke otherwise than the replaying FEM does (made by another build) is refused
    // with its reason, not replayed with pieces torn off where the prop never broke. Stood in for by a loose
    // record naming a piece of other nodes (all of them the prop's): the piece's nodes shifted by one, then
    // the piece with one node less.
    const Replay recorded = DecodeReplay(ReadFileBytes(path).Get()).Get();
    const auto loose_record = std::find_if(
        recorded.mExtensions.begin(), recorded.mExtensions.end(),
        [](const RecordedExtension& e) { return e.mTag == static_cast<std::uint32_t>(EPropRecord::Loose); });
    REQUIRE(loose_record != recorded.mExtensions.end());
    const std::size_t index = static_cast<std::size_t>(loose_record - recorded.mExtensions.begin());
    ByteReader reader(loose_record->mPayload);
    const std::uint32_t prop_index = reader.ReadU32();
    std::vector<std::uint32_t> nodes(reader.ReadU32());
    for (std::uint32_t& node : nodes)
        node = reader.ReadU32();
    REQUIRE_FALSE(reader.Failed());
    REQUIRE(nodes.size() >= 2u);
    const auto rewritten = [&](const std::vector<std::uint32_t>& inNodes)
    {
        Replay changed = recorded;
        ByteWriter writer;
        writer.WriteU32(prop_index);
        writer.WriteU32(static_cast<std::uint32_t>(inNodes.size()));
        for (std::uint32_t node : inNodes)
            writer.WriteU32(node);
        changed.mExtensions[index].mPayload = writer.TakeBytes();
        return changed;
    };
    std::vector<std::uint32_t> shifted = nodes;
    for (std::uint32_t& node : shifted)
        node = node == 0 ? 1 : node - 1;
    std::vector<std::uint32_t> fewer(nodes.begin(), nodes.end() - 1);
    for (const std::vector<std::uint32_t>& other : {shifted, fewer})
    {
        const Result<std::vector<ReplayedProp>> refused = ReplayProps(rewritten(other));
        REQUIRE(refused.HasError());
        CHECK(refused.GetError().mCode == EError::CorruptData);
        CHECK_THAT(refused.GetError().mMessage,
                   Catch::Matchers::Contains("broke otherwise than when recorded"));
    }
    // The record as written still replays (the check reads the piece, not the record's bytes).
    CHECK(ReplayProps(rewritten(nodes)).IsValid());
}

TEST_CASE("Loose pieces: a prop whose links and anchors did not change is not searched again, and one whose "
          "anchors changed is",
          "[props]")
{
    // TakeLooseFragments skips a prop whose broken links and fixed nodes are those it last settled; the game
    // un-fixing a node it had fixed must still let the piece it held go.
    common::WorldFixture fixture;
    std::unique_ptr<PropWorld> props = PropWorld::Create(fixture.mWorld).Get();
    const PropId wall = props->AddProp(fixture.mWall, test::WeakPanel()).Get();
    Smash(fixture, *props, wall, 12);
    FemProp& prop = *props->GetProp(wall);
    // The game pins one node of each loose piece: nothing is loose, twice (the second call skips the search).
    std::vector<int> pins;
    for (const TetFragment& piece : prop.ComputeFragments())
        if (!piece.mAnchored)
            pins.push_back(piece.mNodes.front());
    REQUIRE_FALSE(pins.empty());
    for (int node : pins)
        REQUIRE(prop.SetNodeFixed(node, true));
    CHECK(props->TakeLooseFragments().Get().empty());
    CHECK(props->TakeLooseFragments().Get().empty());
    // Unpinned, without a link breaking: the pieces leave at the next call.
    for (int node : pins)
        REQUIRE(prop.SetNodeFixed(node, false));
    CHECK(props->TakeLooseFragments().Get().size() == pins.size());
    CHECK(props->TakeLooseFragments().Get().empty());
}

TEST_CASE("Loose pieces: a prop settled before it cracked is searched again once links break", "[props]")
{
    common::WorldFixture fixture;
    std::unique_ptr<PropWorld> props = PropWorld::Create(fixture.mWorld).Get();
    const PropId wall = props->AddProp(fixture.mWall, test::WeakPanel()).Get();
    CHECK(props->TakeLooseFragments().Get().empty()); // whole: settled with no link broken
    Smash(fixture, *props, wall, 12);
    int loose = 0;
    for (const TetFragment& piece : props->GetProp(wall)->ComputeFragments())
        loose += piece.mAnchored ? 0 : 1;
    REQUIRE(loose > 0);
    CHECK(static_cast<int>(props->TakeLooseFragments().Get().size()) == loose);
}

TEST_CASE("Loose pieces lighter than the minimum mass are dropped without a body", "[props]")
{
    common::WorldFixture fixture;
    std::unique_ptr<PropWorld> props = PropWorld::Create(fixture.mWorld).Get();
    const PropId wall = props->AddProp(fixture.mWall, test::WeakPanel()).Get();
    Smash(fixture, *props, wall, 12);
    const std::vector<LooseFragment> loose = props->TakeLooseFragments(1.0e9).Get();
    REQUIRE_FALSE(loose.empty());
    for (const LooseFragment& piece : loose)
    {
        CHECK(piece.mDropped);
        CHECK(piece.mRigidBody.mBody.mHullPoints.empty());
    }
    for (const TetFragment& piece : props->GetProp(wall)->ComputeFragments())
        CHECK(piece.mAnchored);
}

TEST_CASE("A free prop keeps the piece its body carries, however often its loose pieces are taken", "[props]")
{
    // Review finding: a prop with no fixed node counted as held once the first pieces taken from it were fixed,
    // and the second call handed over the piece the prop's own body carries.
    common::WorldFixture fixture;
    std::unique_ptr<PropWorld> props = PropWorld::Create(fixture.mWorld).Get();
    FemProp panel = test::WeakPanel();
    for (int node = 0; node < panel.GetNodeCount(); ++node)
        REQUIRE(panel.SetNodeFixed(node, false).IsValid()); // free: nothing holds it
    const PropId wall = props->AddProp(fixture.mWall, std::move(panel)).Get();
    Smash(fixture, *props, wall, 12);
    REQUIRE(props->GetProp(wall)->ComputeFragments().size() > 2);
    const std::vector<LooseFragment> first = props->TakeLooseFragments().Get();
    REQUIRE_FALSE(first.empty());
    for (const LooseFragment& piece : first)
        CHECK(std::find(piece.mElements.begin(), piece.mElements.end(), 0) == piece.mElements.end()); // group 0 stays
    // More hits and steps, then a second call: still never the carried piece (the one holding element 0).
    Smash(fixture, *props, wall, 4);
    const std::vector<LooseFragment> second = props->TakeLooseFragments().Get();
    for (const LooseFragment& piece : second)
        CHECK(std::find(piece.mElements.begin(), piece.mElements.end(), 0) == piece.mElements.end());
    const std::vector<TetFragment> pieces = props->GetProp(wall)->ComputeFragments();
    CHECK_FALSE(pieces[0].mAnchored); // the carried piece still moves freely
}

TEST_CASE("Loose pieces stay out of the prop's shape and collisions after later cracks renumber its nodes",
          "[props]")
{
    // Fracture numbers the nodes it splits afresh from the set of broken links: a crack after a piece left
    // can give the piece's nodes other indices. What was taken is kept by element (whose indices never
    // change): kept by node, the shape drew the piece where it froze and collisions landed on its fixed
    // nodes.
    common::WorldFixture fixture;
    std::unique_ptr<PropWorld> props = PropWorld::Create(fixture.mWorld).Get();
    const PropId wall = props->AddProp(fixture.mWall, test::BrittlePanel({1, 8, 8}, 1.0e9, 10.0)).Get();
    const FemProp& prop = *props->GetProp(wall);
    const auto hit = [&](double inY, double inZ, double inSpeed, double inTime)
    {
        REQUIRE(fixture.mWorld.SetBodyState(fixture.mCar, fixture.CarState(inSpeed)));
        REQUIRE(
            fixture.mWorld.SubmitContacts(std::vector<ContactEvent>{fixture.FrontContact(inY, inZ, inTime)}));
        fixture.mWorld.Flush();
        for (int step = 0; step < 10; ++step)
            REQUIRE(props->Step(1.0 / 120.0));
    };
    // A corner knocked out at the top; the pieces taken.
    hit(-0.6, 0.7, 40.0, 0.0);
    const std::vector<LooseFragment> loose = props->TakeLooseFragments().Get();
    REQUIRE_FALSE(loose.empty());
    std::vector<std::uint8_t> taken(prop.GetElementNodes().size(), 0);
    std::set<int> nodes_when_taken;
    for (const LooseFragment& piece : loose)
    {
        for (int element : piece.mElements)
            taken[static_cast<std::size_t>(element)] = 1;
        nodes_when_taken.insert(piece.mNodes.begin(), piece.mNodes.end());
    }
    // Then lower down, where the rest nodes come first: new nodes there push the pieces' numbers on.
    for (int round = 0; round < 4; ++round)
        hit(0.4 - 0.3 * round, -0.3, 120.0, 1.0 + round);
    bool renumbered = false;
    for (std::size_t element = 0; element < taken.size(); ++element)
        if (taken[element] != 0)
            for (int node : prop.GetElementNodes()[element])
                renumbered = renumbered || nodes_when_taken.count(node) == 0;
    REQUIRE(renumbered); // a taken element has a node whose index was not a piece's: the test is not vacuous

    // The shape is that of the elements not taken, exactly.
    std::vector<Vec3> positions;
    prop.ReadPositions(positions);
    const Result<std::vector<std::vector<Vec3>>> shape = props->GetCollisionPieces(wall, 0.25);
    const Result<std::vector<std::vector<Vec3>>> expected =
        PropCollisionPieces(positions, prop.GetElementNodes(), taken, 0.25);
    REQUIRE(shape);
    REQUIRE(expected);
    CHECK_FALSE(expected.Get().empty());
    CHECK(shape.Get() == expected.Get());

    // A contact inside any taken element lands on what is left, never on a piece's nodes.
    std::vector<std::uint8_t> kept_node(positions.size(), 0);
    for (std::size_t element = 0; element < taken.size(); ++element)
        if (taken[element] == 0)
            for (int node : prop.GetElementNodes()[element])
                kept_node[static_cast<std::size_t>(node)] = 1;
    int on_pieces = 0, contacts = 0;
    for (std::size_t element = 0; element < taken.size(); ++element)
    {
        if (taken[element] == 0)
            continue;
        Vec3 centroid = Vec3::Zero();
        for (int node : prop.GetElementNodes()[element])
            centroid += 0.25 * positions[static_cast<std::size_t>(node)];
        Collision collision;
        collision.mBodyA = fixture.mWall;
        collision.mBodyB = fixture.mCar;
        CollisionContact contact;
        contact.mLocalPointOnA = centroid;
        contact.mLocalNormalOnA = Vec3::UnitX();
        contact.mImpulse = 1.0e-3;
        collision.mContacts.push_back(contact);
        std::vector<NodalImpulse> applied;
        REQUIRE(props->GetProp(wall)->ApplyCollision(collision, fixture.mWall, &applied).IsValid());
        ++contacts;
        for (const NodalImpulse& impulse : applied)
            on_pieces += kept_node[static_cast<std::size_t>(impulse.mNode)] != 0 ? 0 : 1;
    }
    CHECK(contacts > 0);
    CHECK(on_pieces == 0);
}
