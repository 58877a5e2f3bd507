// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// Plasticity on the GPU against the CPU: a bar bent past yield keeps the CPU's permanent set (explicit and
// implicit), a blow-up restores the plastic state with the rest, and an elastic bar keeps none. Runs on
// llvmpipe where no GPU exists; skips without EGL.
#include "GpuTestDevice.h"
#include "GpuTestScenes.h"

#include <crumple/gpu/GpuTetSolver.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <limits>

using namespace crumple;
using namespace crumple::fem;
using namespace crumple::gpu;

namespace
{

// A soft, ductile bar: E 10 MPa, yield at 20 kPa (about 0.2 % strain), flowing at once, damped so it settles.
FemMaterialSettings Ductile()
{
    FemMaterialSettings material = test::SoftBarMaterial();
    material.mMassDamping = 20.0;
    material.mStiffnessDamping = 0.0;
    material.mYieldStress = 2.0e4;
    return material;
}

TetSolverSettings Settings(EIntegrator inIntegrator)
{
    TetSolverSettings settings;
    settings.mIntegrator = inIntegrator;
    settings.mGravity = Vec3::Zero();
    settings.mSleepSpeed = 0.0;
    return settings;
}

// The bar's tip pushed sideways (N s): it bends past yield at the clamp.
const Vec3 cPush(0.0, 0.0, 20.0);

struct BentBar
{
    std::vector<Vec3> mPositions;
    int mPlasticEvents = 0;
};

template <class Solver> BentBar Bend(Solver& ioSolver, int inSteps)
{
    BentBar bent;
    REQUIRE(ioSolver.ApplyImpulse(test::cBarTipNode, cPush).IsValid());
    for (int step = 0; step < inSteps; ++step)
    {
        const Result<TetStepResult> stepped = ioSolver.Step(1.0 / 60.0);
        REQUIRE(stepped.IsValid());
        REQUIRE_FALSE(HasEvent(stepped.Get().mEvents, ETetStepEvent::Diverged));
        bent.mPlasticEvents += stepped.Get().mPlasticElements;
    }
    return bent;
}

} // namespace

TEST_CASE("GPU plasticity: a bar bent past yield keeps the CPU's permanent set", "[gpu]")
{
    const std::shared_ptr<ComputeDevice> device = test::DeviceOrSkip();
    const EIntegrator integrator = GENERATE(EIntegrator::SymplecticEuler, EIntegrator::ImplicitEuler);
    CAPTURE(ToString(integrator));
    TetSolver cpu = test::ClampedBar(Ductile(), Settings(integrator));
    Result<GpuTetSolver> created = GpuTetSolver::CreateFrom(device, cpu);
    REQUIRE(created.IsValid());
    GpuTetSolver& gpu = created.Get();
    const std::vector<Vec3> rest = cpu.GetPositions();

    // 2 s: the blow bends the bar, the damping settles it on its permanent set.
    const BentBar on_gpu = Bend(gpu, 120);
    const BentBar on_cpu = Bend(cpu, 120);
    std::vector<Vec3> positions;
    gpu.ReadPositions(positions);
    std::vector<Mat3> gpu_plastic;
    gpu.ReadPlasticStrains(gpu_plastic);
    REQUIRE(gpu_plastic.size() == cpu.GetPlasticStrains().size());
    double largest_plastic = 0.0, plastic_gap = 0.0;
    for (std::size_t element = 0; element < gpu_plastic.size(); ++element)
    {
        largest_plastic = std::max(largest_plastic, cpu.GetPlasticStrains()[element].cwiseAbs().maxCoeff());
        plastic_gap = std::max(
            plastic_gap, (gpu_plastic[element] - cpu.GetPlasticStrains()[element]).cwiseAbs().maxCoeff());
    }
    const double set = test::MaxDistance(cpu.GetPositions(), rest);
    const double gap = test::MaxDistance(positions, cpu.GetPositions());

    // The same bar without plasticity springs back: the set is the plastic flow's.
    FemMaterialSettings elastic = Ductile();
    elastic.mYieldStress = std::numeric_limits<double>::infinity();
    TetSolver spring = test::ClampedBar(elastic, Settings(integrator));
    (void)Bend(spring, 120);
    const double spring_back = test::MaxDistance(spring.GetPositions(), rest);

    INFO("permanent set " << set << " m (elastic bar " << spring_back << " m), GPU vs CPU " << gap
                          << " m; plastic events GPU " << on_gpu.mPlasticEvents << ", CPU "
                          << on_cpu.mPlasticEvents << "; largest plastic strain " << largest_plastic
                          << ", GPU vs CPU " << plastic_gap);
    REQUIRE(set > 0.01);
    CHECK(spring_back < 0.01 * set);
    REQUIRE(on_cpu.mPlasticEvents > 0);
    CHECK(on_gpu.mPlasticEvents > 0);
    // Float against double on a path-dependent flow (elements near the yield surface flow or not by
    // round-off: 398 against 413 events implicit, 66,286 against 66,281 explicit): measured 2.7e-5 (explicit)
    // and 1.7e-4 (implicit) of the set, 1.3e-4 and 2.1e-4 of the largest plastic strain; bounded at 1e-3 (a
    // missing or doubled flow term moves them by their own size).
    CHECK(gap < 1.0e-3 * set);
    CHECK(plastic_gap < 1.0e-3 * largest_plastic);
}

TEST_CASE("GPU plasticity: a blow-up restores the plastic state bit for bit", "[gpu]")
{
    const std::shared_ptr<ComputeDevice> device = test::DeviceOrSkip();
    GpuTetSolver gpu =
        GpuTetSolver::CreateFrom(device, test::ClampedBar(Ductile(), Settings(EIntegrator::ImplicitEuler)))
            .Get();
    (void)Bend(gpu, 10); // flowed: a plastic set to lose
    std::vector<Mat3> before, after;
    gpu.ReadPlasticStrains(before);
    REQUIRE(before.size() == gpu.GetElementNodes().size());
    REQUIRE(std::any_of(before.begin(), before.end(),
                        [](const Mat3& inStrain) { return !inStrain.isZero(0.0); }));
    // 1e30 N s: every attempt diverges (the flow pass sees the non-finite state too) and the start comes
    // back.
    test::CheckBlowUpRestored(gpu, test::cBarTipNode);
    gpu.ReadPlasticStrains(after);
    CHECK(after == before);
}
