// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// The dent's per-vertex kernel on its own: the B-spline tensor-product sum in AVX lanes against the scalar sum
// (ffd/src/TensorProductSum.h), interleaved, and whether they give the same bits.
#include "Benchmarks.h"

#include "TensorProductSum.h"

#include <crumple/ffd/CubicBSplineWeights.h>

#include <algorithm>
#include <cstring>
#include <random>
#include <string>
#include <vector>

namespace crumple::bench
{

void RunTensorSumCase(BenchTable& ioTable, const BenchOptions& inOptions)
{
    using namespace crumple::ffd;
    // intent: the default lattice of the 50k-triangle car (32 x 16 x 13 controls), random controls and points
    // sorted by cell (the order a dent evaluates them in)
    const int nx = 32, ny = 16, nz = 13;
    const int evaluations = inOptions.mQuick ? 2000 : 20000;
    std::mt19937_64 random(3);
    std::uniform_real_distribution<double> value(-0.1, 0.1), unit(0.0, 1.0);
    std::vector<Vec3> controls(static_cast<std::size_t>(nx * ny * nz));
    for (Vec3& control : controls)
    {
        const double z = value(random), y = value(random),
                     x = value(random); // sequenced, last argument first (the tests' common::DrawVec3)
        control = Vec3(x, y, z);
    }
    struct Point
    {
        std::size_t mFirst;
        CellWeights mWeights;
    };
    std::vector<Point> points(static_cast<std::size_t>(evaluations));
    for (Point& point : points)
    {
        // intent: any cell but the lattice's last (the wide sum reads one double past it; Displacement keeps
        // the scalar sum there)
        std::size_t first = 0;
        do
            first = random() % static_cast<std::size_t>(nx - 3) +
                    static_cast<std::size_t>(nx) * (random() % static_cast<std::size_t>(ny - 3) +
                                                    static_cast<std::size_t>(ny) * (random() % static_cast<std::size_t>(nz - 3)));
        while (first + static_cast<std::size_t>(3 + 3 * nx + 3 * nx * ny) + 1 >= controls.size());
        point = {first, {CubicBSplineWeights(unit(random)), CubicBSplineWeights(unit(random)), CubicBSplineWeights(unit(random))}};
    }
    std::sort(points.begin(), points.end(), [](const Point& inA, const Point& inB) { return inA.mFirst < inB.mFirst; });

    std::vector<Vec3> scalar(points.size()), wide(points.size());
    const bool has_wide = HasWideTensorProductSum();
    const auto run = [&](bool inWide, std::vector<Vec3>& outSums) {
        for (std::size_t i = 0; i < points.size(); ++i)
            outSums[i] = inWide ? WideTensorProductSum(&controls[points[i].mFirst], nx, nx * ny, points[i].mWeights)
                                : TensorProductSum(&controls[points[i].mFirst], nx, nx * ny, points[i].mWeights);
    };
    const int repetitions = inOptions.mQuick ? 3 : 61;
    const std::vector<Timing> timing = InterleavedMedians(
        repetitions, {{[] {}, [&] { run(false, scalar); }}, {[] {}, [&] { run(has_wide, wide); }}});
    std::size_t differing = 0;
    for (std::size_t i = 0; i < points.size(); ++i)
        differing += std::memcmp(scalar[i].data(), wide[i].data(), sizeof(Vec3)) == 0 ? 0 : 1;
    ioTable.Add({"tensor_sum", std::string(has_wide ? "avx" : "no_avx_scalar_twice") + "_vs_scalar/" + std::to_string(evaluations) + "_evaluations",
                 timing[1].mWallMs, static_cast<double>(differing), "evaluations_whose_bits_differ",
                 "scalar_ms=" + FormatExtra(timing[0].mWallMs) + ";scalar_cpu_ms=" + FormatExtra(timing[0].mCpuMs) +
                     ";wide_cpu_ms=" + FormatExtra(timing[1].mCpuMs) + ";speedup=" + FormatExtra(timing[0].mCpuMs / timing[1].mCpuMs)});
}

} // namespace crumple::bench
