// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// crumple-crash: a scenario in, a verdict, numbers and pictures out. Exit 0 when every expectation holds,
// 1 when one fails (printing which, with the measured value), 2 for a bad scenario or command line (nothing
// written).
#include <crumple/base/Version.h>
#include <crumple/crash/CrashReport.h>
#include <crumple/crash/ScenarioFile.h>

#include "ObjWriter.h"

#include <cstdio>
#include <string>
#include <system_error>

using namespace crumple;
using namespace crumple::crash;

namespace
{

constexpr int cExitPass = 0;
constexpr int cExitFail = 1;
constexpr int cExitBadInput = 2;

void PrintUsage(std::FILE* inStream)
{
    std::fprintf(inStream,
                 "usage: crumple-crash SCENARIO.json [--out DIR] [--no-pictures]\n"
                 "  Runs a crash scenario (schema: docs/scenarios.md) and writes into DIR (default\n"
                 "  crash-output/<scenario file name>): report.json, deformed.obj, replay.crumple (replay it with\n"
                 "  crumple-replay) and PNG pictures. Exit status: 0 all expectations hold, 1 one failed,\n"
                 "  2 bad scenario or command line (nothing written).\n"
                 "  --no-pictures  skip the renders (no EGL context is made)\n"
                 "  --help, --version\n");
}

} // namespace

int main(int argc, char** argv)
{
    std::filesystem::path scenario_path, out;
    bool pictures = true;
    for (int i = 1; i < argc; ++i)
    {
        const std::string arg = argv[i];
        if (arg == "--help")
        {
            PrintUsage(stdout);
            return cExitPass;
        }
        if (arg == "--version")
        {
            std::printf("crumple-crash %s\n", VersionString());
            return cExitPass;
        }
        if (arg == "--no-pictures")
            pictures = false;
        else if (arg == "--out" && i + 1 < argc)
            out = argv[++i];
        else if (!arg.empty() && arg[0] != '-' && scenario_path.empty())
            scenario_path = arg;
        else
        {
            std::fprintf(stderr, "crumple-crash: unexpected argument '%s'\n", arg.c_str());
            PrintUsage(stderr);
            return cExitBadInput;
        }
    }
    if (scenario_path.empty())
    {
        PrintUsage(stderr);
        return cExitBadInput;
    }

    // A bad scenario is refused before anything is written.
    Result<CrashScenario> scenario = LoadCrashScenario(scenario_path);
    if (scenario.HasError())
    {
        std::fprintf(stderr, "crumple-crash: %s: %s\n", scenario_path.string().c_str(),
                     scenario.GetError().mMessage.c_str());
        return cExitBadInput;
    }
    if (out.empty())
        out = std::filesystem::path("crash-output") / scenario_path.stem();
    std::error_code error;
    std::filesystem::create_directories(out, error);
    if (error)
    {
        std::fprintf(stderr, "crumple-crash: cannot create %s: %s\n", out.string().c_str(), error.message().c_str());
        return cExitBadInput;
    }

    // Run, then the outputs: replay (written during the run), report, deformed mesh, pictures.
    std::printf("crumple-crash: running %s on %s for %.2f s\n", scenario.Get().mName.c_str(),
                ToString(scenario.Get().mEngine), scenario.Get().mDuration);
    Result<CrashOutcome> outcome = RunCrash(scenario.Get(), CrashRunOptions{out / "replay.crumple"});
    if (outcome.HasError())
    {
        std::fprintf(stderr, "crumple-crash: %s\n", outcome.GetError().mMessage.c_str());
        return cExitBadInput;
    }
    const std::vector<ExpectationResult> results = CheckExpectations(scenario.Get(), outcome.Get());
    if (Status status = WriteReportJson(out / "report.json", scenario.Get(), outcome.Get(), results); status.HasError())
    {
        std::fprintf(stderr, "crumple-crash: %s\n", status.GetError().mMessage.c_str());
        return cExitBadInput;
    }
    if (Status status = common::WriteObj(out / "deformed.obj", outcome.Get().mPositions, outcome.Get().mNormals,
                                         outcome.Get().mRestMesh.mTriangles);
        status.HasError())
        std::fprintf(stderr, "crumple-crash: %s\n", status.GetError().mMessage.c_str());
    if (pictures && scenario.Get().mPictures)
        if (Status status = WritePictures(out, outcome.Get()); status.HasError())
            std::printf("crumple-crash: pictures skipped: %s\n", status.GetError().mMessage.c_str());
    if (Status status = WriteReportHtml(out / "report.html", scenario.Get(), outcome.Get(), results, out);
        status.HasError())
        std::fprintf(stderr, "crumple-crash: %s\n", status.GetError().mMessage.c_str());
    PrintSummary(stdout, scenario.Get(), outcome.Get(), results);
    bool passed = true;
    for (const ExpectationResult& result : results)
        passed = passed && result.mPassed;
    std::printf("crumple-crash: %s; report in %s\n", passed ? "all expectations hold" : "an expectation FAILED",
                (out / "report.html").string().c_str());
    return passed ? cExitPass : cExitFail;
}
