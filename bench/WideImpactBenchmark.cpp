// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// The wide-impact fill on its own (ffd::InterpolateWideImpact): a dent's scattered contacts become samples
// across the face they span. Time of a car front's random contacts and of a ring of contacts (a round
// impactor's rim: every point on one circle, the Delaunay step's worst case), interleaved; the error is how far
// the samples' displacements are from the affine field the contacts were given (linear interpolation
// reproduces it exactly, up to round-off).
#include "Benchmarks.h"

#include <crumple/ffd/InterpolateWideImpact.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace crumple::bench
{

namespace
{

Vec3 AffineDisplacement(const Vec3& inPoint)
{
    Mat3 gradient;
    gradient << 0.01, 0.02, 0.0, -0.03, 0.0, 0.01, 0.05, 0.04, 0.0;
    return Vec3(-0.1, 0.0, 0.02) + gradient * inPoint;
}

// The largest distance of a sample's displacement from the affine field (m).
double AffineError(const std::vector<ffd::PointDisplacement>& inSamples)
{
    double error = 0.0;
    for (const ffd::PointDisplacement& sample : inSamples)
        error = std::max(error, (sample.mDisplacement - AffineDisplacement(sample.mPoint)).norm());
    return error;
}

} // namespace

void RunWideImpactCases(BenchTable& ioTable, const BenchOptions& inOptions)
{
    using ffd::PointDisplacement;
    // intent: 64 contacts at random on a 1.8 m x 1.4 m car front (x = 2.1 m), and a ring of 150 on a 0.6 m
    // circle in the same plane; the default lattice's spacing and the dent's cap
    constexpr double cSpacing = 0.15;
    constexpr std::size_t cCap = 512;
    std::mt19937_64 random(11);
    std::uniform_real_distribution<double> y(-0.9, 0.9), z(-0.7, 0.7);
    std::vector<PointDisplacement> front, ring;
    for (int i = 0; i < 64; ++i)
    {
        const double pz = z(random),
                     py = y(random); // sequenced, last argument first (the tests' common::DrawVec3)
        const Vec3 point(2.1, py, pz);
        front.push_back({point, AffineDisplacement(point)});
    }
    constexpr int cRing = 150;
    for (int i = 0; i < cRing; ++i)
    {
        const double angle = 2.0 * std::numbers::pi * i / cRing;
        const Vec3 point(2.1, 0.6 * std::cos(angle), 0.6 * std::sin(angle));
        ring.push_back({point, AffineDisplacement(point)});
    }
    std::vector<PointDisplacement> front_samples, ring_samples;
    const int repetitions = inOptions.mQuick ? 3 : 31;
    const std::vector<Timing> timing = InterleavedMedians(
        repetitions, {{[] {}, [&] { front_samples = ffd::InterpolateWideImpact(front, cSpacing, cCap); }},
                      {[] {}, [&] { ring_samples = ffd::InterpolateWideImpact(ring, cSpacing, cCap); }}});
    ioTable.Add({"wide_impact", "64_random_contacts_on_a_face", timing[0].mWallMs, AffineError(front_samples), "m_from_affine_field",
                 "cpu_ms=" + FormatExtra(timing[0].mCpuMs) + ";samples=" + std::to_string(front_samples.size())});
    ioTable.Add({"wide_impact", std::to_string(cRing) + "_contacts_on_a_ring", timing[1].mWallMs, AffineError(ring_samples),
                 "m_from_affine_field", "cpu_ms=" + FormatExtra(timing[1].mCpuMs) + ";samples=" + std::to_string(ring_samples.size())});
}

} // namespace crumple::bench
