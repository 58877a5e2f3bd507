// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// Fracture in the solver: Rankine's threshold on an analytic uniaxial stress, crack planes perpendicular to
// the principal direction, a wall that breaks where it is hit, reproducible fragments, and no NaN under
// random impulses.
#include <crumple/fem/LumpedNodeMass.h>
#include <crumple/fem/TetGrid.h>
#include <crumple/fem/TetSolver.h>

#include <BrittleMaterial.h>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>

using namespace crumple;
using namespace crumple::fem;

namespace
{

constexpr double cStrength = common::cBrittleStrength; // Pa
constexpr double cYoung = common::cBrittleYoung;       // Pa
constexpr double cPoisson = common::cBrittlePoisson;
using common::BrittleMaterial;
using common::StiffBrittleMaterial;

// A free 1 m x 0.5 m x 0.5 m bar of 4 x 2 x 2 cubes stretched to the uniaxial stress inStress along x (exact
// for the corotated model: strain diag(e, -nu e, -nu e) with e = stress / E), then stepped by 1 us.
TetSolver StretchedBar(double inStress, EFractureMode inMode)
{
    TetGridSettings grid;
    grid.mSize = Vec3(1.0, 0.5, 0.5);
    grid.mCellCount = {4, 2, 2};
    TetSolverSettings settings;
    settings.mGravity = Vec3::Zero();
    TetSolver solver = TetSolver::Create(TetGrid(grid).Get(), BrittleMaterial(inMode), settings).Get();
    const double strain = inStress / cYoung;
    std::vector<Vec3> positions = solver.GetPositions();
    for (Vec3& x : positions)
        x = Vec3(x.x() * (1.0 + strain), x.y() * (1.0 - cPoisson * strain), x.z() * (1.0 - cPoisson * strain));
    REQUIRE(solver.SetPositions(positions).IsValid());
    REQUIRE(solver.Step(1.0e-6).IsValid());
    return solver;
}

struct Wall
{
    TetSolver mSolver;
    std::array<int, 3> mCells;
};

// A 2 m x 0.2 m x 1 m wall of 0.2 m cubes anchored along its base.
Wall MakeWall(EIntegrator inIntegrator)
{
    TetGridSettings grid;
    grid.mSize = Vec3(2.0, 0.2, 1.0);
    grid.mCellCount = {10, 1, 5};
    FemMaterialSettings material = StiffBrittleMaterial();
    material.mMassDamping = 2.0;
    TetSolverSettings settings;
    settings.mIntegrator = inIntegrator;
    Wall wall{TetSolver::Create(TetGrid(grid).Get(), material, settings).Get(), grid.mCellCount};
    for (int i = 0; i <= 10; ++i)
        for (int j = 0; j <= 1; ++j)
            REQUIRE(wall.mSolver.SetNodeFixed(TetGridNode(grid.mCellCount, i, j, 0), true).IsValid());
    return wall;
}

// Centre of dense group inGroup of a TetGrid wall (its group ids are the cell indices) (m).
Vec3 CellCentre(const Wall& inWall, int inGroup)
{
    const int i = inGroup % inWall.mCells[0];
    const int k = inGroup / (inWall.mCells[0] * inWall.mCells[1]);
    return Vec3(0.2 * i + 0.1, 0.1, 0.2 * k + 0.1);
}

// Hits the front face (y = 0) of cell (7, 0, 3), centre (1.5, 0, 0.7), with inImpulse (N s) along +y.
void Hit(Wall& ioWall, double inImpulse)
{
    for (int k = 3; k <= 4; ++k)
        for (int i = 7; i <= 8; ++i)
            REQUIRE(ioWall.mSolver.ApplyImpulse(TetGridNode(ioWall.mCells, i, 0, k), Vec3(0.0, inImpulse / 4.0, 0.0)).IsValid());
}

} // namespace

TEST_CASE("Fracture: a bar opens exactly when its principal stress passes the tensile strength", "[fem]")
{
    const TetSolver below = StretchedBar(0.95 * cStrength, EFractureMode::CrackPlane);
    CHECK(below.GetBrokenLinkCount() == 0);
    CHECK(below.GetNodeCount() == below.GetMesh().GetNodeCount());
    for (const PrincipalStress& principal : below.GetGroupPrincipalStress())
    {
        CHECK(principal.mValue == Approx(0.95 * cStrength).epsilon(1e-4));
        CHECK(std::abs(principal.mDirection.x()) == Approx(1.0).epsilon(1e-9));
    }

    // Above: the crack planes are perpendicular to x, so exactly the 3 x 4 links across x open and the bar
    // falls into four slabs of 2 x 2 cubes that stay whole.
    const TetSolver above = StretchedBar(1.05 * cStrength, EFractureMode::CrackPlane);
    const FractureLinks& links = above.GetFractureLinks();
    for (int link = 0; link < links.GetLinkCount(); ++link)
        CHECK((above.GetBrokenLinks()[link] != 0) == (std::abs(links.mLinkRestNormals[link].x()) > 0.5));
    CHECK(above.GetBrokenLinkCount() == 12);
    const std::vector<TetFragment> slabs = above.ComputeFragments();
    REQUIRE(slabs.size() == 4);
    for (const TetFragment& slab : slabs)
    {
        CHECK(slab.mGroups.size() == 4u);
        CHECK(slab.mMass == Approx(2000.0 * 0.25 * 0.5 * 0.5).epsilon(1e-12));
    }
}

TEST_CASE("Fracture: DetachGroup breaks a cracking cube away from every neighbour, as in the paper", "[fem]")
{
    const TetSolver above = StretchedBar(1.05 * cStrength, EFractureMode::DetachGroup);
    CHECK(above.GetBrokenLinkCount() == above.GetFractureLinks().GetLinkCount());
    const std::vector<TetFragment> pieces = above.ComputeFragments();
    CHECK(pieces.size() == 16u);
    CHECK(above.GetNodeCount() == 16 * 8);
}

TEST_CASE("Fracture: a wall hit at one spot breaks there first, the same way every run", "[fem]")
{
    // An impact is a stress wave (2.2 km/s here): symplectic Euler with its stable sub-steps follows it, and
    // the crack opens in the sub-step where the peak passes the hit cube. (Implicit Euler at a large step
    // spreads an impulse over the whole body within the step: it suits pushes, not blows.)
    auto run = [](std::vector<std::uint8_t>& outFirstCracks, std::vector<TetFragment>& outFragments)
    {
        Wall wall = MakeWall(EIntegrator::SymplecticEuler);
        Hit(wall, 100.0);
        for (int step = 0; step < 200 && outFirstCracks.empty(); ++step)
        {
            const Result<TetStepResult> result = wall.mSolver.Step(1.0e-4);
            REQUIRE(result.IsValid());
            REQUIRE_FALSE(HasEvent(result.Get().mEvents, ETetStepEvent::Diverged));
            if (HasEvent(result.Get().mEvents, ETetStepEvent::Fractured))
                outFirstCracks = wall.mSolver.GetBrokenLinks();
        }
        for (int step = 0; step < 50; ++step)
            REQUIRE(wall.mSolver.Step(1.0e-3).IsValid());
        outFragments = wall.mSolver.ComputeFragments();
        return wall;
    };

    std::vector<std::uint8_t> first_cracks;
    std::vector<TetFragment> fragments;
    const Wall wall = run(first_cracks, fragments);
    REQUIRE_FALSE(first_cracks.empty());

    // Every link that opened first joins cubes within 0.45 m of the hit cube's centre (1.5, 0.1, 0.7).
    const FractureLinks& links = wall.mSolver.GetFractureLinks();
    int opened = 0;
    for (int link = 0; link < links.GetLinkCount(); ++link)
        if (first_cracks[link] != 0)
        {
            ++opened;
            for (int group : links.mLinkGroups[link])
                CHECK((CellCentre(wall, group) - Vec3(1.5, 0.1, 0.7)).norm() < 0.45);
        }
    CHECK(opened > 0);
    // Pieces came loose, and mass is conserved.
    REQUIRE(fragments.size() >= 2u);
    double mass = 0.0;
    for (const TetFragment& fragment : fragments)
        mass += fragment.mMass;
    CHECK(mass == Approx(2000.0 * 2.0 * 0.2 * 1.0).epsilon(1e-12));

    // A second run gives bitwise the same cracks, fragments and positions.
    std::vector<std::uint8_t> first_cracks_again;
    std::vector<TetFragment> fragments_again;
    const Wall again = run(first_cracks_again, fragments_again);
    CHECK(first_cracks_again == first_cracks);
    CHECK(again.mSolver.GetBrokenLinks() == wall.mSolver.GetBrokenLinks());
    CHECK(again.mSolver.GetPositions() == wall.mSolver.GetPositions());
    REQUIRE(fragments_again.size() == fragments.size());
    for (std::size_t index = 0; index < fragments.size(); ++index)
    {
        CHECK(fragments_again[index].mElements == fragments[index].mElements);
        CHECK(fragments_again[index].mCenterOfMass == fragments[index].mCenterOfMass);
    }
}

TEST_CASE("Fracture: a wall hit below its strength stays whole", "[fem]")
{
    Wall wall = MakeWall(EIntegrator::SymplecticEuler);
    Hit(wall, 3.0);
    for (int step = 0; step < 30; ++step)
        REQUIRE(wall.mSolver.Step(1.0e-3).IsValid());
    CHECK(wall.mSolver.GetBrokenLinkCount() == 0);
    CHECK(wall.mSolver.ComputeFragments().size() == 1u);
}

TEST_CASE("Fracture: an unbreakable material builds no links and reports one piece", "[fem]")
{
    TetGridSettings grid;
    grid.mCellCount = {2, 2, 2};
    TetSolver solver = TetSolver::Create(TetGrid(grid).Get(), FemMaterialSettings{}, TetSolverSettings{}).Get();
    CHECK(solver.GetFractureLinks().GetLinkCount() == 0);
    CHECK(solver.GetBrokenLinks().empty());
    CHECK(solver.GetGroupPrincipalStress().empty());
    CHECK(solver.ComputeFragments().size() == 1u);
}

TEST_CASE("Fracture: cubes that touch only along an edge are separate pieces for a breakable material", "[fem]")
{
    TetGridSettings grid;
    grid.mSize = Vec3(2.0, 2.0, 1.0);
    grid.mCellCount = {2, 2, 1};
    const TetMesh mesh = TetGridCells(grid, std::vector<std::uint8_t>{1, 0, 0, 1}).Get();
    // Unbreakable: one piece through the shared edge. Breakable: no face joins them, so two pieces with
    // their own nodes from the start, and the first crack elsewhere changes nothing about them.
    TetSolver whole = TetSolver::Create(mesh, FemMaterialSettings{}, TetSolverSettings{}).Get();
    CHECK(whole.GetNodeCount() == 14);
    CHECK(whole.ComputeFragments().size() == 1u);
    TetSolver breakable = TetSolver::Create(mesh, BrittleMaterial(EFractureMode::CrackPlane), TetSolverSettings{}).Get();
    CHECK(breakable.GetNodeCount() == 16);
    const std::vector<TetFragment> pieces = breakable.ComputeFragments();
    REQUIRE(pieces.size() == 2u);
    CHECK(pieces[0].mNodes.size() == 8u);
    CHECK(pieces[1].mNodes.size() == 8u);
}

TEST_CASE("Stress: random impulses on a breakable wall never produce NaN and conserve mass", "[fem]")
{
    Wall wall = MakeWall(TetSolverSettings{}.mIntegrator); // the defaults
    std::mt19937_64 random(20261123);
    int previous_nodes = wall.mSolver.GetNodeCount();
    int fractured = 0;
    for (int step = 0; step < 60; ++step)
    {
        // One impulse of 1e-3 ... 1e5 N s (log-uniform) on a random node in a random direction.
        const double magnitude = std::pow(10.0, -3.0 + 8.0 * static_cast<double>(random() >> 11) * 0x1.0p-53);
        Vec3 direction(static_cast<double>(random() % 2001) - 1000.0, static_cast<double>(random() % 2001) - 1000.0,
                       static_cast<double>(random() % 2001) - 1000.0);
        direction = direction.norm() > 0.0 ? Vec3(direction.normalized()) : Vec3(Vec3::UnitY());
        const int node = static_cast<int>(random() % static_cast<std::uint64_t>(wall.mSolver.GetNodeCount()));
        REQUIRE(wall.mSolver.ApplyImpulse(node, magnitude * direction).IsValid());
        const Result<TetStepResult> result = wall.mSolver.Step(1.0 / 30.0);
        REQUIRE(result.IsValid());
        fractured += HasEvent(result.Get().mEvents, ETetStepEvent::Fractured) ? 1 : 0;
        for (const Vec3& x : wall.mSolver.GetPositions())
            REQUIRE(IsFinite(x));
        CHECK(wall.mSolver.GetNodeCount() >= previous_nodes);
        previous_nodes = wall.mSolver.GetNodeCount();
    }
    REQUIRE(fractured > 0); // the run did exercise node duplication

    // Node duplication shares each rest node's lumped mass among its copies: the copies of every rest node
    // (found by rest position) weigh what the node weighed in the intact mesh.
    const std::vector<double> intact = LumpedNodeMass(wall.mSolver.GetMesh(), 2000.0).Get();
    std::vector<double> shared(intact.size(), 0.0);
    const std::vector<Vec3>& rest = wall.mSolver.GetMesh().GetRestPositions();
    for (int node = 0; node < wall.mSolver.GetNodeCount(); ++node)
    {
        const auto origin = std::find(rest.begin(), rest.end(), wall.mSolver.GetNodeRestPositions()[node]);
        REQUIRE(origin != rest.end());
        shared[origin - rest.begin()] += wall.mSolver.GetMasses()[node];
    }
    for (std::size_t node = 0; node < intact.size(); ++node)
        CHECK(shared[node] == Approx(intact[node]).epsilon(1e-12));
    double mass = 0.0;
    for (const TetFragment& fragment : wall.mSolver.ComputeFragments())
        mass += fragment.mMass;
    CHECK(mass == Approx(2000.0 * 2.0 * 0.2 * 1.0).epsilon(1e-12));
    double node_mass = 0.0;
    for (double m : wall.mSolver.GetMasses())
        node_mass += m;
    CHECK(node_mass == Approx(mass).epsilon(1e-12));
}
