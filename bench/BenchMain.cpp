// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// crumple-bench: run time against error for every module; prints a table, writes CSV with --csv FILE.
#include "Benchmarks.h"

#include <crumple/base/Version.h>

#include <cstdio>
#include <exception>
#include <string>
#include <utility>

int main(int argc, char** argv)
{
    using namespace crumple::bench;
    using Group = void (*)(BenchTable&, const BenchOptions&);
    const std::pair<const char*, Group> groups[] = {{"dent", RunDentBenchmarks},
                                                    {"impulse", RunImpulseBenchmarks},
                                                    {"adapter", RunAdapterBenchmarks},
                                                    {"frame_budget", RunFrameBudgetBenchmarks},
                                                    {"fem", RunFemBenchmarks},
                                                    {"fem_refresh", RunFemRefreshBenchmarks},
                                                    {"fem_cracks", RunCrackBoundBenchmarks},
                                                    {"contact_mass", RunContactMassBenchmarks},
                                                    {"fem_ground", RunGroundBenchmarks},
                                                    {"fem_vs_bullet", RunFemVsBulletBenchmarks},
                                                    {"barrier", RunBarrierBenchmarks},
                                                    {"props", RunPropBenchmarks},
                                                    {"props_gpu", RunPropGpuBenchmarks},
                                                    {"crush", RunCrushBenchmarks},
                                                    {"gpu", RunGpuBenchmarks}};
    BenchOptions options;
    std::string csv, only;
    for (int i = 1; i < argc; ++i)
    {
        const std::string arg = argv[i];
        if (arg == "--help" || arg == "-h")
        {
            std::printf("usage: crumple-bench [--quick] [--only GROUP] [--csv FILE]\n"
                        "  Times every benchmark (median of repetitions) and reports its error.\n"
                        "  --quick       few repetitions on small meshes (a smoke run)\n"
                        "  --only GROUP  one group:");
            // intent: the list is the table's, so a new group cannot be missing from it
            for (const auto& [name, run] : groups)
                std::printf(" %s", name);
            std::printf("\n  --csv FILE    also write rows benchmark,case,median_ms,error,error_unit,extra\n");
            return 0;
        }
        if (arg == "--version")
        {
            std::printf("crumple-bench %s\n", crumple::VersionString());
            return 0;
        }
        if (arg == "--quick")
            options.mQuick = true;
        else if (arg == "--csv" && i + 1 < argc)
            csv = argv[++i];
        else if (arg == "--only" && i + 1 < argc)
            only = argv[++i];
        else
        {
            std::fprintf(stderr, "crumple-bench: unknown argument '%s' (see --help)\n", arg.c_str());
            return 2;
        }
    }

    bool known = only.empty();
    for (const auto& [name, run] : groups)
        known = known || only == name;
    if (!known)
    {
        std::fprintf(stderr, "crumple-bench: unknown group '%s' (see --help)\n", only.c_str());
        return 2;
    }

    BenchTable table;
    std::printf("crumple-bench %s%s: running\n", crumple::VersionString(), options.mQuick ? " (quick)" : "");
    for (const auto& [name, run] : groups)
        if (only.empty() || only == name)
        {
            // A group that cannot measure what it claims stops the run: a table with a silent hole is worse.
            try
            {
                run(table, options);
            }
            catch (const std::exception& error)
            {
                std::fprintf(stderr, "crumple-bench: group %s failed: %s\n", name, error.what());
                return 1;
            }
        }
    table.Print();
    if (!csv.empty() && !table.WriteCsv(csv))
    {
        std::fprintf(stderr, "crumple-bench: cannot write %s\n", csv.c_str());
        return 2;
    }
    return 0;
}
