// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "Benchmarks.h"
#include "ThreadCpuTime.h"

#if defined(CRUMPLE_BENCH_CRASH)
#include <crumple/crash/CrashRun.h>
#include <crumple/crash/ShippedCars.h>
#include <crumple/ffd/BoundingBox.h>
#include <crumple/plugin/CampbellCrush.h>
#include <crumple/plugin/DamageWorldSettings.h>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

namespace crumple::bench
{

void RunCrushBenchmarks(BenchTable& ioTable, const BenchOptions& inOptions)
{
#if defined(CRUMPLE_BENCH_CRASH)
    // Full-width rigid-wall crashes of every body in each engine, default material (Campbell's law, mid-size
    // class). The error: the energy CRASH3 reads from the residual crush profile (six stations C1..C6 across
    // the damage width, StruckCrushProfile) against the energy the collision absorbed, E = (1 - e^2) m v^2 /
    // 2 (Baraff's impulse at restitution e): how faithfully the dent stores the energy, whatever the front's
    // shape. Beside it the largest front crush against the law's answer for a flat front as wide as the body,
    // C(E / w) (a rounded or slanted front crushes deeper where it meets the wall first), and against the
    // oracle's nominal mid-size line (shared/data/crash/campbell_oracle.csv, b0 = 2.173 m/s, b1 = 24.07 1/s),
    // the largest mean wall gap over the speeds (how far the struck front ended behind the wall's final
    // plane, MeasureWallGap: a flat wall should leave a flat front), and the run time of a whole 0.3 s crash.
    using namespace crash;
    const std::vector<NamedVehicle> bodies = ShippedCars();
    const std::vector<double> speeds = inOptions.mQuick ? std::vector<double>{56.0}
                                                        : std::vector<double>{20.0, 30.0, 40.0, 48.0, 56.0, 64.0};
    for (const NamedVehicle& body : bodies)
        for (EEngine engine : {EEngine::Bullet, EEngine::Ode})
        {
            if (inOptions.mQuick && (engine == EEngine::Ode || body.mName != "box car"))
                continue;
            std::vector<double> times, cpu_times, energy_errors, law_errors, line_errors;
            double worst_gap = 0.0;
            for (double km_h : speeds)
            {
                CrashScenario scenario;
                scenario.mEngine = engine;
                scenario.mDuration = 0.3;
                scenario.mVehicle = body.mVehicle;
                scenario.mImpact.mSpeed = km_h / 3.6;
                scenario.mPictures = false;
                const auto start = std::chrono::steady_clock::now();
                const double cpu_start = common::ThreadCpuMs();
                const Result<CrashOutcome> outcome = RunCrash(scenario, {});
                times.push_back(ElapsedMs(start));
                cpu_times.push_back(common::ThreadCpuMs() - cpu_start);
                if (outcome.HasError())
                    continue;
                const double crush = outcome.Get().mResidualCrush[static_cast<int>(EZone::Front)];
                const double width = ffd::BoundingBox(outcome.Get().mRestMesh.mPositions).mMax.y() -
                                     ffd::BoundingBox(outcome.Get().mRestMesh.mPositions).mMin.y();
                const double v = scenario.mImpact.mSpeed, e = plugin::DamageWorldSettings{}.mRestitution;
                const double law = plugin::CampbellCrushDepth(body.mVehicle.mMaterial, width,
                                                              (1.0 - e * e) * 0.5 * body.mVehicle.mMass * v * v);
                const double line = (v - 2.173) / 24.07;
                // CRASH3: linear crush between stations, E = sum over the five segments of
                // (L / 5) (A (Ci + Cj) / 2 + B (Ci^2 + Ci Cj + Cj^2) / 6 + G).
                const CrushProfile& profile = outcome.Get().mCrushProfile;
                const plugin::DamageMaterial& m = body.mVehicle.mMaterial;
                double crash3 = 0.0;
                for (std::size_t i = 0; i + 1 < profile.mC.size(); ++i)
                {
                    const double a = profile.mC[i], b = profile.mC[i + 1];
                    crash3 += profile.mDamageWidth / 5.0 *
                              (m.mCrushA * 0.5 * (a + b) + m.mCrushB * (a * a + a * b + b * b) / 6.0 + m.mCrushG);
                }
                energy_errors.push_back(crash3 / ((1.0 - e * e) * 0.5 * body.mVehicle.mMass * v * v) - 1.0);
                law_errors.push_back(crush / law - 1.0);
                line_errors.push_back(crush / line - 1.0);
                if (outcome.Get().mWallGap)
                    worst_gap = std::max(worst_gap, outcome.Get().mWallGap->mMean);
            }
            if (energy_errors.empty())
                continue;
            auto worst = [](const std::vector<double>& inErrors) {
                return *std::max_element(inErrors.begin(), inErrors.end(),
                                         [](double a, double b) { return std::abs(a) < std::abs(b); });
            };
            std::sort(times.begin(), times.end());
            std::sort(cpu_times.begin(), cpu_times.end());
            std::string name = body.mName;
            std::replace(name.begin(), name.end(), ' ', '_');
            ioTable.Add({"crush_vs_campbell", name + "/" + ToString(engine) + "/full_wall",
                         times[times.size() / 2], worst(energy_errors), "worst_rel_crash3_energy_vs_absorbed",
                         "speeds_km_h=" + std::to_string(speeds.size()) + "_from_" + FormatExtra(speeds.front()) +
                             "_to_" + FormatExtra(speeds.back()) + ";worst_rel_max_crush_vs_flat_law=" +
                             FormatExtra(worst(law_errors)) + ";worst_rel_vs_midsize_line=" +
                             FormatExtra(worst(line_errors)) + ";worst_wall_gap_m=" + FormatExtra(worst_gap) +
                             ";cpu_ms=" + FormatExtra(cpu_times[cpu_times.size() / 2])});
        }
#else
    (void)ioTable;
    (void)inOptions;
#endif
}

} // namespace crumple::bench
