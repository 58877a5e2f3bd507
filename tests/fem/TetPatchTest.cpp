// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem/TetGrid.h>
#include <crumple/fem/TetSolver.h>

#include <catch2/catch.hpp>

#include <algorithm>

using namespace crumple;
using namespace crumple::fem;

namespace
{

constexpr int cCells = 3; // 3 x 3 x 3 cells of 0.1 m: 64 nodes, 8 of them interior

// A solver on a 3 x 3 x 3 grid of 0.1 m cells, E = 1e9 Pa, no gravity.
TetSolver MakeBlock(EElasticModel inModel, ECubeSplit inSplit = ECubeSplit::Five)
{
    TetGridSettings grid;
    grid.mOrigin = Vec3(0.2, -0.1, 0.3);
    grid.mSize = Vec3(0.3, 0.3, 0.3);
    grid.mCellCount = {cCells, cCells, cCells};
    grid.mSplit = inSplit;
    FemMaterialSettings material;
    material.mYoungsModulus = 1.0e9;
    material.mPoissonRatio = 0.3;
    material.mModel = inModel;
    TetSolverSettings settings;
    settings.mGravity = Vec3::Zero();
    return TetSolver::Create(TetGrid(grid).Get(), material, settings).Get();
}

bool IsInterior(int inNode)
{
    const int i = inNode % (cCells + 1), j = (inNode / (cCells + 1)) % (cCells + 1),
              k = inNode / ((cCells + 1) * (cCells + 1));
    return i > 0 && i < cCells && j > 0 && j < cCells && k > 0 && k < cCells;
}

// Positions of the affine map x = A X + b applied to the rest positions.
std::vector<Vec3> Affine(const TetSolver& inSolver, const Mat3& inA, const Vec3& inB)
{
    std::vector<Vec3> positions;
    for (const Vec3& rest : inSolver.GetMesh().GetRestPositions())
        positions.push_back(inA * rest + inB);
    return positions;
}

// A random-looking but fixed matrix A = I + inAmplitude * G.
Mat3 Gradient(double inAmplitude)
{
    Mat3 g;
    g << 0.3, -0.7, 0.2, 0.5, 0.1, -0.4, -0.6, 0.8, 0.9;
    return Mat3::Identity() + inAmplitude * g;
}

} // namespace

TEST_CASE("Patch test: an affine deformation gives zero force at interior nodes", "[fem]")
{
    for (EElasticModel model : {EElasticModel::StVenantKirchhoff, EElasticModel::CorotatedLinear})
        for (ECubeSplit split : {ECubeSplit::Five, ECubeSplit::Six})
            for (double amplitude : {1.0e-3, 0.2})
            {
                TetSolver solver = MakeBlock(model, split);
                REQUIRE(solver.SetPositions(Affine(solver, Gradient(amplitude), Vec3(0.05, -0.02, 0.01)))
                            .IsValid());
                std::vector<Vec3> forces;
                solver.ElasticForces(forces);

                // Interior forces vanish relative to the boundary tractions; all forces sum to zero.
                double interior = 0.0, boundary = 0.0;
                Vec3 sum = Vec3::Zero();
                for (int node = 0; node < solver.GetMesh().GetNodeCount(); ++node)
                {
                    (IsInterior(node) ? interior : boundary) =
                        std::max(IsInterior(node) ? interior : boundary, forces[node].norm());
                    sum += forces[node];
                }
                INFO(ToString(model) << (split == ECubeSplit::Five ? " five" : " six") << "-tet, amplitude "
                                     << amplitude << ": max interior |f| " << interior
                                     << " N, max boundary |f| " << boundary << " N");
                CHECK(boundary > 1.0e4);
                CHECK(interior <= 1.0e-9 * boundary);
                CHECK(sum.norm() <= 1.0e-9 * boundary);
            }
}

TEST_CASE("Patch test: with the boundary on a linear field, the static solve puts the interior on it",
          "[fem]")
{
    for (EElasticModel model : {EElasticModel::StVenantKirchhoff, EElasticModel::CorotatedLinear})
        for (double amplitude : {1.0e-3, 0.1})
        {
            // Boundary nodes anchored on the field, interior nodes left at rest.
            TetSolver solver = MakeBlock(model);
            const std::vector<Vec3> target = Affine(solver, Gradient(amplitude), Vec3(0.01, 0.02, -0.03));
            std::vector<Vec3> start = solver.GetMesh().GetRestPositions();
            for (int node = 0; node < solver.GetMesh().GetNodeCount(); ++node)
                if (!IsInterior(node))
                {
                    start[node] = target[node];
                    REQUIRE(solver.SetNodeFixed(node, true).IsValid());
                }
            REQUIRE(solver.SetPositions(start).IsValid());
            Result<TetStaticResult> result = solver.SolveStatic(50, 1.0e-10);
            REQUIRE(result.IsValid());

            double worst = 0.0;
            for (int node = 0; node < solver.GetMesh().GetNodeCount(); ++node)
                worst = std::max(worst, (solver.GetPositions()[node] - target[node]).norm());
            // Exact up to round-off: positions of ~0.5 m carry ~1e-16 m each, far below 1e-8 of the
            // displacement.
            const double displacement = amplitude * 0.3; // of order |A - I| x size
            INFO(ToString(model) << ", amplitude " << amplitude << ": worst interior error " << worst
                                 << " m after " << result.Get().mIterations << " linearisations");
            CHECK(worst <= 1.0e-8 * displacement);
        }
}

TEST_CASE("Rigid motions give zero elastic force, also a 90 degree rotation", "[fem]")
{
    const Mat3 quarter_turn =
        Eigen::AngleAxisd(0.5 * 3.14159265358979323846, Vec3::UnitZ()).toRotationMatrix();
    const Mat3 generic = Eigen::AngleAxisd(2.0944, Vec3(1, 1, 1).normalized()).toRotationMatrix();
    const Mat3 half_turn = Eigen::AngleAxisd(3.1, Vec3(0.3, -1.0, 0.2).normalized()).toRotationMatrix();
    // Force of a 1e-3 strain on one element face (E h^2 eps): the scale "zero" is measured against.
    const double force_scale = 1.0e9 * 0.1 * 0.1 * 1.0e-3;
    for (EElasticModel model : {EElasticModel::StVenantKirchhoff, EElasticModel::CorotatedLinear})
        for (const Mat3& rotation : {Mat3(Mat3::Identity()), quarter_turn, generic, half_turn})
        {
            TetSolver solver = MakeBlock(model);
            REQUIRE(solver.SetPositions(Affine(solver, rotation, Vec3(3.0, -2.0, 5.0))).IsValid());
            std::vector<Vec3> forces;
            solver.ElasticForces(forces);
            double worst = 0.0;
            for (const Vec3& force : forces)
                worst = std::max(worst, force.norm());
            INFO(ToString(model) << ": rotation angle " << Eigen::AngleAxisd(rotation).angle()
                                 << " rad, max |f| " << worst << " N");
            CHECK(worst <= 1.0e-9 * force_scale);
            CHECK(std::abs(solver.ElasticEnergy()) <= 1.0e-12);
        }
}
