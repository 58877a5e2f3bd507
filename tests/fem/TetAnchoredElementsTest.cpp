// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// Elements whose corners are all anchored (a piece handed to the engine and fixed in the prop's solver) cost
// no element work and change nothing: a beam half anchored steps bit for bit as the free half alone.
#include <crumple/fem/TetGrid.h>
#include <crumple/fem/TetSolver.h>

#include <ThreadJobSystem.h>

#include <catch2/catch.hpp>

#include <cstring>
#include <map>
#include <tuple>
#include <vector>

using namespace crumple;
using namespace crumple::fem;

namespace
{

// A 2.4 m x 0.6 m x 0.6 m steel block of 0.1 m cubes (4,320 tetrahedra: enough for the element passes to
// split over two workers).
TetGridSettings Block()
{
    TetGridSettings grid;
    grid.mSize = Vec3(2.4, 0.6, 0.6);
    grid.mCellCount = {24, 6, 6};
    return grid;
}

std::tuple<double, double, double> Key(const Vec3& inPosition)
{
    return {inPosition.x(), inPosition.y(), inPosition.z()};
}

// The solver on inMesh with every node at x >= 1.2 m (the cut, and the whole right half where it exists)
// anchored, its node at (0.4, 0, 0.6) struck.
TetSolver MakeHalfAnchored(const TetMesh& inMesh, EIntegrator inIntegrator)
{
    TetSolverSettings settings;
    settings.mIntegrator = inIntegrator;
    TetSolver solver = TetSolver::Create(inMesh, FemMaterialSettings{}, settings).Get();
    for (int node = 0; node < inMesh.GetNodeCount(); ++node)
    {
        const Vec3& rest = inMesh.GetRestPositions()[static_cast<std::size_t>(node)];
        if (rest.x() >= 1.2 - 1.0e-9)
            REQUIRE(solver.SetNodeFixed(node, true).IsValid());
        if ((rest - Vec3(0.4, 0.0, 0.6)).norm() < 1.0e-9)
            REQUIRE(solver.ApplyImpulse(node, Vec3(0.0, 20.0, -10.0)).IsValid());
    }
    return solver;
}

} // namespace

TEST_CASE("Anchored elements: a half anchored block steps bit for bit as its free half alone, at that half's element work",
          "[fem]")
{
    const TetMesh whole = TetGrid(Block()).Get();
    std::vector<std::uint8_t> left(24 * 6 * 6, 0);
    for (std::size_t cell = 0; cell < left.size(); ++cell)
        left[cell] = cell % 24 < 12 ? 1 : 0;
    const TetMesh half = TetGridCells(Block(), left).Get();
    REQUIRE(2 * half.GetTets().size() == whole.GetTets().size());

    for (EIntegrator integrator : {EIntegrator::SymplecticEuler, EIntegrator::ImplicitEuler})
        for (int threads : {1, 2})
        {
            INFO(ToString(integrator) << ", " << threads << " thread(s)");
            TetSolver anchored = MakeHalfAnchored(whole, integrator);
            TetSolver alone = MakeHalfAnchored(half, integrator);
            // On two workers the whole block's passes split in two pieces and give the skipped elements zero
            // slots; the half alone is too small to split: the gather must add what the serial scatter adds.
            common::ThreadJobSystem jobs(threads);
            anchored.SetJobSystem(&jobs.Get());
            for (int step = 0; step < 5; ++step)
            {
                REQUIRE(anchored.Step(1.0 / 240.0).IsValid());
                REQUIRE(alone.Step(1.0 / 240.0).IsValid());
            }
            // The same element evaluations: the anchored half costs nothing.
            CHECK(anchored.GetElementWorkCount() == alone.GetElementWorkCount());
            CHECK(alone.GetElementWorkCount() > 0);

            // Every node of the free half where it is in the other, bit for bit.
            std::map<std::tuple<double, double, double>, int> in_whole;
            for (int node = 0; node < whole.GetNodeCount(); ++node)
                in_whole[Key(whole.GetRestPositions()[static_cast<std::size_t>(node)])] = node;
            int moved = 0;
            for (int node = 0; node < half.GetNodeCount(); ++node)
            {
                const auto found = in_whole.find(Key(half.GetRestPositions()[static_cast<std::size_t>(node)]));
                REQUIRE(found != in_whole.end());
                const Vec3& a = alone.GetPositions()[static_cast<std::size_t>(node)];
                const Vec3& b = anchored.GetPositions()[static_cast<std::size_t>(found->second)];
                CHECK(std::memcmp(a.data(), b.data(), sizeof(Vec3)) == 0);
                moved += a != half.GetRestPositions()[static_cast<std::size_t>(node)] ? 1 : 0;
            }
            CHECK(moved > 0);

            // The public elastic forces still see every element: the anchors' reactions include the anchored half.
            std::vector<Vec3> forces;
            anchored.ElasticForces(forces);
            CHECK(forces.size() == static_cast<std::size_t>(whole.GetNodeCount()));
        }
}
