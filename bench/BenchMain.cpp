// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// crumple-bench: run time against error for every module; prints a table, writes CSV with --csv FILE.
#include "Benchmarks.h"

#include <crumple/base/Version.h>

#include <cstdio>
#include <string>

int main(int argc, char** argv)
{
    using namespace crumple::bench;
    BenchOptions options;
    std::string csv;
    for (int i = 1; i < argc; ++i)
    {
        const std::string arg = argv[i];
        if (arg == "--help" || arg == "-h")
        {
            std::printf("usage: crumple-bench [--quick] [--csv FILE]\n"
                        "  Times every benchmark (median of repetitions) and reports its error.\n"
                        "  --quick     few repetitions on small meshes (a smoke run)\n"
                        "  --csv FILE  also write rows benchmark,case,median_ms,error,error_unit,extra\n");
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
        else
        {
            std::fprintf(stderr, "crumple-bench: unknown argument '%s' (see --help)\n", arg.c_str());
            return 2;
        }
    }

    BenchTable table;
    std::printf("crumple-bench %s%s: running\n", crumple::VersionString(), options.mQuick ? " (quick)" : "");
    RunDentBenchmarks(table, options);
    RunImpulseBenchmarks(table, options);
    RunAdapterBenchmarks(table, options);
    RunFemBenchmarks(table, options);
    RunGpuBenchmarks(table, options);
    table.Print();
    if (!csv.empty() && !table.WriteCsv(csv))
    {
        std::fprintf(stderr, "crumple-bench: cannot write %s\n", csv.c_str());
        return 2;
    }
    return 0;
}
