// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/crash/SlurmSweep.h>

#include <crumple/base/FileBytes.h>

#include <regex>
#include <span>
#include <string>
#include <sys/stat.h>

namespace crumple::crash
{

namespace
{

// A word for a POSIX shell: single quotes, each ' inside written as '\''.
std::string ShellQuote(const std::string& inText)
{
    std::string quoted = "'";
    for (char c : inText)
        quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}

Status WriteScript(const std::filesystem::path& inPath, const std::string& inText)
{
    if (Status status = WriteFileAtomically(inPath, std::as_bytes(std::span(inText.data(), inText.size())), "crumple-crash --emit-slurm");
        status.HasError())
        return status;
    if (chmod(inPath.c_str(), 0755) != 0)
        return MakeError(EError::IoError, "cannot make " + inPath.string() + " executable");
    return Status::Ok();
}

// The #SBATCH lines every script of the sweep shares.
std::string CommonDirectives(const SlurmSweepSettings& inSettings)
{
    std::string lines = "#SBATCH --time=" + inSettings.mTime + "\n";
    lines += "#SBATCH --cpus-per-task=" + std::to_string(inSettings.mCpusPerTask) + "\n";
    lines += "#SBATCH --ntasks=1\n";
    if (!inSettings.mMemory.empty())
        lines += "#SBATCH --mem=" + inSettings.mMemory + "\n";
    if (!inSettings.mPartition.empty())
        lines += "#SBATCH --partition=" + inSettings.mPartition + "\n";
    return lines;
}

} // namespace

Status ValidateSlurmSweepSettings(const SlurmSweepSettings& inSettings)
{
    if (inSettings.mCasesPerTask < 1 || inSettings.mCasesPerTask > 1'000'000)
        return MakeError(EError::InvalidArgument, "--cases-per-task must be in [1, 1000000]");
    // intent: Slurm's time formats: M, M:S, H:M:S, D-H, D-H:M, D-H:M:S
    static const std::regex time(R"(^([0-9]+-)?[0-9]+(:[0-9]{1,2}){0,2}$)");
    if (!std::regex_match(inSettings.mTime, time))
        return MakeError(EError::InvalidArgument, "--slurm-time must be minutes or [D-]HH:MM[:SS], got '" + inSettings.mTime + "'");
    if (inSettings.mCpusPerTask < 1 || inSettings.mCpusPerTask > 1024)
        return MakeError(EError::InvalidArgument, "--slurm-cpus must be in [1, 1024]");
    static const std::regex memory(R"(^[0-9]+[KMGT]?$)");
    if (!inSettings.mMemory.empty() && !std::regex_match(inSettings.mMemory, memory))
        return MakeError(EError::InvalidArgument, "--slurm-mem must be a number with K, M, G or T, got '" + inSettings.mMemory + "'");
    static const std::regex partition(R"(^[A-Za-z0-9_.-]+$)");
    if (!inSettings.mPartition.empty() && !std::regex_match(inSettings.mPartition, partition))
        return MakeError(EError::InvalidArgument, "--slurm-partition must be a partition name (letters, digits, _ . -), got '" +
                                                      inSettings.mPartition + "'");
    if (!inSettings.mExecutable.is_absolute())
        return MakeError(EError::InvalidArgument, "the crumple-crash the tasks call must be an absolute path, got '" +
                                                      inSettings.mExecutable.string() + "'");
    return Status::Ok();
}

Result<std::size_t> WriteSlurmSweep(const std::filesystem::path& inScenarioFile, const std::string& inSweepText, const CrashSweepSpec& inSpec,
                       const SlurmSweepSettings& inSettings, const std::filesystem::path& inFolder)
{
    if (Status valid = ValidateSlurmSweepSettings(inSettings); valid.HasError())
        return valid.GetError();
    const std::size_t total = inSpec.GetCaseCount();
    if (total == 0)
        return MakeError(EError::InvalidArgument, "the sweep has no cases");
    std::error_code folder_error, scenario_error;
    const std::filesystem::path folder = std::filesystem::absolute(inFolder, folder_error);
    const std::filesystem::path scenario = std::filesystem::absolute(inScenarioFile, scenario_error);
    if (folder_error || scenario_error)
        return MakeError(EError::IoError, "cannot make the paths absolute: " + (folder_error ? folder_error : scenario_error).message());
    std::error_code error;
    // intent: a fresh cases folder (a stale row must not enter the merge) and the logs folder
    std::filesystem::remove_all(folder / "cases", error);
    std::filesystem::create_directories(folder / "cases", error);
    std::filesystem::create_directories(folder / "logs", error);
    if (error)
        return MakeError(EError::IoError, "cannot create " + (folder / "cases").string() + ": " + error.message());

    const std::size_t tasks = (total + inSettings.mCasesPerTask - 1) / inSettings.mCasesPerTask;
    const std::string command = ShellQuote(inSettings.mExecutable.string()) + " " + ShellQuote(scenario.string()) +
                                " --sweep " + ShellQuote(inSweepText) + " --out " + ShellQuote(folder.string());
    const std::string header = "#!/bin/bash\n# Written by crumple-crash --emit-slurm: " + std::to_string(total) + " cases of " +
                               scenario.filename().string() + ", " + std::to_string(inSettings.mCasesPerTask) + " per task.\n";

    std::string array = header;
    array += "#SBATCH --job-name=crumple-sweep\n";
    array += "#SBATCH --array=0-" + std::to_string(tasks - 1) + "\n";
    array += "#SBATCH --output=" + (folder / "logs" / "task_%a.out").string() + "\n";
    array += CommonDirectives(inSettings);
    array += "exec " + command + " --sweep-task \"$SLURM_ARRAY_TASK_ID\" --cases-per-task " +
             std::to_string(inSettings.mCasesPerTask) + "\n";
    if (Status status = WriteScript(folder / "sweep_array.sbatch", array); status.HasError())
        return status.GetError();

    std::string merge = header;
    merge += "#SBATCH --job-name=crumple-sweep-merge\n";
    merge += "#SBATCH --output=" + (folder / "logs" / "merge.out").string() + "\n";
    merge += CommonDirectives(inSettings);
    merge += "exec " + command + " --sweep-merge\n";
    if (Status status = WriteScript(folder / "sweep_merge.sbatch", merge); status.HasError())
        return status.GetError();

    const std::string submit = "#!/bin/sh\n"
                               "# Submits the sweep's array job, then its merge once every task has ended (afterany: a\n"
                               "# task that failed leaves no row, and the merge names it). Prints both job ids.\n"
                               "set -e\n"
                               "array=$(sbatch --parsable " + ShellQuote((folder / "sweep_array.sbatch").string()) + ")\n"
                               "array=${array%%;*}\n"
                               "merge=$(sbatch --parsable --dependency=afterany:\"$array\" " +
                               ShellQuote((folder / "sweep_merge.sbatch").string()) + ")\n"
                               "echo \"$array ${merge%%;*}\"\n";
    if (Status status = WriteScript(folder / "submit.sh", submit); status.HasError())
        return status.GetError();
    return tasks;
}

} // namespace crumple::crash
