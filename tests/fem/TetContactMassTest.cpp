// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// TetSolver::ContactEffectiveMass against what one implicit step does with an impulse (an independent
// computation: the step itself), its limits, and its refusals.
#include <crumple/fem/PropMaterialPreset.h>
#include <crumple/fem/TetFence.h>
#include <crumple/fem/TetGrid.h>
#include <crumple/fem/TetSolver.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <vector>

using namespace crumple;
using namespace crumple::fem;

namespace
{

// A 2 m wooden fence of 10 cm timbers in 5 cm cubes, its footings anchored, no gravity (a held prop's FEM),
// stepped implicitly with the step's solves converged far below the test's tolerance (inNewtonIterations: at
// most so many linearisations per step; 1 is the linearly implicit step, whose response to an impulse is
// exactly the mass's system however far the step moves).
TetSolver MakeFence(EImplicitPreconditioner inPreconditioner, std::vector<int>* outGround = nullptr,
                    int inNewtonIterations = 30)
{
    TetFenceSettings fence;
    fence.mLength = 2.0;
    fence.mHeight = 1.2;
    fence.mThickness = 0.1;
    fence.mCellSize = 0.05;
    fence.mPostSpacing = 2.0;
    const TetFence made = MakeTetFence(fence).Get();
    TetSolverSettings settings;
    settings.mGravity = Vec3::Zero();
    settings.mPreconditioner = inPreconditioner;
    settings.mCgRelativeTolerance = 1.0e-12;
    settings.mCgMaxIterations = 100000;
    settings.mImplicitTolerance = 1.0e-14;
    settings.mImplicitMaxIterations = inNewtonIterations;
    TetSolver solver =
        TetSolver::Create(made.mMesh, MakePropMaterialPreset(EPropMaterial::Wood).Get().mMaterial, settings)
            .Get();
    REQUIRE(solver.SetNodesFixed(made.mGroundNodes, true));
    if (outGround != nullptr)
        *outGround = made.mGroundNodes;
    return solver;
}

// The nodes within inRadius of inPoint that are free, each with a share falling off with distance.
void Footprint(const TetSolver& inSolver, const Vec3& inPoint, double inRadius, std::vector<int>& outNodes,
               std::vector<double>& outShares)
{
    outNodes.clear();
    outShares.clear();
    for (int node = 0; node < inSolver.GetNodeCount(); ++node)
    {
        const double d = (inSolver.GetPositions()[static_cast<std::size_t>(node)] - inPoint).norm();
        if (d < inRadius && inSolver.GetInverseMasses()[static_cast<std::size_t>(node)] > 0.0)
        {
            outNodes.push_back(node);
            outShares.push_back(1.0 + inRadius - d);
        }
    }
    REQUIRE_FALSE(outNodes.empty());
}

// The mass the next step shows: two copies stepped, one after a push of inImpulse (N s) along inDirection
// shared as the shares; the shares' mean velocity along the direction differs by inImpulse / m (the step is
// linear in so small a push about any state).
double MassNextStepShows(const TetSolver& inSolver, const std::vector<int>& inNodes,
                         const std::vector<double>& inShares, const Vec3& inDirection, double inImpulse,
                         double inStep)
{
    TetSolver without = inSolver;
    TetSolver with = inSolver;
    double sum = 0.0;
    for (double share : inShares)
        sum += share;
    const Vec3 d = inDirection.normalized();
    for (std::size_t i = 0; i < inNodes.size(); ++i)
        REQUIRE(with.ApplyImpulse(inNodes[i], inImpulse * inShares[i] / sum * d));
    REQUIRE(without.Step(inStep).IsValid());
    REQUIRE(with.Step(inStep).IsValid());
    double change = 0.0;
    for (std::size_t i = 0; i < inNodes.size(); ++i)
    {
        const auto node = static_cast<std::size_t>(inNodes[i]);
        change += inShares[i] / sum * d.dot(with.GetVelocities()[node] - without.GetVelocities()[node]);
    }
    return inImpulse / change;
}

} // namespace

TEST_CASE("ContactEffectiveMass is the mass one implicit step shows an impulse, and changes nothing", "[fem]")
{
    constexpr double cStep = 1.0 / 120.0;
    for (const EImplicitPreconditioner preconditioner :
         {EImplicitPreconditioner::RestFactorization, EImplicitPreconditioner::BlockJacobi})
    {
        TetSolver solver = MakeFence(preconditioner);
        REQUIRE(solver.Prepare(cStep));
        // Mid-rail, near a post, and the top rail struck obliquely; one node and footprints of 10 and 20 cm.
        const struct
        {
            Vec3 mPoint;
            double mRadius;
            Vec3 mDirection;
        } contacts[] = {{{1.0, 0.0, 0.4}, 0.01, {0, 1, 0}},
                        {{1.0, 0.0, 0.4}, 0.1, {0, 1, 0}},
                        {{0.15, 0.0, 0.4}, 0.2, {0, 1, 0}},
                        {{0.7, 0.1, 0.8}, 0.1, {0.3, -1.0, 0.2}}};
        std::vector<int> nodes;
        std::vector<double> shares;
        for (const auto& contact : contacts)
        {
            Footprint(solver, contact.mPoint, contact.mRadius, nodes, shares);
            const TetSolver untouched = solver;
            const Result<TetContactMass> found =
                solver.ContactEffectiveMass(nodes, shares, contact.mDirection, cStep);
            REQUIRE(found.IsValid());
            REQUIRE(found.Get().mConverged);
            const Result<double> mass = found.Get().mMass;
            // A small impulse keeps the corotated step linear: the step shows the same mass.
            const double shown = MassNextStepShows(solver, nodes, shares, contact.mDirection, 1.0e-3, cStep);
            INFO("at " << contact.mPoint.transpose() << ", radius " << contact.mRadius << ": " << mass.Get()
                       << " kg, one step shows " << shown);
            CHECK(mass.Get() == Approx(shown).epsilon(1.0e-6));
            // More than the struck nodes' own mass (the rail's stiffness and the posts hold them back).
            double lumped = 0.0;
            for (int node : nodes)
                lumped += solver.GetMasses()[static_cast<std::size_t>(node)];
            CHECK(mass.Get() > lumped);
            // Nothing changed: the next step is bitwise the same as an untouched copy's.
            TetSolver after = solver;
            TetSolver reference = untouched;
            REQUIRE(after.ApplyImpulse(nodes[0], Vec3(0.0, 2.0, 0.0)));
            REQUIRE(reference.ApplyImpulse(nodes[0], Vec3(0.0, 2.0, 0.0)));
            REQUIRE(after.Step(cStep).IsValid());
            REQUIRE(reference.Step(cStep).IsValid());
            CHECK(after.GetPositions() == reference.GetPositions());
            CHECK(after.GetVelocities() == reference.GetVelocities());
        }
        // Deformed and moving (after a blow), the mass is still what the next step shows.
        Footprint(solver, {1.0, 0.0, 0.4}, 0.1, nodes, shares);
        for (std::size_t i = 0; i < nodes.size(); ++i)
            REQUIRE(solver.ApplyImpulse(nodes[i], Vec3(0.0, 5.0, 0.0)));
        for (int step = 0; step < 3; ++step)
            REQUIRE(solver.Step(cStep).IsValid());
        const double moving = solver.ContactEffectiveMass(nodes, shares, Vec3::UnitY(), cStep).Get().mMass;
        CHECK(moving ==
              Approx(MassNextStepShows(solver, nodes, shares, Vec3::UnitY(), 1.0e-3, cStep)).epsilon(1.0e-4));
    }
}

TEST_CASE("ContactEffectiveMass: the node's own mass for a vanishing step, more for a longer one, infinite "
          "at an anchor",
          "[fem]")
{
    std::vector<int> ground;
    TetSolver solver = MakeFence(EImplicitPreconditioner::RestFactorization, &ground);
    std::vector<int> nodes;
    std::vector<double> shares;
    Footprint(solver, {1.0, 0.0, 0.4}, 0.01, nodes, shares);
    REQUIRE(nodes.size() == 1u);
    const double own = solver.GetMasses()[static_cast<std::size_t>(nodes[0])];
    // h -> 0: A = M, the node alone. The stiffness damping's h beta K is first order in h (4e-5 of the node's
    // mass at 1 ns), so the limit is taken at 1 ps.
    CHECK(solver.ContactEffectiveMass(nodes, shares, Vec3::UnitY(), 1.0e-12).Get().mMass ==
          Approx(own).epsilon(1.0e-6));
    // Longer steps reach more of the fence and the posts behind it.
    double previous = own;
    for (const double step : {1.0e-4, 1.0e-3, 1.0 / 120.0, 1.0 / 30.0})
    {
        const double mass = solver.ContactEffectiveMass(nodes, shares, Vec3::UnitY(), step).Get().mMass;
        INFO("step " << step << " s: " << mass << " kg");
        CHECK(mass > previous);
        previous = mass;
    }
    // A contact on anchored nodes alone meets the ground.
    const std::vector<int> footing{ground[0], ground[1]};
    const std::vector<double> footing_shares{1.0, 2.0};
    CHECK(solver.ContactEffectiveMass(footing, footing_shares, Vec3::UnitY(), 1.0 / 120.0).Get().mMass ==
          std::numeric_limits<double>::infinity());
    // Shares on anchored nodes take nothing from the free ones' response: the free node alone, weighted by
    // its share of the load (w = 1/3: the mass is 9 times the node's effective mass, as w^2 scales the
    // compliance).
    const double alone = solver.ContactEffectiveMass(nodes, shares, Vec3::UnitY(), 1.0 / 120.0).Get().mMass;
    const std::vector<int> mixed{nodes[0], ground[0]};
    const std::vector<double> mixed_shares{1.0, 2.0};
    CHECK(solver.ContactEffectiveMass(mixed, mixed_shares, Vec3::UnitY(), 1.0 / 120.0).Get().mMass ==
          Approx(9.0 * alone).epsilon(1.0e-9));
}

TEST_CASE("ContactEffectiveMass refuses bad input and changes nothing", "[fem]")
{
    TetSolver solver = MakeFence(EImplicitPreconditioner::RestFactorization);
    const TetSolver before = solver;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::vector<int> node{5};
    const std::vector<double> one{1.0};
    CHECK_FALSE(solver.ContactEffectiveMass(node, one, Vec3::UnitY(), 0.0).IsValid());
    CHECK_FALSE(solver.ContactEffectiveMass(node, one, Vec3::UnitY(), nan).IsValid());
    CHECK_FALSE(solver.ContactEffectiveMass(node, one, Vec3::Zero(), 0.01).IsValid());
    CHECK_FALSE(solver.ContactEffectiveMass(node, one, Vec3(nan, 1.0, 0.0), 0.01).IsValid());
    CHECK_FALSE(
        solver.ContactEffectiveMass(node, std::vector<double>{1.0, 1.0}, Vec3::UnitY(), 0.01).IsValid());
    CHECK_FALSE(solver.ContactEffectiveMass(std::vector<int>{-1}, one, Vec3::UnitY(), 0.01).IsValid());
    CHECK_FALSE(solver.ContactEffectiveMass(std::vector<int>{solver.GetNodeCount()}, one, Vec3::UnitY(), 0.01)
                    .IsValid());
    CHECK_FALSE(solver.ContactEffectiveMass(node, std::vector<double>{-1.0}, Vec3::UnitY(), 0.01).IsValid());
    CHECK_FALSE(solver.ContactEffectiveMass(node, std::vector<double>{nan}, Vec3::UnitY(), 0.01).IsValid());
    CHECK_FALSE(solver.ContactEffectiveMass(node, std::vector<double>{0.0}, Vec3::UnitY(), 0.01).IsValid());
    CHECK_FALSE(solver.ContactEffectiveMass({}, {}, Vec3::UnitY(), 0.01).IsValid());
    CHECK(solver.GetPositions() == before.GetPositions());
    CHECK(solver.GetVelocities() == before.GetVelocities());
    CHECK(solver.GetFactorizationCount() == before.GetFactorizationCount());
}

TEST_CASE("ContactEffectiveMass after a crack: the factor the next step would build, converged", "[fem]")
{
    constexpr double cStep = 1.0 / 120.0;
    // One linearisation per step: the blow moves the rail fast, and a converged step's Newton iterations
    // would move its linearisation away from the start's (4.5 % in the mass here), which is not what is
    // tested.
    TetSolver solver = MakeFence(EImplicitPreconditioner::RestFactorization, nullptr, 1);
    REQUIRE(solver.Prepare(cStep));
    std::vector<int> nodes;
    std::vector<double> shares;
    Footprint(solver, {1.0, 0.0, 0.4}, 0.1, nodes, shares);
    // A blow that cracks the wood: the last step's cracks leave the solver's factor behind its connectivity.
    for (std::size_t i = 0; i < nodes.size(); ++i)
        REQUIRE(solver.ApplyImpulse(nodes[i], Vec3(0.0, 60.0, 0.0)));
    int steps = 0;
    int broken = 0;
    for (; steps < 20 && broken == 0; ++steps)
    {
        REQUIRE(solver.Step(cStep).IsValid());
        broken = solver.GetBrokenLinkCount();
    }
    REQUIRE(broken > 0);
    const int factored_before = solver.GetFactorizationCount();
    const TetContactMass found = solver.ContactEffectiveMass(nodes, shares, Vec3::UnitY(), cStep).Get();
    CHECK(found.mConverged);
    CHECK(found.mIterations <
          100); // the rest factor at moved frames: tens of iterations, not block Jacobi's 1,000s
    CHECK(solver.GetFactorizationCount() == factored_before + 1);
    // It is the mass the next step shows.
    INFO(broken << " links broken after " << steps << " steps");
    CHECK(found.mMass ==
          Approx(MassNextStepShows(solver, nodes, shares, Vec3::UnitY(), 1.0e-3, cStep)).epsilon(1.0e-4));
    // The step that follows reuses the factor the call built: no factorisation more than without the call.
    REQUIRE(solver.Step(cStep).IsValid());
    CHECK(solver.GetFactorizationCount() == factored_before + 1);
}
