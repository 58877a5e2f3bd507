// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// CPU and GPU behind one prop: a CPU prop never makes a context, a GPU prop without EGL (or with a feature
// the GPU lacks) runs on the CPU with its reason logged and visible, and bad input is an error either way.
#include <crumple/fem/TetGrid.h>
#include <crumple/props/FemProp.h>
#include <crumple/props/HeldFemProp.h>
#if defined(CRUMPLE_TEST_PROPS_WITH_GPU)
#include <crumple/gpu/ComputeDevice.h>
#endif

#include "GpuFallback.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

using namespace crumple;
using namespace crumple::fem;
using namespace crumple::props;

namespace
{

// The scene's device provider where the build has crumple::gpu; none elsewhere (a GPU request then runs on the
// CPU with the reason that the build has no GPU backend).
#if defined(CRUMPLE_TEST_PROPS_WITH_GPU)
struct Devices
{
    gpu::ComputeDeviceProvider mProvider;
    gpu::ComputeDeviceProvider* Get() { return &mProvider; }
    bool HasTried() const { return mProvider.HasTried(); }
};
#else
struct Devices
{
    gpu::ComputeDeviceProvider* Get() { return nullptr; }
    bool HasTried() const { return false; }
};
#endif

TetMesh Bar()
{
    TetGridSettings grid;
    grid.mSize = Vec3(0.6, 0.2, 0.2);
    grid.mCellCount = {6, 2, 2};
    return TetGrid(grid).Get();
}

FemMaterialSettings Soft()
{
    FemMaterialSettings material;
    material.mYoungsModulus = 1.0e7;
    material.mMassDamping = 1.0;
    return material;
}

TetSolverSettings Explicit()
{
    TetSolverSettings settings;
    settings.mIntegrator = EIntegrator::SymplecticEuler;
    return settings;
}

} // namespace

TEST_CASE("FemProp on the CPU never touches the device provider", "[props]")
{
    Devices provider;
    Result<FemProp> prop = FemProp::Create(provider.Get(), Bar(), Soft(), Explicit(), FemPropSettings{});
    REQUIRE(prop.IsValid());
    CHECK(prop.Get().GetBackend() == EFemBackend::Cpu);
    CHECK(prop.Get().GetFallbackReason().empty());
    REQUIRE(prop.Get().Step(1.0 / 60.0).IsValid());
    CHECK_FALSE(provider.HasTried()); // no EGL context for a scene without GPU props
}

TEST_CASE("FemProp asking for the GPU without EGL runs on the CPU, logs why, and steps like the CPU solver",
          "[props]")
{
    ::setenv("CRUMPLE_DISABLE_EGL", "1", 1);
    Devices provider;
    std::vector<std::string> log;
    FemPropSettings settings;
    settings.mBackend = EFemBackend::Gpu;
    settings.mLog = [&](std::string_view inMessage) { log.emplace_back(inMessage); };
    Result<FemProp> prop = FemProp::Create(provider.Get(), Bar(), Soft(), Explicit(), settings);
    ::unsetenv("CRUMPLE_DISABLE_EGL");
    REQUIRE(prop.IsValid());
    CHECK(prop.Get().GetBackend() == EFemBackend::Cpu);
#if defined(CRUMPLE_TEST_PROPS_WITH_GPU)
    CHECK(HasGpuBackend());
    CHECK(prop.Get().GetFallbackReason().find("CRUMPLE_DISABLE_EGL") != std::string::npos);
#else
    CHECK_FALSE(HasGpuBackend());
    CHECK(prop.Get().GetFallbackReason().find("no GPU backend") != std::string::npos);
#endif
    REQUIRE(log.size() == 1u);
    CHECK(log[0].find("running on the CPU") != std::string::npos);

    // The fallback is the CPU solver itself: bitwise the same states.
    TetSolver plain = TetSolver::Create(Bar(), Soft(), Explicit()).Get();
    REQUIRE(prop.Get().ApplyImpulse(20, Vec3(0.0, 0.0, 1.0)).IsValid());
    REQUIRE(plain.ApplyImpulse(20, Vec3(0.0, 0.0, 1.0)).IsValid());
    for (int step = 0; step < 5; ++step)
    {
        REQUIRE(prop.Get().Step(1.0 / 60.0).IsValid());
        REQUIRE(plain.Step(1.0 / 60.0).IsValid());
    }
    std::vector<Vec3> positions;
    prop.Get().ReadPositions(positions);
    CHECK(positions == plain.GetPositions());
}

TEST_CASE(
    "FemProp on the GPU takes what the CPU takes (plastic, implicit, either model), and refuses bad input",
    "[props]")
{
    Devices provider;
    FemPropSettings settings;
    settings.mBackend = EFemBackend::Gpu;
    for (const EElasticModel model : {EElasticModel::CorotatedLinear, EElasticModel::StVenantKirchhoff})
        for (const TetSolverSettings& solver : {Explicit(), TetSolverSettings{}})
        {
            CAPTURE(ToString(model), ToString(solver.mIntegrator));
            FemMaterialSettings material = Soft();
            material.mModel = model;
            material.mYieldStress = 1.0e5;
            Result<FemProp> prop = FemProp::Create(provider.Get(), Bar(), material, solver, settings);
            REQUIRE(prop.IsValid());
            if (prop.Get().GetBackend() != EFemBackend::Gpu)
            {
                // Only without a device (the test above covers that fallback).
                test::RequireNoComputeDevice(provider.Get(), prop.Get().GetFallbackReason());
                WARN("no compute device: " << prop.Get().GetFallbackReason());
                CHECK(prop.Get().GetFallbackReason().find("implement") == std::string::npos);
                continue;
            }
            CHECK(prop.Get().GetFallbackReason().empty());
            REQUIRE(prop.Get().Step(1.0 / 60.0).IsValid());
        }

    FemMaterialSettings negative = Soft();
    negative.mDensity = -1.0;
    CHECK(FemProp::Create(provider.Get(), Bar(), negative, Explicit(), settings).HasError());
    CHECK(FemProp::Create(nullptr, Bar(), negative, Explicit(), FemPropSettings{}).HasError());
}

TEST_CASE("FemProp on the GPU steps like the CPU within float limits, explicit and implicit", "[props]")
{
    Devices provider;
    FemPropSettings settings;
    settings.mBackend = EFemBackend::Gpu;
    const TetSolverSettings solver = GENERATE(Explicit(), TetSolverSettings{});
    CAPTURE(ToString(solver.mIntegrator));
    Result<FemProp> prop = FemProp::Create(provider.Get(), Bar(), Soft(), solver, settings);
    REQUIRE(prop.IsValid());
    if (prop.Get().GetBackend() != EFemBackend::Gpu)
    {
        test::RequireNoComputeDevice(provider.Get(), prop.Get().GetFallbackReason());
        WARN("skipped: no compute device: " << prop.Get().GetFallbackReason());
        return;
    }
    TetSolver plain = TetSolver::Create(Bar(), Soft(), solver).Get();
    REQUIRE(prop.Get().ApplyImpulse(20, Vec3(0.0, 0.0, 1.0)).IsValid());
    REQUIRE(plain.ApplyImpulse(20, Vec3(0.0, 0.0, 1.0)).IsValid());
    for (int step = 0; step < 5; ++step)
    {
        REQUIRE(prop.Get().Step(1.0 / 60.0).IsValid());
        REQUIRE(plain.Step(1.0 / 60.0).IsValid());
    }
    std::vector<Vec3> positions;
    prop.Get().ReadPositions(positions);
    double gap = 0.0, motion = 0.0;
    for (std::size_t node = 0; node < positions.size(); ++node)
    {
        gap = std::max(gap, (positions[node] - plain.GetPositions()[node]).norm());
        motion = std::max(motion, (plain.GetPositions()[node] - plain.GetMesh().GetRestPositions()[node]).norm());
    }
    INFO("gap " << gap << " m over " << motion << " m of motion");
    REQUIRE(motion > 1.0e-3);
    CHECK(gap < 1.0e-3 * motion);
}

TEST_CASE("FemProp takes a dispatched collision on either backend and reports its pieces", "[props]")
{
    // The same collision on a CPU prop and on a GPU prop (where there is one) moves them alike.
    plugin::Collision collision;
    collision.mBodyA = plugin::BodyId{2};
    collision.mBodyB = plugin::BodyId{5};
    plugin::CollisionContact contact;
    contact.mLocalPointOnA = Vec3(0.55, 0.1, 0.2); // on the bar's top face near its end
    contact.mLocalNormalOnA = Vec3(0.0, 0.0, -1.0);
    contact.mImpulse = 2.0;
    collision.mContacts.push_back(contact);

    Devices provider;
    std::vector<std::vector<Vec3>> results;
    for (EFemBackend backend : {EFemBackend::Cpu, EFemBackend::Gpu})
    {
        FemPropSettings settings;
        settings.mBackend = backend;
        Result<FemProp> prop = FemProp::Create(provider.Get(), Bar(), Soft(), Explicit(), settings);
        REQUIRE(prop.IsValid());
        if (prop.Get().GetBackend() != backend)
        {
            test::RequireNoComputeDevice(provider.Get(), prop.Get().GetFallbackReason());
            WARN("GPU case skipped: " << prop.Get().GetFallbackReason());
            break;
        }
        CHECK(prop.Get().ApplyCollision(collision, plugin::BodyId{7}).HasError()); // not this prop's collision
        REQUIRE(prop.Get().ApplyCollision(collision, plugin::BodyId{2}).IsValid());
        REQUIRE(prop.Get().Step(1.0 / 60.0).IsValid());
        CHECK(prop.Get().ComputeFragments().size() == 1u);
        std::vector<Vec3> positions;
        prop.Get().ReadPositions(positions);
        results.push_back(positions);
    }
    REQUIRE_FALSE(results.empty());
    // The free bar (no anchors) was pushed down: its nodes moved down on the whole.
    double drop = 0.0;
    for (std::size_t node = 0; node < results[0].size(); ++node)
        drop += results[0][node].z() - Bar().GetRestPositions()[node].z();
    CHECK(drop < -1.0e-6);
    if (results.size() == 2)
        for (std::size_t node = 0; node < results[0].size(); ++node)
            CHECK((results[1][node] - results[0][node]).norm() < 1e-5);
}

TEST_CASE("MakeHeldFemProp on the GPU: anchored as on the CPU, a struck wall moves as the CPU's", "[props]")
{
    Devices provider;
    // A 1 m x 0.2 m x 1 m wall of 0.2 m cubes standing on its footings (z = 0), the held prop's implicit
    // solver.
    TetGridSettings grid;
    grid.mSize = Vec3(1.0, 0.2, 1.0);
    grid.mCellCount = {5, 1, 5};
    const TetMesh mesh = TetGrid(grid).Get();
    std::vector<int> footings;
    for (int node = 0; node < mesh.GetNodeCount(); ++node)
        if (mesh.GetRestPositions()[static_cast<std::size_t>(node)].z() < 1.0e-9)
            footings.push_back(node);
    FemMaterialSettings material = Soft();
    Result<FemProp> on_gpu = MakeHeldFemProp(mesh, material, footings, HeldPropSolverSettings(), 0.0,
                                             {.mBackend = EFemBackend::Gpu, .mLog = nullptr}, provider.Get());
    REQUIRE(on_gpu.IsValid());
    if (on_gpu.Get().GetBackend() != EFemBackend::Gpu)
    {
        test::RequireNoComputeDevice(provider.Get(), on_gpu.Get().GetFallbackReason());
        WARN("skipped: no compute device: " << on_gpu.Get().GetFallbackReason());
        return;
    }
    FemProp on_cpu = MakeHeldFemProp(mesh, material, footings).Get();
    REQUIRE(on_cpu.GetBackend() == EFemBackend::Cpu);
    CHECK(on_gpu.Get().GetInverseMasses() ==
          on_cpu.GetInverseMasses()); // the footings, and only they, anchored
    CHECK(std::count(on_cpu.GetInverseMasses().begin(), on_cpu.GetInverseMasses().end(), 0.0) ==
          static_cast<std::ptrdiff_t>(footings.size()));

    const int struck = mesh.GetNodeCount() - 1; // a top corner
    for (FemProp* prop : {&on_gpu.Get(), &on_cpu})
    {
        REQUIRE(prop->ApplyImpulse(struck, Vec3(0.0, 20.0, 0.0)).IsValid());
        for (int step = 0; step < 10; ++step)
            REQUIRE(prop->Step(1.0 / 60.0).IsValid());
    }
    std::vector<Vec3> gpu_positions, cpu_positions;
    on_gpu.Get().ReadPositions(gpu_positions);
    on_cpu.ReadPositions(cpu_positions);
    double gap = 0.0, motion = 0.0;
    for (std::size_t node = 0; node < gpu_positions.size(); ++node)
    {
        gap = std::max(gap, (gpu_positions[node] - cpu_positions[node]).norm());
        motion = std::max(motion, (cpu_positions[node] - mesh.GetRestPositions()[node]).norm());
    }
    INFO("gap " << gap << " m over " << motion << " m of motion");
    REQUIRE(motion > 1.0e-3);
    CHECK(gap < 1.0e-3 * motion); // float against double, as the bar above
}

namespace
{

// A bar and, overlapping its top, a second bar raised 0.13 m and shifted 0.05 m along x: the second stands
// for a piece that broke off the first and froze where it was when it left (its nodes fixed), as a piece
// handed over does. Nodes of the bar first, then the piece's.
struct BarAndFrozenPiece
{
    TetMesh mMesh;
    std::vector<int> mPieceNodes;
};

BarAndFrozenPiece MakeBarAndFrozenPiece()
{
    const TetMesh bar = Bar();
    std::vector<Vec3> positions = bar.GetRestPositions();
    std::vector<TetIndices> tets = bar.GetTets();
    const int offset = bar.GetNodeCount();
    std::vector<int> piece;
    for (int node = 0; node < bar.GetNodeCount(); ++node)
    {
        positions.push_back(bar.GetRestPositions()[static_cast<std::size_t>(node)] + Vec3(0.05, 0.0, 0.13));
        piece.push_back(offset + node);
    }
    for (TetIndices tet : bar.GetTets())
    {
        for (int& node : tet)
            node += offset;
        tets.push_back(tet);
    }
    return {TetMesh::Create(std::move(positions), std::move(tets)).Get(), std::move(piece)};
}

} // namespace

TEST_CASE("FemProp: a collision lands on what is left of the prop, not on a piece that left it", "[props]")
{
    // A contact on the bar's top face, which lies strictly inside an element of the frozen piece: its best
    // element is the piece's, and before SetNodesLeft the impulse vanished into the piece's fixed nodes.
    plugin::Collision collision;
    collision.mBodyA = plugin::BodyId{2};
    collision.mBodyB = plugin::BodyId{5};
    plugin::CollisionContact contact;
    contact.mLocalPointOnA = Vec3(0.533, 0.067, 0.2);
    contact.mLocalNormalOnA = Vec3(0.0, 0.0, -1.0);
    contact.mImpulse = 2.0;
    collision.mContacts.push_back(contact);
    const BarAndFrozenPiece scene = MakeBarAndFrozenPiece();
    const auto bar_momentum = [&](const FemProp& inProp)
    {
        std::vector<Vec3> velocities;
        inProp.ReadVelocities(velocities);
        Vec3 momentum = Vec3::Zero();
        for (std::size_t node = 0; node < static_cast<std::size_t>(scene.mPieceNodes.front()); ++node)
            momentum += inProp.GetMasses()[node] * velocities[node];
        return momentum;
    };

    Result<FemProp> fixed_only = FemProp::Create(nullptr, scene.mMesh, Soft(), Explicit(), FemPropSettings{});
    REQUIRE(fixed_only.IsValid());
    REQUIRE(fixed_only.Get().SetNodesFixed(scene.mPieceNodes, true).IsValid());
    REQUIRE(fixed_only.Get().ApplyCollision(collision, plugin::BodyId{2}).IsValid());
    CHECK(bar_momentum(fixed_only.Get()).norm() < 1.0e-12); // the old way: lost in the piece's fixed nodes

    Result<FemProp> left = FemProp::Create(nullptr, scene.mMesh, Soft(), Explicit(), FemPropSettings{});
    REQUIRE(left.IsValid());
    REQUIRE(left.Get().SetNodesLeft(scene.mPieceNodes).IsValid());
    std::vector<NodalImpulse> applied;
    REQUIRE(left.Get().ApplyCollision(collision, plugin::BodyId{2}, &applied).IsValid());
    // The bar takes the whole impulse, on its own nodes, and the piece's nodes stay fixed.
    CHECK((bar_momentum(left.Get()) - Vec3(0.0, 0.0, -2.0)).norm() < 1.0e-12);
    for (const NodalImpulse& impulse : applied)
        CHECK(impulse.mNode < scene.mPieceNodes.front());
    CHECK(left.Get().GetInverseMasses()[static_cast<std::size_t>(scene.mPieceNodes.back())] == 0.0);

    SECTION("a prop all of whose material left takes nothing, and a node out of range changes nothing")
    {
        std::vector<int> all(static_cast<std::size_t>(scene.mMesh.GetNodeCount()));
        for (std::size_t node = 0; node < all.size(); ++node)
            all[node] = static_cast<int>(node);
        Result<FemProp> gone = FemProp::Create(nullptr, scene.mMesh, Soft(), Explicit(), FemPropSettings{});
        REQUIRE(gone.IsValid());
        CHECK(gone.Get().SetNodesLeft(std::vector<int>{0, scene.mMesh.GetNodeCount()}).HasError());
        CHECK(gone.Get().GetInverseMasses()[0] > 0.0); // refused whole: node 0 not fixed
        std::vector<NodalImpulse> taken;
        REQUIRE(gone.Get().ApplyCollision(collision, plugin::BodyId{2}, &taken).IsValid());
        CHECK(taken.size() == 4u); // nothing left yet: the collision lands
        REQUIRE(gone.Get().SetNodesLeft(all).IsValid());
        std::vector<NodalImpulse> none;
        REQUIRE(gone.Get().ApplyCollision(collision, plugin::BodyId{2}, &none).IsValid());
        CHECK(none.empty());
    }
}
