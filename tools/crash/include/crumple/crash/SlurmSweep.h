// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Result.h>
#include <crumple/crash/CrashSweep.h>

#include <cstddef>
#include <filesystem>
#include <string>

namespace crumple::crash
{

/// How a sweep is cut into Slurm array tasks and what each task asks the cluster for.
struct SlurmSweepSettings
{
    std::size_t mCasesPerTask = 1;  ///< Cases one array task runs one after the other, >= 1
    std::string mTime = "00:30:00"; ///< Each task's --time: minutes, or [D-]HH:MM[:SS]
    int mCpusPerTask = 1;           ///< Each task's --cpus-per-task, in [1, 1024] (a case runs on one core)
    std::string mMemory;            ///< Each task's --mem (a number with K, M, G or T); empty: the cluster's default
    std::string mPartition;         ///< --partition; empty: the cluster's default
    std::filesystem::path mExecutable; ///< The crumple-crash the tasks call (absolute: nodes share the file system)
};

/// Checks the settings at the API boundary (cases per task, time, cpus, memory and partition syntax, an
/// absolute executable), naming the bad one.
Status ValidateSlurmSweepSettings(const SlurmSweepSettings& inSettings);

/// Writes a sweep as a Slurm job into inFolder, which also receives its results, for a cluster whose nodes
/// see the same file system:
/// - sweep_array.sbatch: an array job, task k runs cases k * mCasesPerTask onwards
///   (crumple-crash SCENARIO --sweep SPEC --sweep-task k --cases-per-task n --out inFolder), rows in cases/;
/// - sweep_merge.sbatch: gathers the rows into sweep.csv and sweep.png (crumple-crash ... --sweep-merge),
///   byte for byte what a local --sweep of the same scenario and spec writes, and exits 1 when a case failed;
/// - submit.sh: submits the array, then the merge with --dependency=afterany on it; prints both job ids.
/// Task logs go to logs/. The cases folder is emptied, so a stale row cannot enter the merge.
/// @param[in] inScenarioFile the scenario file (made absolute)
/// @param[in] inSweepText    the --sweep text, passed to every task as it is (inSpec is its parse)
/// @return the number of array tasks
Result<std::size_t> WriteSlurmSweep(const std::filesystem::path& inScenarioFile, const std::string& inSweepText,
                       const CrashSweepSpec& inSpec, const SlurmSweepSettings& inSettings,
                       const std::filesystem::path& inFolder);

} // namespace crumple::crash
