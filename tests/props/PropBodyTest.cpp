// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// A prop as an engine body: its exact mass frame, its mesh moved into it, and its collision pieces, which
// lose what breaks loose and follow what its FEM does.
#include "BrittlePanel.h"
#include "DrawVec3.h"
#include "ScratchDirectory.h"
#include "WorldFixture.h"

#include <crumple/fem/TetGrid.h>
#include <crumple/fem/TetVolume.h>
#include <crumple/plugin/DamageRecorder.h>
#include <crumple/props/HeldFemProp.h>
#include <crumple/props/PropBody.h>
#include <crumple/props/PropWorld.h>


#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <map>
#include <random>
#include <set>
#include <cmath>
#include <limits>

using namespace crumple;
using namespace crumple::props;

namespace
{

// A 1 x 0.5 x 0.2 m slab of 4 x 2 x 1 cubes of 0.25 x 0.25 x 0.2 m.
fem::TetMesh Slab()
{
    fem::TetGridSettings grid;
    grid.mOrigin = Vec3(2.0, -1.0, 0.0);
    grid.mSize = Vec3(1.0, 0.5, 0.2);
    grid.mCellCount = {4, 2, 1};
    return fem::TetGrid(grid).Get();
}

// A 1 m x 0.2 m x 1 m wall of 5 x 1 x 5 cubes standing on z = 0.
fem::TetMesh StandingWall()
{
    fem::TetGridSettings grid;
    grid.mSize = Vec3(1.0, 0.2, 1.0);
    grid.mCellCount = {5, 1, 5};
    return fem::TetGrid(grid).Get();
}

// The nodes a mesh stands on (z = 0), ascending.
std::vector<int> Footings(const fem::TetMesh& inMesh)
{
    std::vector<int> footings;
    for (int node = 0; node < inMesh.GetNodeCount(); ++node)
        if (inMesh.GetRestPositions()[static_cast<std::size_t>(node)].z() < 1.0e-9)
            footings.push_back(node);
    return footings;
}

Transform Pose()
{
    Transform pose;
    pose.mRotation = Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, -0.5).normalized()).toRotationMatrix();
    pose.mTranslation = Vec3(5.0, -3.0, 1.0);
    return pose;
}

} // namespace

TEST_CASE("MakePropBody: the exact mass, centre and principal inertia of a slab, its mesh moved into that frame", "[props]")
{
    const fem::TetMesh slab = Slab();
    const PropBody made = MakePropBody(slab, 500.0, Pose(), true, 0.25).Get();
    const double mass = 500.0 * 1.0 * 0.5 * 0.2;
    CHECK(std::abs(made.mBody.mMass - mass) <= 1.0e-12 * mass);
    // A uniform box: m / 12 (b^2 + c^2), ascending.
    const Vec3 inertia = mass / 12.0 * Vec3(0.5 * 0.5 + 0.2 * 0.2, 1.0 + 0.2 * 0.2, 1.0 + 0.5 * 0.5);
    CHECK((made.mBody.mPrincipalInertia - inertia).norm() <= 1.0e-9 * inertia.norm());
    CHECK((made.mBody.mPosition - Pose().ToWorld(Vec3(2.5, -0.75, 0.1))).norm() <= 1.0e-12);
    CHECK(IsRotation(made.mBody.mOrientation, 1.0e-12));
    CHECK(made.mBody.mHeld);
    // The body axes are the slab's (up to sign), turned by the pose.
    const Mat3 local = Pose().mRotation.transpose() * made.mBody.mOrientation;
    for (int axis = 0; axis < 3; ++axis)
        CHECK(std::abs(std::abs(local(axis, axis)) - 1.0) <= 1.0e-9);
    // Same nodes, same elements, moved rigidly into the body frame, whose origin is the centre of mass.
    REQUIRE(made.mMesh.GetNodeCount() == slab.GetNodeCount());
    CHECK(made.mMesh.GetTets() == slab.GetTets());
    Vec3 first = Vec3::Zero();
    for (std::size_t node = 0; node < slab.GetRestPositions().size(); ++node)
        CHECK((made.mMesh.GetRestPositions()[node] - made.mMeshToBody.ToWorld(slab.GetRestPositions()[node])).norm() <= 1.0e-15);
    for (const fem::TetIndices& tet : made.mMesh.GetTets())
    {
        const auto& x = made.mMesh.GetRestPositions();
        const Vec3 sum = x[tet[0]] + x[tet[1]] + x[tet[2]] + x[tet[3]];
        first += fem::TetVolume(x[tet[0]], x[tet[1]], x[tet[2]], x[tet[3]]) * 0.25 * sum;
    }
    CHECK(first.norm() <= 1.0e-15);
    // The world sees the mesh where it was: body pose times body-frame position.
    const Transform body{made.mBody.mOrientation, made.mBody.mPosition};
    CHECK((body.ToWorld(made.mMesh.GetRestPositions()[7]) - Pose().ToWorld(slab.GetRestPositions()[7])).norm() <= 1.0e-12);
    // The pieces are those of the moved mesh (cubes of the body frame's grid), and hold every node.
    CHECK(made.mBody.mPieces == PropCollisionPieces(made.mMesh.GetRestPositions(), made.mMesh.GetTets(), {}, 0.25).Get());
    std::size_t held = 0;
    for (const Vec3& node : made.mMesh.GetRestPositions())
        held += std::any_of(made.mBody.mPieces.begin(), made.mBody.mPieces.end(), [&](const std::vector<Vec3>& inPiece) {
            return std::find(inPiece.begin(), inPiece.end(), node) != inPiece.end();
        }) ? 1 : 0;
    CHECK(held == made.mMesh.GetRestPositions().size());
}

TEST_CASE("MakePropBody and PropCollisionPieces refuse bad input and leave out what left", "[props]")
{
    const fem::TetMesh slab = Slab();
    CHECK(MakePropBody(slab, 0.0, Pose(), true, 0.25).HasError());
    CHECK(MakePropBody(slab, 500.0, Pose(), true, std::numeric_limits<double>::quiet_NaN()).HasError());
    Transform skewed = Pose();
    skewed.mRotation(0, 0) += 0.1;
    CHECK(MakePropBody(slab, 500.0, skewed, true, 0.25).HasError());
    // A pose from an engine in single precision (orthonormal to about 1e-6) is taken, made a rotation, and
    // gives the body of the exact pose to float round-off.
    Transform single = Pose();
    single.mRotation = Pose().mRotation.cast<float>().cast<double>() * (1.0 + 2.0e-6);
    REQUIRE_FALSE(IsRotation(single.mRotation, 1.0e-6));
    const Result<PropBody> from_float = MakePropBody(slab, 500.0, single, true, 0.25);
    REQUIRE(from_float);
    const PropBody exact = MakePropBody(slab, 500.0, Pose(), true, 0.25).Get();
    CHECK(IsRotation(from_float.Get().mBody.mOrientation, 1.0e-9));
    CHECK((from_float.Get().mBody.mOrientation - exact.mBody.mOrientation).cwiseAbs().maxCoeff() <= 1.0e-6);
    CHECK((from_float.Get().mBody.mPosition - exact.mBody.mPosition).norm() <= 1.0e-6);

    // In the slab's own frame its cubes are the grid's: one piece per cube, its eight corners. Leaving out the
    // first cube's five tetrahedra removes its piece, and only that one.
    std::vector<std::uint8_t> left_out(slab.GetTets().size(), 0);
    const std::vector<std::vector<Vec3>> all = PropCollisionPieces(slab.GetRestPositions(), slab.GetTets(), {}, 0.25).Get();
    for (std::size_t element = 0; element < 5; ++element)
        left_out[element] = 1;
    const std::vector<std::vector<Vec3>> rest = PropCollisionPieces(slab.GetRestPositions(), slab.GetTets(), left_out, 0.25).Get();
    REQUIRE(all.size() == 8);
    for (const std::vector<Vec3>& piece : all)
        CHECK(piece.size() == 8);
    CHECK(rest.size() == 7);
    CHECK(std::find(rest.begin(), rest.end(), all[0]) == rest.end());

    // A cell size that is not finite and > 0, or so small that the cubes' indices would not be exact, and an
    // element naming a node that is not there.
    for (double cell : {std::numeric_limits<double>::quiet_NaN(), 0.0, -1.0, 1.0e-300})
    {
        INFO("cell " << cell);
        CHECK(PropCollisionPieces(slab.GetRestPositions(), slab.GetTets(), {}, cell).HasError());
        CHECK(MakePropBody(slab, 500.0, Pose(), true, cell).HasError());
    }
    std::vector<fem::TetIndices> elements = slab.GetTets();
    elements.back()[1] = static_cast<int>(slab.GetRestPositions().size());
    CHECK(PropCollisionPieces(slab.GetRestPositions(), elements, {}, 0.25).GetError().mCode == EError::OutOfRange);
}

namespace
{

// The pieces as the definition reads: an ordered map from cube (z, y, x) to its elements' nodes, each
// cube's nodes deduplicated and ascending.
std::vector<std::vector<Vec3>> MapPieces(std::span<const Vec3> inPositions, std::span<const fem::TetIndices> inElements,
                                         std::span<const std::uint8_t> inLeftOut, double inCellSize)
{
    std::map<std::array<std::int64_t, 3>, std::set<int>> cubes;
    for (std::size_t element = 0; element < inElements.size(); ++element)
    {
        if (element < inLeftOut.size() && inLeftOut[element] != 0)
            continue;
        Vec3 centroid = Vec3::Zero();
        for (int node : inElements[element])
            centroid += inPositions[static_cast<std::size_t>(node)];
        const Vec3 cell = (0.25 * centroid / inCellSize).array().floor();
        cubes[{static_cast<std::int64_t>(cell.z()), static_cast<std::int64_t>(cell.y()), static_cast<std::int64_t>(cell.x())}]
            .insert(inElements[element].begin(), inElements[element].end());
    }
    std::vector<std::vector<Vec3>> pieces;
    for (const auto& [cube, nodes] : cubes)
    {
        std::vector<Vec3>& piece = pieces.emplace_back();
        for (int node : nodes)
            piece.push_back(inPositions[static_cast<std::size_t>(node)]);
    }
    return pieces;
}

} // namespace

TEST_CASE("PropCollisionPieces equals the cube map it stands for, near the origin and far from it", "[props]")
{
    // A slab crumpled at random (elements straddle cubes, some cubes share nodes), a third of its elements
    // left out; then the same moved far out along one axis (more cubes between the extremes than one integer
    // can number) and spread over a span wider than 2^20 cubes.
    const fem::TetMesh slab = fem::TetGrid({.mSize = Vec3(1.0, 0.6, 0.4), .mCellCount = {10, 6, 4}}).Get();
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> jitter(-0.04, 0.04);
    std::vector<Vec3> positions = slab.GetRestPositions();
    for (Vec3& position : positions)
        position += common::DrawVec3([&] { return jitter(random); });
    std::vector<std::uint8_t> left_out(slab.GetTets().size(), 0);
    for (std::size_t element = 0; element < left_out.size(); element += 3)
        left_out[element] = 1;
    for (const Vec3& offset : {Vec3(0.0, 0.0, 0.0), Vec3(-0.37, 0.11, -0.05), Vec3(1.0e9, -3.0e8, 0.0)})
        for (double cell : {0.05, 0.25, 0.7})
        {
            INFO("offset " << offset.transpose() << ", cell " << cell);
            std::vector<Vec3> moved = positions;
            for (Vec3& position : moved)
                position += offset;
            CHECK(PropCollisionPieces(moved, slab.GetTets(), left_out, cell).Get() == MapPieces(moved, slab.GetTets(), left_out, cell));
            CHECK(PropCollisionPieces(moved, slab.GetTets(), {}, cell).Get() == MapPieces(moved, slab.GetTets(), {}, cell));
        }
    std::vector<Vec3> spread = positions;
    spread[0] = Vec3(-4.0e5, 2.0e5, 1.0e5); // with 0.05 m cubes: 8e6 cubes from the rest of the slab
    CHECK(PropCollisionPieces(spread, slab.GetTets(), {}, 0.05).Get() == MapPieces(spread, slab.GetTets(), {}, 0.05));
    CHECK(PropCollisionPieces(positions, slab.GetTets(), std::vector<std::uint8_t>(left_out.size(), 1), 0.25).Get().empty());
}

TEST_CASE("A prop's collision shape follows its FEM and loses the pieces handed over", "[props]")
{
    common::WorldFixture fixture;
    std::unique_ptr<PropWorld> props = PropWorld::Create(fixture.mWorld).Get();
    const PropId wall = props->AddProp(fixture.mWall, test::BrittlePanel({1, 8, 8}, 1.0e9, 0.1)).Get();
    CHECK(props->GetCollisionPieces(PropId{7}, 0.25).HasError());
    CHECK(props->TakeChangedShape(wall, 0.25, -1.0).GetError().mCode == EError::InvalidArgument);
    CHECK(props->TakeChangedShape(wall, 0.25, std::numeric_limits<double>::quiet_NaN()).GetError().mCode ==
          EError::NonFinite);
    // The first call gives the shape; with nothing moved, the next gives nothing.
    const std::optional<std::vector<std::vector<Vec3>>> first = props->TakeChangedShape(wall, 0.25, 0.01).Get();
    REQUIRE(first);
    CHECK(first->size() == 64);
    CHECK_FALSE(props->TakeChangedShape(wall, 0.25, 0.01).Get());
    // Hits until pieces break loose: the shape moves with the panel, and the pieces handed over leave it.
    int hits = 0;
    std::vector<LooseFragment> loose;
    while (loose.empty() && hits < 12)
    {
        REQUIRE(fixture.mWorld.SetBodyState(fixture.mCar, fixture.CarState(40.0)));
        const double y = -0.6 + 0.4 * (hits % 4), z = 0.6 - 0.4 * (hits / 4);
        REQUIRE(fixture.mWorld.SubmitContacts(std::vector<plugin::ContactEvent>{fixture.FrontContact(y, z, 0.2 * hits),
                                                                               fixture.FrontContact(y + 0.1, z - 0.1, 0.2 * hits)}));
        fixture.mWorld.Flush();
        for (int step = 0; step < 10; ++step)
            REQUIRE(props->Step(1.0 / 120.0));
        if (hits++ == 0)
            CHECK(props->TakeChangedShape(wall, 0.25, 0.001).Get()); // the first hit moved the panel
        loose = props->TakeLooseFragments().Get();
    }
    REQUIRE_FALSE(loose.empty());
    CHECK(props->GetShapeRevision(wall) == loose.size());
    const std::optional<std::vector<std::vector<Vec3>>> after = props->TakeChangedShape(wall, 0.25, 1.0e9).Get();
    REQUIRE(after); // pieces left: a new shape whatever the tolerance
    std::size_t left = 0;
    for (const LooseFragment& piece : loose)
        left += piece.mElements.size();
    std::size_t points = 0, points_before = 0;
    for (const std::vector<Vec3>& piece : *after)
        points += piece.size();
    for (const std::vector<Vec3>& piece : *first)
        points_before += piece.size();
    CHECK(left > 0);
    CHECK(after->size() <= first->size());
    CHECK(points < points_before);
}

TEST_CASE("MakeHeldFemProp: no gravity by default, its footings anchored, asleep until struck, with gravity "
          "it settles on its anchors, a bad anchor is refused",
          "[props]")
{
    const fem::TetMesh mesh = StandingWall();
    const std::vector<int> footings = Footings(mesh);
    props::FemProp prop = props::MakeHeldFemProp(mesh, fem::FemMaterialSettings{}, footings).Get();
    const fem::TetSolver& solver = *prop.GetCpuSolver();
    CHECK(solver.GetSettings().mGravity == Vec3::Zero());
    for (int node = 0; node < solver.GetNodeCount(); ++node)
        CHECK((solver.GetInverseMasses()[static_cast<std::size_t>(node)] == 0.0) ==
              (std::find(footings.begin(), footings.end(), node) != footings.end()));
    // Nothing pulls it: it stays where it stands (to round-off) and falls asleep.
    for (int step = 0; step < 60 && !solver.IsSleeping(); ++step)
        REQUIRE(prop.Step(1.0 / 60.0));
    CHECK(solver.IsSleeping());
    double moved = 0.0;
    for (int node = 0; node < mesh.GetNodeCount(); ++node)
        moved = std::max(moved, (solver.GetPositions()[static_cast<std::size_t>(node)] - mesh.GetRestPositions()[static_cast<std::size_t>(node)]).norm());
    CHECK(moved < 1.0e-12);

    const std::vector<int> bad{0, mesh.GetNodeCount()};
    const Result<props::FemProp> refused = props::MakeHeldFemProp(mesh, fem::FemMaterialSettings{}, bad);
    REQUIRE(refused.HasError());
    CHECK(refused.GetError().mMessage.find("anchored node " + std::to_string(mesh.GetNodeCount())) != std::string::npos);

    // The game's own solver settings are used; settings the solver refuses are refused.
    fem::TetSolverSettings own = props::HeldPropSolverSettings();
    own.mFactorRefreshIterations = 3;
    own.mCgRelativeTolerance = 1.0e-8;
    const props::FemProp tuned = props::MakeHeldFemProp(mesh, fem::FemMaterialSettings{}, footings, own).Get();
    CHECK(tuned.GetCpuSolver()->GetSettings().mFactorRefreshIterations == 3);
    CHECK(tuned.GetCpuSolver()->GetSettings().mCgRelativeTolerance == 1.0e-8);
    props::FemPropSettings unknown_backend;
    unknown_backend.mBackend = static_cast<props::EFemBackend>(7);
    const Result<props::FemProp> no_backend =
        props::MakeHeldFemProp(mesh, fem::FemMaterialSettings{}, footings, own, 0.0, unknown_backend);
    REQUIRE(no_backend.HasError());
    CHECK(no_backend.GetError().mMessage.find("mBackend") != std::string::npos);
    own.mFactorRefreshIterations = -1;
    CHECK(props::MakeHeldFemProp(mesh, fem::FemMaterialSettings{}, footings, own).HasError());

    // The contact spread is the prop's; a bad one is refused before the solver's reasons.
    CHECK(props::MakeHeldFemProp(mesh, fem::FemMaterialSettings{}, footings, props::HeldPropSolverSettings(), 0.3)
              .Get()
              .GetContactSpread() == 0.3);
    for (double radius : {-0.1, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
    {
        const Result<props::FemProp> spread = props::MakeHeldFemProp(mesh, fem::FemMaterialSettings{}, footings, own, radius);
        REQUIRE(spread.HasError());
        CHECK(spread.GetError().mMessage.find("contact spread") != std::string::npos);
        own.mFactorRefreshIterations = 3;
    }

    // With gravity (the default TetSolverSettings has one) it starts where it hangs on its footings: the
    // static equilibrium of the same solver, bit for bit, made as a fresh solver there (no element work yet,
    // so it can be recorded), and it sleeps once its steps find it settled (3 steps; 6 when it started at its
    // rest shape and sagged), having moved no more than its weight strains it (rho g H / E over its height).
    props::FemProp pulled =
        props::MakeHeldFemProp(mesh, fem::FemMaterialSettings{}, footings, fem::TetSolverSettings{}).Get();
    const fem::TetSolver& sagging = *pulled.GetCpuSolver();
    fem::TetSolver reference =
        fem::TetSolver::Create(mesh, fem::FemMaterialSettings{}, fem::TetSolverSettings{}).Get();
    REQUIRE(reference.SetNodesFixed(footings, true).IsValid());
    REQUIRE(reference.SolveStatic().IsValid());
    CHECK(sagging.GetPositions() == reference.GetPositions());
    CHECK(sagging.GetElementWorkCount() == 0u);
    int steps = 0;
    for (; steps < 240 && !sagging.IsSleeping(); ++steps)
        REQUIRE(pulled.Step(1.0 / 60.0));
    CHECK(sagging.IsSleeping());
    CHECK(steps <= 3);
    double sag = 0.0;
    for (int node = 0; node < mesh.GetNodeCount(); ++node)
        sag = std::max(sag, (sagging.GetPositions()[static_cast<std::size_t>(node)] -
                             mesh.GetRestPositions()[static_cast<std::size_t>(node)])
                                .norm());
    WARN("a held wall under gravity sleeps after " << steps << " steps, having sagged " << sag << " m");
    CHECK(sag > 0.0);
    CHECK(sag < 1.0e-5);
}

TEST_CASE("AddHeldProp: a held body from the prop's shape, its anchored FEM in the world, bad input makes no body", "[props]")
{
    const fem::TetMesh mesh = StandingWall();
    const std::vector<int> footings = Footings(mesh);
    common::WorldFixture fixture;
    std::unique_ptr<props::PropWorld> world = props::PropWorld::Create(fixture.mWorld).Get();
    // The "engine" hands back the fixture's wall body and keeps what it was asked to make.
    std::vector<plugin::PropBodySettings> asked;
    const auto make_body = [&](const plugin::PropBodySettings& inBody) -> Result<plugin::BodyId> {
        asked.push_back(inBody);
        return fixture.mWall;
    };

    // Bad input: no body is asked for, no prop joins.
    CHECK(props::AddHeldProp(*world, mesh, fem::FemMaterialSettings{}, std::vector<int>{mesh.GetNodeCount()}, Transform(), 0.25, make_body)
              .GetError().mCode == EError::OutOfRange);
    CHECK(props::AddHeldProp(*world, mesh, fem::FemMaterialSettings{}, footings, Transform(), 0.0, make_body).IsValid() == false);
    CHECK(props::AddHeldProp(*world, mesh, fem::FemMaterialSettings{}, footings, Transform(), 0.25, nullptr).IsValid() == false);
    CHECK(props::AddHeldProp(*world, mesh, fem::FemMaterialSettings{}, footings, Transform(), 0.25, make_body,
                             props::HeldPropSolverSettings(), -1.0)
              .IsValid() == false);
    CHECK(asked.empty());
    CHECK(world->GetPropCount() == 0);
    // A recorder that can take no more records (closed): refused before the engine body is made.
    {
        std::unique_ptr<plugin::DamageRecorder> recorder =
            std::move(plugin::DamageRecorder::Create(common::ScratchDirectory() / "held_closed.crumple", fixture.mWorld).Get());
        REQUIRE(world->AttachRecorder(recorder.get()).IsValid());
        REQUIRE(recorder->Close().IsValid());
        CHECK(props::AddHeldProp(*world, mesh, fem::FemMaterialSettings{}, footings, Transform(), 0.25, make_body).HasError());
        CHECK(asked.empty());
        CHECK(world->GetPropCount() == 0);
        REQUIRE(world->AttachRecorder(nullptr).IsValid());
    }

    const props::HeldProp held = props::AddHeldProp(*world, mesh, fem::FemMaterialSettings{}, footings, Transform(), 0.25, make_body,
                                                    props::HeldPropSolverSettings(), 0.2)
                                     .Get();
    CHECK(world->GetProp(held.mProp)->GetContactSpread() == 0.2);
    REQUIRE(asked.size() == 1u);
    CHECK(asked[0].mHeld);
    CHECK(asked[0].mMass == held.mMade.mBody.mMass);
    CHECK(asked[0].mPieces == held.mMade.mBody.mPieces);
    CHECK(held.mBody == fixture.mWall);
    CHECK(world->GetBody(held.mProp) == fixture.mWall);
    const fem::TetSolver& solver = *world->GetProp(held.mProp)->GetCpuSolver();
    CHECK(solver.GetSettings().mGravity == Vec3::Zero());
    CHECK(solver.GetPositions() == held.mMade.mMesh.GetRestPositions()); // the FEM works in the body frame
    for (int node : footings)
        CHECK(solver.GetInverseMasses()[static_cast<std::size_t>(node)] == 0.0);
}

TEST_CASE("AddHeldProp: the world's gravity and ground reach the FEM in the body frame", "[props]")
{
    const fem::TetMesh mesh = StandingWall();
    const std::vector<int> footings = Footings(mesh);
    common::WorldFixture fixture;
    std::unique_ptr<props::PropWorld> world = props::PropWorld::Create(fixture.mWorld).Get();
    const auto make_body = [&](const plugin::PropBodySettings&) -> Result<plugin::BodyId>
    { return fixture.mWall; };

    // The wall turned 30 degrees about the world's up axis z and stood on a ground at z = 0.25, 2 m from the
    // origin; the game gives gravity and ground in world terms.
    Transform pose;
    pose.mRotation = Eigen::AngleAxisd(0.5235987755982988, Vec3::UnitZ()).toRotationMatrix();
    pose.mTranslation = Vec3(2.0, -1.0, 0.25);
    fem::TetSolverSettings settings = props::HeldPropSolverSettings();
    settings.mGravity = Vec3(0.0, 0.0, -9.81);
    settings.mGround.mEnabled = true;
    settings.mGround.mNormal = Vec3::UnitZ();
    settings.mGround.mOffset = 0.25;
    settings.mGround.mFriction = 0.4;
    const props::HeldProp held = props::AddHeldProp(*world, mesh, fem::FemMaterialSettings{}, footings, pose,
                                                    0.25, make_body, settings)
                                     .Get();
    const fem::TetSolverSettings& body = world->GetProp(held.mProp)->GetCpuSolver()->GetSettings();
    const Transform body_pose{held.mMade.mBody.mOrientation, held.mMade.mBody.mPosition};

    // Gravity and the ground's normal turned into the body frame; a body point is on the ground exactly when
    // its world image is.
    CHECK((body_pose.mRotation * body.mGravity - settings.mGravity).norm() < 1.0e-12);
    CHECK((body_pose.mRotation * body.mGround.mNormal - Vec3::UnitZ()).norm() < 1.0e-12);
    CHECK(body.mGround.mFriction == 0.4);
    for (const Vec3& world_point : {Vec3(0.0, 0.0, 0.25), Vec3(3.0, -2.0, 0.25), Vec3(1.0, 1.0, 1.25)})
    {
        const Vec3 body_point = body_pose.ToBody(world_point);
        CHECK(body.mGround.mNormal.dot(body_point) - body.mGround.mOffset ==
              Approx(world_point.z() - 0.25).margin(1.0e-12));
    }
    // The wall's footings stand on that ground: in the body frame they lie on its plane.
    for (int node : footings)
        CHECK(body.mGround.mNormal.dot(held.mMade.mMesh.GetRestPositions()[static_cast<std::size_t>(node)]) ==
              Approx(body.mGround.mOffset).margin(1.0e-12));
}
