// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Result.h>
#include <crumple/crash/CrashRun.h>
#include <crumple/crash/SanityChecks.h>
#include <crumple/crash/TimeHistory.h>

#include <cstdio>
#include <filesystem>
#include <vector>

namespace crumple::crash
{

/// An expectation with the value measured and its verdict.
struct ExpectationResult
{
    Expectation mExpectation;
    double mValue = 0.0; ///< Measured, in the quantity's SI unit
    bool mPassed = false;
};

/// Checks every expectation of inScenario against inOutcome.
std::vector<ExpectationResult> CheckExpectations(const CrashScenario& inScenario, const CrashOutcome& inOutcome);

/// What a run's outcome means, computed once and read by every report: its expectations, its sanity checks
/// and its time history.
struct CrashFindings
{
    std::vector<ExpectationResult> mExpectations;
    std::vector<SanityResult> mSanity;
    TimeHistory mHistory;

    bool ExpectationsHold() const;
    bool Sane() const { return AllSane(mSanity); }
    /// The run's verdict (exit 0): every expectation holds and every sanity check passes
    bool Passed() const { return ExpectationsHold() && Sane(); }
};

/// Checks inOutcome against inScenario (CheckExpectations, CheckSanity) and takes its time history.
CrashFindings AnalyzeCrash(const CrashScenario& inScenario, const CrashOutcome& inOutcome);

/// Writes report.json: the scenario's name and engine, per-zone residual crush (m), peak and total impulse
/// (N s), delta-v (m/s and km/h), energy absorbed (J), start and end velocity, every collision, every
/// expectation with its value and verdict, and the overall verdict.
Status WriteReportJson(const std::filesystem::path& inPath, const CrashScenario& inScenario,
                       const CrashOutcome& inOutcome, const CrashFindings& inFindings);

/// The human summary (stdout): the numbers and each expectation as PASS/FAIL with its measured value.
void PrintSummary(std::FILE* inStream, const CrashScenario& inScenario, const CrashOutcome& inOutcome,
                  const CrashFindings& inFindings);

/// Writes report.html: a self-contained page (pictures embedded as base64 data, no external file or
/// network) with the summary table, the expectations and the PNGs found in inPictureFolder.
Status WriteReportHtml(const std::filesystem::path& inPath, const CrashScenario& inScenario,
                       const CrashOutcome& inOutcome, const CrashFindings& inFindings,
                       const std::filesystem::path& inPictureFolder);

/// PNG renders of the car before and after from the front, side and top, and a heat map of the residual
/// displacement (iso view), into inFolder. Needs an EGL context: without one the error says why.
/// @param inColourMax  the dent colour scale's top (m); 0: samples::DentColorScale of the deepest dent, as
///                     crumple-replay uses, so that the same damage has the same colours in both
Status WritePictures(const std::filesystem::path& inFolder, const CrashOutcome& inOutcome, double inColourMax = 0.0);

} // namespace crumple::crash
