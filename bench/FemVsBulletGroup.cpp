// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// The fem_vs_bullet group of crumple-bench: runs crumple-bench-fem-vs-bullet, the program beside this one
// that links Bullet's double-precision build (whose symbols clash with the float Bullet linked here), and
// takes its rows into the table.
#include "Benchmarks.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

namespace crumple::bench
{

namespace
{

// Splits a CSV line into its first inFields - 1 fields and the rest (the extra column keeps its text).
std::vector<std::string> SplitRow(const std::string& inLine, std::size_t inFields)
{
    std::vector<std::string> fields;
    std::size_t start = 0;
    while (fields.size() + 1 < inFields)
    {
        const std::size_t comma = inLine.find(',', start);
        if (comma == std::string::npos)
            break;
        fields.push_back(inLine.substr(start, comma - start));
        start = comma + 1;
    }
    fields.push_back(inLine.substr(start));
    return fields;
}

} // namespace

void RunFemVsBulletBenchmarks(BenchTable& ioTable, const BenchOptions& inOptions)
{
    std::error_code error;
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
    const std::filesystem::path program = self.parent_path() / "crumple-bench-fem-vs-bullet";
    if (error || !std::filesystem::exists(program))
    {
        std::printf("note: fem_vs_bullet: %s is not built (it needs Bullet's double build, pkg-config "
                    "bullet-float64); no rows\n",
                    program.string().c_str());
        return;
    }
    const std::filesystem::path csv =
        std::filesystem::temp_directory_path() / ("crumple-fem-vs-bullet-" + std::to_string(::getpid()) + ".csv");
    std::string command = "\"";
    command += program.string();
    command += inOptions.mQuick ? "\" --quick --csv \"" : "\" --csv \"";
    command += csv.string();
    command += "\"";
    std::fflush(stdout);
    const int status = std::system(command.c_str());
    if (status != 0)
    {
        std::filesystem::remove(csv, error);
        throw std::runtime_error(command + " exited with status " + std::to_string(status));
    }

    // Its rows: benchmark,case,median_ms,cpu_ms,error,error_unit,extra.
    std::ifstream in(csv);
    std::string line;
    std::getline(in, line); // header
    int rows = 0;
    while (std::getline(in, line))
    {
        const std::vector<std::string> fields = SplitRow(line, 7);
        if (fields.size() != 7)
            throw std::runtime_error("unreadable row of " + csv.string() + ": " + line);
        ioTable.Add({fields[0], fields[1], std::stod(fields[2]), std::stod(fields[4]), fields[5],
                     fields[6] + ";cpu_ms=" + fields[3] + ";program=crumple-bench-fem-vs-bullet"});
        ++rows;
    }
    std::filesystem::remove(csv, error);
    if (rows == 0)
        throw std::runtime_error(program.string() + " wrote no rows");
}

} // namespace crumple::bench
