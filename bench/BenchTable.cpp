// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "BenchTable.h"
#include "ThreadCpuTime.h"

#include <algorithm>
#include <cstdio>
#include <fstream>

namespace crumple::bench
{

void BenchTable::Add(BenchRow inRow)
{
    std::printf("  %-18s %-40s %10.4f ms  %10.3e %-22s %s\n", inRow.mBenchmark.c_str(), inRow.mCase.c_str(),
                inRow.mMedianMs, inRow.mError, inRow.mErrorUnit.c_str(), inRow.mExtra.c_str());
    std::fflush(stdout);
    mRows.push_back(std::move(inRow));
}

void BenchTable::Print() const
{
    std::printf("\n%-20s %-40s %12s  %10s %-22s %s\n", "benchmark", "case", "median", "error", "error_unit", "extra");
    for (const BenchRow& row : mRows)
        std::printf("%-20s %-40s %9.4f ms  %10.3e %-22s %s\n", row.mBenchmark.c_str(), row.mCase.c_str(), row.mMedianMs,
                    row.mError, row.mErrorUnit.c_str(), row.mExtra.c_str());
}

bool BenchTable::WriteCsv(const std::string& inPath) const
{
    std::ofstream out(inPath);
    if (!out)
        return false;
    out << "benchmark,case,median_ms,error,error_unit,extra\n";
    char number[64];
    for (const BenchRow& row : mRows)
    {
        out << row.mBenchmark << ',' << row.mCase << ',';
        std::snprintf(number, sizeof(number), "%.6f,%.6e", row.mMedianMs, row.mError);
        out << number << ',' << row.mErrorUnit << ',' << row.mExtra << '\n';
    }
    return static_cast<bool>(out.flush());
}

double ElapsedMs(std::chrono::steady_clock::time_point inStart)
{
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - inStart).count();
}

std::string FormatExtra(double inValue)
{
    char text[32];
    std::snprintf(text, sizeof(text), "%.4g", inValue);
    return text;
}

double Quantile(std::vector<double> inValues, double inQuantile)
{
    std::sort(inValues.begin(), inValues.end());
    return inValues[static_cast<std::size_t>(inQuantile * static_cast<double>(inValues.size() - 1))];
}

LockstepFrames TimeLockstep(int inFrames, const std::function<bool(int inSide)>& inStep)
{
    LockstepFrames frames;
    for (int frame = 0; frame < inFrames; ++frame)
        for (int side = 0; side < 2; ++side)
        {
            const double cpu_start = ThreadCpuMs();
            const auto start = std::chrono::steady_clock::now();
            const bool stepped = inStep(side);
            frames.mWallMs[side].push_back(ElapsedMs(start));
            frames.mCpuMs[side].push_back(ThreadCpuMs() - cpu_start);
            if (!stepped)
                return frames;
        }
    return frames;
}

double Median(std::vector<double> inValues)
{
    std::nth_element(inValues.begin(), inValues.begin() + static_cast<std::ptrdiff_t>(inValues.size() / 2), inValues.end());
    return inValues[inValues.size() / 2];
}

std::vector<Timing> InterleavedMedians(int inRepetitions,
                                       const std::vector<std::pair<std::function<void()>, std::function<void()>>>& inSides)
{
    std::vector<std::vector<double>> wall(inSides.size()), cpu(inSides.size());
    for (int i = 0; i < inRepetitions; ++i)
        for (std::size_t side = 0; side < inSides.size(); ++side)
        {
            inSides[side].first();
            const double cpu_start = ThreadCpuMs();
            const auto start = std::chrono::steady_clock::now();
            inSides[side].second();
            const auto stop = std::chrono::steady_clock::now();
            cpu[side].push_back(ThreadCpuMs() - cpu_start);
            wall[side].push_back(std::chrono::duration<double, std::milli>(stop - start).count());
        }
    std::vector<Timing> medians;
    for (std::size_t side = 0; side < inSides.size(); ++side)
        medians.push_back({Median(wall[side]), Median(cpu[side])});
    return medians;
}

Timing MedianTiming(int inRepetitions, const std::function<void()>& inPrepare, const std::function<void()>& inRun)
{
    std::vector<double> wall, cpu;
    for (int i = 0; i < inRepetitions; ++i)
    {
        inPrepare();
        const auto start = std::chrono::steady_clock::now();
        const double cpu_start = ThreadCpuMs();
        inRun();
        cpu.push_back(ThreadCpuMs() - cpu_start);
        wall.push_back(ElapsedMs(start));
    }
    return {Median(wall), Median(cpu)};
}

} // namespace crumple::bench
