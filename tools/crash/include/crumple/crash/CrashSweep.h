// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Result.h>
#include <crumple/crash/CrashScenario.h>

#include <cstdio>
#include <filesystem>
#include <string_view>
#include <vector>

namespace crumple::crash
{

/// The values a sweep crosses: every combination of speed, wall angle and sideways offset is one case.
struct CrashSweepSpec
{
    std::vector<double> mSpeeds;        ///< m/s
    std::vector<double> mAngles{0.0};   ///< Wall angle (deg); used only when mSweepAngles
    std::vector<double> mOffsets{0.0};  ///< Sideways offset (m); used only when mSweepOffsets
    bool mSweepAngles = false;          ///< angles_deg was given: else every case keeps the scenario's angle_deg
    bool mSweepOffsets = false;         ///< offsets_m was given: else every case keeps the scenario's offset_m

    /// Number of cases
    std::size_t GetCaseCount() const { return mSpeeds.size() * mAngles.size() * mOffsets.size(); }
};

/// Parses "speeds_km_h=20,30,40;angles_deg=0,30;offsets_m=0,0.5" (speeds required; without angles or offsets
/// every case keeps the scenario's). Refuses unknown names, non-numbers and values out of range (speed in
/// (0, 3600] km/h or (0, 1000] m/s, angle in (-90, 90), offset in (-1000, 1000) m), naming the item.
Result<CrashSweepSpec> ParseCrashSweep(std::string_view inText);
/// Refuses a sweep the scenario cannot take (angles other than 0 for a target that is not a rigid wall); the
/// local sweep, its cases and crumple-crash's --emit-slurm check it before running anything.
Status CheckSweepFitsScenario(const CrashScenario& inScenario, const CrashSweepSpec& inSpec);

/// Runs every case of inSpec on inScenario in inWorkers worker processes (fork; case i runs in worker
/// i mod inWorkers), each writing its row to inFolder/cases/; shows a progress bar on inProgress; then
/// writes inFolder/sweep.csv (rows in case order: the file does not depend on the number of workers) and
/// inFolder/sweep.png (front residual crush against impact speed). Expectations are not checked per case.
/// @return the number of cases whose run failed (their rows say why)
Result<int> RunCrashSweep(const CrashScenario& inScenario, const CrashSweepSpec& inSpec, int inWorkers,
                          const std::filesystem::path& inFolder, std::FILE* inProgress);

/// Runs the cases inFirst .. inFirst + inCount - 1 (those below the case count) of inSpec on inScenario, one
/// after the other in this process, each writing its row to inFolder/cases/ (a Slurm array task's share of a
/// sweep, WriteSlurmSweep). A case that fails writes a row that says why.
/// @return an error only when the cases folder cannot be made
Status RunCrashSweepCases(const CrashScenario& inScenario, const CrashSweepSpec& inSpec, std::size_t inFirst,
                          std::size_t inCount, const std::filesystem::path& inFolder);

/// Gathers the rows in inFolder/cases/ into inFolder/sweep.csv and inFolder/sweep.png, byte for byte what
/// RunCrashSweep writes for the same rows, whoever ran them; a case without a row counts as failed. Names
/// each failed case on inProgress (may be null).
/// @return the number of cases that failed a check, failed to run or wrote no row
Result<int> MergeCrashSweep(const CrashScenario& inScenario, const CrashSweepSpec& inSpec,
                            const std::filesystem::path& inFolder, std::FILE* inProgress);

} // namespace crumple::crash
