// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/base/Crc32.h>
#include <crumple/fem/TetGrid.h>
#include <crumple/fem/TetSolver.h>

#include <catch2/catch.hpp>

#include <cstring>
#include <limits>
#include <span>
#include <string>

using namespace crumple;
using namespace crumple::fem;

namespace
{

constexpr double cNaN = std::numeric_limits<double>::quiet_NaN();

TetMesh SmallBox()
{
    TetGridSettings grid;
    grid.mSize = Vec3(0.3, 0.2, 0.1);
    grid.mCellCount = {3, 2, 1};
    return TetGrid(grid).Get();
}

// Everything observable about a solver's state.
struct Snapshot
{
    std::vector<Vec3> mPositions;
    std::vector<Vec3> mVelocities;
    std::vector<Vec3> mForces;
    std::vector<double> mInverseMasses;
    std::uint64_t mWork = 0;
    bool mSleeping = false;

    explicit Snapshot(const TetSolver& inSolver)
        : mPositions(inSolver.GetPositions()), mVelocities(inSolver.GetVelocities()),
          mForces(inSolver.GetExternalForces()), mInverseMasses(inSolver.GetInverseMasses()),
          mWork(inSolver.GetElementWorkCount()), mSleeping(inSolver.IsSleeping())
    {
    }
    bool operator==(const Snapshot& inOther) const
    {
        return mPositions == inOther.mPositions && mVelocities == inOther.mVelocities &&
               mForces == inOther.mForces && mInverseMasses == inOther.mInverseMasses &&
               mWork == inOther.mWork && mSleeping == inOther.mSleeping;
    }
};

// CRC of positions and velocities, the golden-hash style fingerprint of a run.
std::uint32_t StateHash(const TetSolver& inSolver)
{
    std::vector<double> values;
    for (const Vec3& p : inSolver.GetPositions())
        values.insert(values.end(), {p.x(), p.y(), p.z()});
    for (const Vec3& v : inSolver.GetVelocities())
        values.insert(values.end(), {v.x(), v.y(), v.z()});
    return Crc32(std::as_bytes(std::span<const double>(values)));
}

} // namespace

TEST_CASE("TetSolver::Create refuses bad material and settings, naming the field", "[fem]")
{
    const TetMesh mesh = SmallBox();
    struct MaterialCase
    {
        double mYoung, mPoisson, mDensity;
        const char* mNeedle;
    };
    for (const MaterialCase& c :
         {MaterialCase{cNaN, 0.3, 1000.0, "mYoungsModulus = nan"},
          MaterialCase{-2.0e11, 0.3, 7850.0, "mYoungsModulus = -2e+11 Pa: must be > 0"},
          MaterialCase{2.0e11, 0.5, 7850.0, "mPoissonRatio = 0.5"},
          MaterialCase{2.0e11, 0.62, 7850.0, "mPoissonRatio = 0.62"},
          MaterialCase{2.0e11, 0.3, -1.0, "mDensity = -1 kg/m^3"},
          MaterialCase{2.0e11, 0.3, 0.0, "mDensity = 0 kg/m^3"}})
    {
        FemMaterialSettings material;
        material.mYoungsModulus = c.mYoung;
        material.mPoissonRatio = c.mPoisson;
        material.mDensity = c.mDensity;
        Result<TetSolver> solver = TetSolver::Create(mesh, material, TetSolverSettings());
        REQUIRE(solver.HasError());
        INFO(solver.GetError().mMessage);
        CHECK(solver.GetError().mMessage.find(c.mNeedle) != std::string::npos);
    }

    auto refused = [&](auto inChange, const char* inNeedle)
    {
        TetSolverSettings settings;
        inChange(settings);
        Result<TetSolver> solver = TetSolver::Create(mesh, FemMaterialSettings(), settings);
        REQUIRE(solver.HasError());
        INFO(solver.GetError().mMessage);
        CHECK(solver.GetError().mMessage.find(inNeedle) != std::string::npos);
    };
    refused([](TetSolverSettings& s) { s.mGravity.y() = cNaN; }, "mGravity");
    refused([](TetSolverSettings& s) { s.mStabilitySafetyFactor = 1.5; }, "mStabilitySafetyFactor = 1.5");
    refused([](TetSolverSettings& s) { s.mStabilitySafetyFactor = 0.0; }, "mStabilitySafetyFactor = 0");
    refused([](TetSolverSettings& s) { s.mMaxSubSteps = 0; }, "mMaxSubSteps");
    refused([](TetSolverSettings& s) { s.mCgRelativeTolerance = 0.0; }, "mCgRelativeTolerance");
    refused([](TetSolverSettings& s) { s.mCgMaxIterations = 0; }, "mCgMaxIterations");
    refused([](TetSolverSettings& s) { s.mImplicitMaxIterations = 0; }, "mImplicitMaxIterations");
    refused([](TetSolverSettings& s) { s.mSleepSpeed = -1.0; }, "mSleepSpeed");
    refused([](TetSolverSettings& s) { s.mSleepStepCount = 0; }, "mSleepStepCount");
    refused([](TetSolverSettings& s) { s.mDivergenceEnergyRatio = 1.0; }, "mDivergenceEnergyRatio = 1");
    refused([](TetSolverSettings& s) { s.mMaxStepSplits = -1; }, "mMaxStepSplits");
    refused([](TetSolverSettings& s) { s.mIntegrator = static_cast<EIntegrator>(9); }, "mIntegrator");
    // Found by a bad-input audit: accepted before, and stepped past every velocity bound (gravity 1e150
    // m/s^2) or treated as block Jacobi (an unknown preconditioner)
    refused([](TetSolverSettings& s) { s.mGravity.z() = -1.0e150; }, "mGravity beyond 1e100");
    refused([](TetSolverSettings& s) { s.mPreconditioner = static_cast<EImplicitPreconditioner>(7); },
            "mPreconditioner");

    // Meshes a step cannot hold (found by the same audit: accepted, then every step diverged to NaN): one
    // element 1e-105 m across has subnormal node masses, one 1e40 m across (1e102 m in the audit) masses past
    // what a step holds (1e100 kg), and
    // a node beyond 1e100 m overflowed the volume and was refused as degenerate.
    const auto one_tet = [](double inSize)
    {
        return TetMesh::Create(
            {Vec3::Zero(), Vec3(inSize, 0.0, 0.0), Vec3(0.0, inSize, 0.0), Vec3(0.0, 0.0, inSize)},
            {TetIndices{0, 1, 2, 3}});
    };
    for (const double size : {1.0e-105, 1.0e40})
    {
        INFO("an element " << size << " m across");
        REQUIRE(one_tet(size));
        const Result<TetSolver> solver =
            TetSolver::Create(one_tet(size).Get(), FemMaterialSettings(), TetSolverSettings());
        REQUIRE(solver.HasError());
        CHECK(solver.GetError().mCode == EError::DegenerateGeometry);
        CHECK(solver.GetError().mMessage.find("mass") != std::string::npos);
    }
    CHECK(TetSolver::Create(one_tet(1.0e-3).Get(), FemMaterialSettings(), TetSolverSettings()));
    CHECK(one_tet(1.0e101).GetError().mCode == EError::OutOfRange);
}

TEST_CASE("TetSolver refuses bad input and changes nothing", "[fem]")
{
    TetSolver solver = TetSolver::Create(SmallBox(), FemMaterialSettings(), TetSolverSettings()).Get();
    REQUIRE(solver.SetNodeFixed(0, true).IsValid());
    REQUIRE(solver.ApplyImpulse(5, Vec3(0.0, 0.0, 1.0)).IsValid());
    REQUIRE(solver.Step(1.0 / 60.0).IsValid());
    const int n = solver.GetMesh().GetNodeCount();
    const Snapshot before(solver);

    auto expect = [&](const Status& inStatus, EError inCode, const char* inNeedle)
    {
        REQUIRE(inStatus.HasError());
        INFO(inStatus.GetError().mMessage);
        CHECK(inStatus.GetError().mCode == inCode);
        CHECK(inStatus.GetError().mMessage.find(inNeedle) != std::string::npos);
        CHECK(Snapshot(solver) == before);
    };
    expect(solver.ApplyImpulse(n, Vec3::UnitX()), EError::OutOfRange, "node 24 is outside [0, 24)");
    expect(solver.ApplyImpulse(-1, Vec3::UnitX()), EError::OutOfRange, "node -1");
    expect(solver.ApplyImpulse(3, Vec3(cNaN, 0.0, 0.0)), EError::NonFinite,
           "impulse on node 3 must be finite");
    expect(solver.SetExternalForce(3, Vec3(0.0, std::numeric_limits<double>::infinity(), 0.0)),
           EError::NonFinite, "force on node 3");
    expect(solver.SetExternalForce(99, Vec3::Zero()), EError::OutOfRange, "node 99");
    expect(solver.SetNodeFixed(n + 3, true), EError::OutOfRange, "SetNodeFixed");
    expect(solver.SetGravity(Vec3(0.0, 0.0, cNaN)), EError::NonFinite, "gravity");
    std::vector<Vec3> positions = solver.GetPositions();
    positions[7].z() = cNaN;
    expect(solver.SetPositions(positions), EError::NonFinite, "positions must be finite");
    positions.pop_back();
    expect(solver.SetPositions(positions), EError::InvalidArgument, "23 positions for 24 nodes");
    expect(solver.SetVelocities(std::vector<Vec3>(3, Vec3::Zero())), EError::InvalidArgument, "3 velocities");

    for (double step_time : {0.0, -0.01, cNaN, std::numeric_limits<double>::infinity()})
    {
        Result<TetStepResult> result = solver.Step(step_time);
        REQUIRE(result.HasError());
        CHECK(result.GetError().mMessage.find("must be finite and > 0") != std::string::npos);
        CHECK(Snapshot(solver) == before);
    }
}

TEST_CASE("SetNodesFixed is SetNodeFixed node by node, and refuses a bad node changing nothing", "[fem]")
{
    TetSolverSettings settings;
    settings.mIntegrator = EIntegrator::SymplecticEuler;
    TetSolver one_by_one = TetSolver::Create(SmallBox(), FemMaterialSettings{}, settings).Get();
    for (int node = 0; node < one_by_one.GetNodeCount(); ++node)
        REQUIRE(one_by_one.ApplyImpulse(node, Vec3(0.01 * node, -0.02, 0.03)));
    TetSolver together = one_by_one;
    // A piece's nodes as a prop hands them over: unordered, one of them fixed twice, then some freed again.
    const std::vector<int> piece{7, 2, 11, 2, 5, 0};
    for (int node : piece)
        REQUIRE(one_by_one.SetNodeFixed(node, true));
    REQUIRE(together.SetNodesFixed(piece, true));
    CHECK(Snapshot(together) == Snapshot(one_by_one));
    const std::vector<int> freed{11, 0};
    for (int node : freed)
        REQUIRE(one_by_one.SetNodeFixed(node, false));
    REQUIRE(together.SetNodesFixed(freed, false));
    CHECK(Snapshot(together) == Snapshot(one_by_one));
    for (int step = 0; step < 5; ++step)
    {
        REQUIRE(one_by_one.Step(1.0e-4));
        REQUIRE(together.Step(1.0e-4));
    }
    CHECK(StateHash(together) == StateHash(one_by_one));

    const Snapshot before(together);
    CHECK(together.SetNodesFixed(std::vector<int>{3, together.GetNodeCount()}, true).GetError().mCode == EError::OutOfRange);
    CHECK(together.SetNodesFixed(std::vector<int>{-1, 4}, true).HasError());
    CHECK(Snapshot(together) == before);
    CHECK(together.SetNodesFixed({}, true)); // nothing to do
    CHECK(Snapshot(together) == before);
}

TEST_CASE("TetSolver refuses a symplectic step beyond mMaxSubSteps and a static solve without anchors",
          "[fem]")
{
    FemMaterialSettings steel;
    steel.mYoungsModulus = 2.0e11;
    steel.mDensity = 7850.0;
    TetSolverSettings settings;
    settings.mIntegrator = EIntegrator::SymplecticEuler;
    TetSolver solver = TetSolver::Create(SmallBox(), steel, settings).Get();
    const Snapshot before(solver);

    // Steel 0.1 m cells: a stable sub-step of ~3e-6 s, so 1/30 s needs ~10,600 > 10,000 sub-steps.
    Result<TetStepResult> result = solver.Step(1.0 / 30.0);
    REQUIRE(result.HasError());
    INFO(result.GetError().mMessage);
    CHECK(result.GetError().mMessage.find("mMaxSubSteps = 10000") != std::string::npos);
    CHECK(Snapshot(solver) == before);

    Result<TetStaticResult> statics = solver.SolveStatic();
    REQUIRE(statics.HasError());
    CHECK(statics.GetError().mMessage.find("no node is fixed") != std::string::npos);
    CHECK(Snapshot(solver) == before);
}

TEST_CASE("An impulse changes a free node's velocity by J / m, an anchored node absorbs it", "[fem]")
{
    TetSolver solver = TetSolver::Create(SmallBox(), FemMaterialSettings(), TetSolverSettings()).Get();
    const Vec3 impulse(0.3, -2.0, 1.5);
    REQUIRE(solver.ApplyImpulse(9, impulse).IsValid());
    CHECK((solver.GetVelocities()[9] - impulse / solver.GetMasses()[9]).norm() < 1e-15);
    CHECK(solver.GetVelocities()[9].norm() == Approx(impulse.norm() * solver.GetInverseMasses()[9]));

    REQUIRE(solver.SetNodeFixed(4, true).IsValid());
    REQUIRE(solver.ApplyImpulse(4, impulse).IsValid());
    CHECK(solver.GetVelocities()[4] == Vec3::Zero());
    CHECK(solver.GetInverseMasses()[4] == 0.0);

    // Anchored nodes never move, whatever the integrator does around them.
    const Vec3 anchored = solver.GetPositions()[4];
    for (int step = 0; step < 30; ++step)
        REQUIRE(solver.Step(1.0 / 60.0).IsValid());
    CHECK(solver.GetPositions()[4] == anchored);

    // Freed again, it has its mass back.
    REQUIRE(solver.SetNodeFixed(4, false).IsValid());
    CHECK(solver.GetInverseMasses()[4] == Approx(1.0 / solver.GetMasses()[4]));
}

TEST_CASE("A free body falls with exactly g t and does not deform, with either integrator", "[fem]")
{
    for (EIntegrator integrator : {EIntegrator::ImplicitEuler, EIntegrator::SymplecticEuler})
    {
        TetSolverSettings settings;
        settings.mIntegrator = integrator;
        TetSolver solver = TetSolver::Create(SmallBox(), FemMaterialSettings(), settings).Get();
        const int steps = 30;
        int pieces = 0;
        for (int step = 0; step < steps; ++step)
        {
            const TetStepResult result = solver.Step(1.0 / 60.0).Get();
            REQUIRE(result.mEvents == ETetStepEvent::None);
            pieces = result.mSubSteps;
        }
        const double expected = -9.81 * steps / 60.0;
        // Exact up to the conjugate-gradient tolerance (1e-6 of each step's velocity change, implicit) or
        // round-off.
        INFO(ToString(integrator));
        for (const Vec3& velocity : solver.GetVelocities())
        {
            CHECK(velocity.z() == Approx(expected).epsilon(1e-6));
            CHECK(std::abs(velocity.x()) + std::abs(velocity.y()) < 1e-6 * std::abs(expected));
        }
        CHECK(solver.ElasticEnergy() < 1e-12);

        // The drop of an integrator that moves with the new velocity, x += h v_{k+1}, over N = steps x pieces
        // (sub-)steps of h: g h^2 N (N + 1) / 2, a first-order error of 1/N against g t^2 / 2.
        const double h = 1.0 / 60.0 / pieces;
        const double n = static_cast<double>(steps) * pieces;
        const double drop = 0.5 * 9.81 * h * h * n * (n + 1.0);
        for (int node = 0; node < solver.GetMesh().GetNodeCount(); ++node)
            CHECK(solver.GetMesh().GetRestPositions()[node].z() - solver.GetPositions()[node].z() ==
                  Approx(drop).epsilon(1e-6));
    }
}

TEST_CASE("TetSolver runs are deterministic: same inputs, bitwise the same states", "[fem]")
{
    for (EIntegrator integrator : {EIntegrator::ImplicitEuler, EIntegrator::SymplecticEuler})
    {
        TetSolverSettings settings;
        settings.mIntegrator = integrator;
        FemMaterialSettings material;
        material.mYoungsModulus = 1.0e7;
        const TetMesh mesh = SmallBox();
        TetSolver a = TetSolver::Create(mesh, material, settings).Get();
        TetSolver b = TetSolver::Create(mesh, material, settings).Get();
        for (TetSolver* solver : {&a, &b})
        {
            REQUIRE(solver->SetNodeFixed(0, true).IsValid());
            REQUIRE(solver->SetNodeFixed(4, true).IsValid());
        }
        for (int step = 0; step < 60; ++step)
        {
            if (step % 10 == 0)
                for (TetSolver* solver : {&a, &b})
                    REQUIRE(solver->ApplyImpulse(23 - step / 10, Vec3(0.5, -0.2, 1.0 + step)).IsValid());
            const TetStepResult ra = a.Step(1.0 / 60.0).Get();
            const TetStepResult rb = b.Step(1.0 / 60.0).Get();
            REQUIRE(ra.mEvents == rb.mEvents);
            REQUIRE(std::memcmp(a.GetPositions().data(), b.GetPositions().data(),
                                a.GetPositions().size() * sizeof(Vec3)) == 0);
            REQUIRE(std::memcmp(a.GetVelocities().data(), b.GetVelocities().data(),
                                a.GetVelocities().size() * sizeof(Vec3)) == 0);
        }
        WARN(ToString(integrator) << ": state hash after 60 steps 0x" << std::hex << StateHash(a));
        CHECK(StateHash(a) == StateHash(b));
    }
}

TEST_CASE("TetSolver::Prepare factors the first step's system ahead and changes no result", "[fem]")
{
    // A steel box anchored at one end, sagging under gravity: the implicit default with the factored rest
    // system. Prepared or not, ten steps end bitwise the same; the prepared one factors before its first step
    // and not again in it.
    const TetMesh mesh = SmallBox();
    FemMaterialSettings steel;
    steel.mYoungsModulus = 2.0e11;
    steel.mDensity = 7850.0;
    const auto make = [&]() {
        TetSolver solver = TetSolver::Create(mesh, steel, TetSolverSettings()).Get();
        for (int node = 0; node < solver.GetNodeCount(); ++node)
            if (mesh.GetRestPositions()[static_cast<std::size_t>(node)].x() < 1e-9)
                REQUIRE(solver.SetNodeFixed(node, true).IsValid());
        return solver;
    };
    TetSolver plain = make(), prepared = make();
    CHECK(prepared.Prepare(cNaN).GetError().mCode == EError::NonFinite);
    CHECK(prepared.Prepare(-1.0 / 60.0).GetError().mCode == EError::InvalidArgument);
    CHECK(Snapshot(prepared) == Snapshot(plain));
    REQUIRE(prepared.Prepare(1.0 / 60.0).IsValid());
    CHECK(prepared.GetFactorizationCount() == 1);
    CHECK(Snapshot(prepared) == Snapshot(plain)); // no state changed, no element work counted
    REQUIRE(prepared.Step(1.0 / 60.0).IsValid());
    CHECK(prepared.GetFactorizationCount() == 1);
    REQUIRE(plain.Step(1.0 / 60.0).IsValid());
    CHECK(plain.GetFactorizationCount() == 1);
    for (int step = 1; step < 10; ++step)
    {
        REQUIRE(plain.Step(1.0 / 60.0).IsValid());
        REQUIRE(prepared.Step(1.0 / 60.0).IsValid());
    }
    CHECK(StateHash(prepared) == StateHash(plain));
    CHECK(prepared.GetPositions() == plain.GetPositions());
}
