// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include "ThreadCpuTime.h"

#include <chrono>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace crumple::bench
{

using common::ThreadCpuMs;

/// One benchmark result: a row of the printed table and of the CSV
/// (benchmark,case,median_ms,error,error_unit,extra).
struct BenchRow
{
    std::string mBenchmark;  ///< e.g. "apply_collision"
    std::string mCase;       ///< e.g. "50k_tris/1_zone/38_contacts"
    double mMedianMs = 0.0;  ///< Median wall time of one repetition (ms)
    double mError = 0.0;     ///< Accuracy figure of the case
    std::string mErrorUnit;  ///< What mError measures, e.g. "rel_contact_error"
    std::string mExtra;      ///< key=value pairs separated by ';'
};

/// Collects rows, prints them as a table and writes them as CSV.
class BenchTable
{
public:
    void Add(BenchRow inRow);
    void Print() const;
    bool WriteCsv(const std::string& inPath) const;

private:
    std::vector<BenchRow> mRows;
};

/// Milliseconds since inStart (steady clock).
double ElapsedMs(std::chrono::steady_clock::time_point inStart);

/// A number for the extra column: 4 significant digits, never a comma.
std::string FormatExtra(double inValue);

/// The value below which inQuantile (in [0, 1]) of inValues lie, nearest rank; inValues not empty.
double Quantile(std::vector<double> inValues, double inQuantile);

/// The middle value of inValues (the upper one of an even count); inValues not empty.
double Median(std::vector<double> inValues);

/// How many elements of inA and inB differ (compared exactly; the elements past the shorter one count as
/// differing): links broken in two runs, node positions of two replays.
template <class T> int CountDiffering(const std::vector<T>& inA, const std::vector<T>& inB)
{
    const std::size_t common = inA.size() < inB.size() ? inA.size() : inB.size();
    int differing = static_cast<int>((inA.size() > inB.size() ? inA.size() : inB.size()) - common);
    for (std::size_t index = 0; index < common; ++index)
        differing += inA[index] == inB[index] ? 0 : 1;
    return differing;
}

/// Each frame's wall and thread CPU time (ms) of two sides stepped in lockstep: side 0 (bare) and side 1
/// (attached).
struct LockstepFrames
{
    std::vector<double> mWallMs[2];
    std::vector<double> mCpuMs[2];
};

/// Steps inFrames frames of two sides alternating (side 0 frame, side 1 frame, ...), so that both see the same
/// machine load, timing each step; stops after the first step for which inStep(side) returns false.
LockstepFrames TimeLockstep(int inFrames, const std::function<bool(int inSide)>& inStep);

/// Wall and thread CPU time of one repetition (ms).
struct Timing
{
    double mWallMs = 0.0;
    double mCpuMs = 0.0;
};

/// Medians of wall and thread CPU time for each side, the sides interleaved (A, B, A, B, ...) so that
/// noise from other jobs on the machine falls on both alike. Each side's prepare is untimed.
std::vector<Timing> InterleavedMedians(int inRepetitions,
                                       const std::vector<std::pair<std::function<void()>, std::function<void()>>>& inSides);

/// Median wall and thread CPU time (ms) of inRepetitions calls of inRun, each preceded by an untimed inPrepare.
Timing MedianTiming(int inRepetitions, const std::function<void()>& inPrepare, const std::function<void()>& inRun);

} // namespace crumple::bench
