// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// crumple-crash: a scenario in, a verdict, numbers and pictures out. Exit 0 when every expectation holds,
// 1 when one fails (printing which, with the measured value), 2 for a bad scenario or command line (nothing
// written).
#include <crumple/base/Version.h>
#include <crumple/crash/Calibration.h>
#include <crumple/crash/CrashReport.h>
#include <crumple/crash/CrashSweep.h>
#include <crumple/crash/SlurmSweep.h>
#include <crumple/crash/SanityChecks.h>
#include <crumple/crash/TimeHistory.h>
#include <crumple/crash/ScenarioFile.h>

#include "ObjWriter.h"
#include "OutputFolders.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <cstdlib>
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
    std::fprintf(
        inStream,
        "usage: crumple-crash SCENARIO.json [--out DIR] [--no-pictures]\n"
        "  Runs a crash scenario (schema: docs/scenarios.md) and writes into DIR (default\n"
        "  crash-output/<scenario file name>): report.json, deformed.obj, replay.crumple (replay it with\n"
        "  crumple-replay) and PNG pictures. Exit status: 0 all expectations hold, 1 one failed,\n"
        "  2 bad scenario or command line (nothing written).\n"
        "  --no-pictures  skip the renders (no EGL context is made)\n"
        "  --colour-max M the dent colour scale's top (m; default: the deepest dent rounded up to 1, 2,\n"
        "                 2.5 or 5 x 10^k, as crumple-replay does, so the same damage gets the same "
        "colours)\n"
        "  --strict       refuse a scenario that would run with a warning: a mesh whose stated forward\n"
        "                 axis is not its longest extent, rigid-part names that match no part,\n"
        "                 a time step in which the car closes more than it overlaps its target across\n"
        "                 its path (without it the run goes on and the report carries the warning)\n"
        "  --calibrate --b0 B0 --b1 B1 [--preset-name NAME] [--source TEXT]\n"
        "      fit the vehicle material so that the scenario (a full-frontal rigid-wall crash) reproduces\n"
        "      Campbell's line C = (v - B0) / B1 (B0 in m/s, B1 in 1/s) at 20, 30, 40, 48, 56 and 64 km/h;\n"
        "      writes preset.json, calibration.csv and calibration.png (crush against speed: the line and\n"
        "      the simulated points); exit 0 when every point is within 10 %% of the line, else 1\n"
        "  --sweep \"speeds_km_h=20,40,60;angles_deg=0,30;offsets_m=0\" [--workers N]\n"
        "      every combination as a case, in N worker processes (default 2): sweep.csv (one row per\n"
        "      case, in case order whatever N) and sweep.png (front crush against speed)\n"
        "  --sweep SPEC --emit-slurm DIR [--cases-per-task N] [--slurm-time T] [--slurm-cpus C]\n"
        "          [--slurm-mem M] [--slurm-partition P]\n"
        "      the sweep as a Slurm job array for a cluster that shares DIR: DIR/submit.sh submits\n"
        "      sweep_array.sbatch (N cases per task, default 1; time T, default 00:30:00) and then\n"
        "      sweep_merge.sbatch, which writes DIR/sweep.csv and sweep.png byte for byte as a local\n"
        "      --sweep would (tasks run --sweep-task K --cases-per-task N, the merge --sweep-merge)\n"
        "  --campbell-check --b0 B0 --b1 B1\n"
        "      the same speeds with the scenario's material as it is: csv, plot, exit 0 within 10 %%\n"
        "  --impulse-tolerance F\n"
        "      sanity check impulse_momentum: largest relative difference between Crumple's impulses on\n"
        "      the car and its momentum change over the collisions (default 0.05). Every run is also\n"
        "      checked for tunnelling, energy balance and folded vertices; a failed sanity check exits 1\n"
        "  --help, --version\n");
}

// Calibration to, or a check against, Campbell's line (see PrintUsage).
int RunCampbell(const CrashScenario& inScenario, const CampbellLine& inLine, bool inCalibrate,
                const std::string& inPresetName, const std::string& inSource, const std::filesystem::path& inOut)
{
    const std::vector<double> speeds = {20.0 / 3.6, 30.0 / 3.6, 40.0 / 3.6, 48.0 / 3.6, 56.0 / 3.6, 64.0 / 3.6};
    std::vector<CampbellPoint> points;
    if (inCalibrate)
    {
        std::printf("crumple-crash: calibrating %s to C = (v - %.3f m/s) / %.3f s^-1\n", inScenario.mName.c_str(),
                    inLine.mNoDamageSpeed, inLine.mSlope);
        Result<VehicleSpec> vehicle = CalibrateToCampbell(inScenario, inLine, speeds, 3, points);
        if (vehicle.HasError())
        {
            std::fprintf(stderr, "crumple-crash: %s\n", vehicle.GetError().mMessage.c_str());
            return cExitBadInput;
        }
        if (Status status = WritePresetFile(inOut / "preset.json", inPresetName, inSource, inLine, vehicle.Get());
            status.HasError())
        {
            std::fprintf(stderr, "crumple-crash: %s\n", status.GetError().mMessage.c_str());
            return cExitBadInput;
        }
        std::printf("  deformation factor %.6g m/(N s), impulse threshold %.6g N s -> %s\n",
                    vehicle.Get().mMaterial.mDeformationFactor, vehicle.Get().mMaterial.mImpulseThreshold,
                    (inOut / "preset.json").string().c_str());
    }
    else
    {
        Result<std::vector<CampbellPoint>> run = RunCampbellSpeeds(inScenario, inLine, speeds);
        if (run.HasError())
        {
            std::fprintf(stderr, "crumple-crash: %s\n", run.GetError().mMessage.c_str());
            return cExitBadInput;
        }
        points = run.Get();
    }
    double worst = 0.0;
    std::printf("  speed_km_h  model_m  simulated_m  error\n");
    for (const CampbellPoint& point : points)
    {
        std::printf("  %10.1f  %7.3f  %11.3f  %+5.1f %%\n", point.mSpeed * 3.6, point.mModel, point.mCrush,
                    100.0 * (point.mCrush - point.mModel) / point.mModel);
        // intent: a point the line gives no crush for (or a non-finite error) fails the check, never passes it
        const double error = point.RelativeError();
        worst = std::isfinite(error) && point.mModel > 0.0 ? std::max(worst, error) : std::numeric_limits<double>::infinity();
    }
    (void)WriteCampbellCsv(inOut / "calibration.csv", points);
    if (Status status = WriteCampbellPlot(inOut / "calibration.png", inLine, points); status.HasError())
        std::fprintf(stderr, "crumple-crash: %s\n", status.GetError().mMessage.c_str());
    std::printf("crumple-crash: largest deviation from the line %.1f %% (limit 10 %%); plot %s\n", 100.0 * worst,
                (inOut / "calibration.png").string().c_str());
    return worst <= 0.10 ? cExitPass : cExitFail;
}

} // namespace

int Run(const CrashScenario& inScenario, const std::string& inSweep, const CrashSweepSpec& inSweepSpec, int inWorkers,
        bool inCampbell, bool inCalibrate, const CampbellLine& inLine, const std::string& inPresetName,
        const std::string& inSource, bool inPictures, double inColourMax, bool inStrict, const std::filesystem::path& inOut);

int main(int argc, char** argv)
{
    std::filesystem::path scenario_path, out;
    bool pictures = true, calibrate = false, campbell_check = false, strict = false;
    double colour_max = 0.0; // 0: the deepest dent, rounded up (samples::DentColorScale)
    CampbellLine line{std::nan(""), std::nan("")};
    double impulse_tolerance = std::numeric_limits<double>::quiet_NaN();
    std::string preset_name = "calibrated", source = "crumple-crash --calibrate", sweep;
    int workers = 2;
    // Slurm: write the job (--emit-slurm), run one array task's cases (--sweep-task), or merge (--sweep-merge)
    std::filesystem::path emit_slurm;
    SlurmSweepSettings slurm;
    long long sweep_task = -1;
    bool sweep_merge = false;
    auto number = [](const char* inText, double& outValue)
    {
        char* end = nullptr;
        outValue = std::strtod(inText, &end);
        return end != inText && *end == '\0' && std::isfinite(outValue);
    };
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
        if (arg == "--strict")
            strict = true;
        else if (arg == "--no-pictures")
            pictures = false;
        else if (arg == "--colour-max" && i + 1 < argc)
        {
            if (!number(argv[++i], colour_max) || !(colour_max > 0.0))
            {
                std::fprintf(stderr, "crumple-crash: --colour-max needs a number > 0 (m), got '%s'\n", argv[i]);
                return cExitBadInput;
            }
        }
        else if (arg == "--calibrate")
            calibrate = true;
        else if (arg == "--campbell-check")
            campbell_check = true;
        else if ((arg == "--b0" || arg == "--b1") && i + 1 < argc)
        {
            double& value = arg == "--b0" ? line.mNoDamageSpeed : line.mSlope;
            if (!number(argv[++i], value))
            {
                std::fprintf(stderr, "crumple-crash: %s needs a finite number, got '%s'\n", arg.c_str(), argv[i]);
                return cExitBadInput;
            }
        }
        else if (arg == "--sweep" && i + 1 < argc)
            sweep = argv[++i];
        else if (arg == "--workers" && i + 1 < argc)
        {
            double value = 0.0;
            if (!number(argv[++i], value) || value < 1.0 || value > 256.0 || value != std::floor(value))
            {
                std::fprintf(stderr, "crumple-crash: --workers needs an integer in [1, 256], got '%s'\n", argv[i]);
                return cExitBadInput;
            }
            workers = static_cast<int>(value);
        }
        else if (arg == "--emit-slurm" && i + 1 < argc)
            emit_slurm = argv[++i];
        else if ((arg == "--sweep-task" || arg == "--cases-per-task" || arg == "--slurm-cpus") && i + 1 < argc)
        {
            double value = 0.0;
            const double low = arg == "--sweep-task" ? 0.0 : 1.0;
            if (!number(argv[++i], value) || value < low || value > 1.0e9 || value != std::floor(value))
            {
                std::fprintf(stderr, "crumple-crash: %s needs an integer >= %g, got '%s'\n", arg.c_str(), low, argv[i]);
                return cExitBadInput;
            }
            if (arg == "--sweep-task")
                sweep_task = static_cast<long long>(value);
            else if (arg == "--cases-per-task")
                slurm.mCasesPerTask = static_cast<std::size_t>(value);
            else
                slurm.mCpusPerTask = static_cast<int>(std::min(value, 1.0e6));
        }
        else if (arg == "--sweep-merge")
            sweep_merge = true;
        else if (arg == "--slurm-time" && i + 1 < argc)
            slurm.mTime = argv[++i];
        else if (arg == "--slurm-mem" && i + 1 < argc)
            slurm.mMemory = argv[++i];
        else if (arg == "--slurm-partition" && i + 1 < argc)
            slurm.mPartition = argv[++i];
        else if (arg == "--impulse-tolerance" && i + 1 < argc)
        {
            if (!number(argv[++i], impulse_tolerance) || !(impulse_tolerance > 0.0 && impulse_tolerance <= 1.0))
            {
                std::fprintf(stderr, "crumple-crash: --impulse-tolerance needs a number in (0, 1], got '%s'\n", argv[i]);
                return cExitBadInput;
            }
        }
        else if (arg == "--preset-name" && i + 1 < argc)
            preset_name = argv[++i];
        else if (arg == "--source" && i + 1 < argc)
            source = argv[++i];
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
        // LoadCrashScenario's messages name the file already
        std::fprintf(stderr, "crumple-crash: %s\n", scenario.GetError().mMessage.c_str());
        return cExitBadInput;
    }
    if (!std::isnan(impulse_tolerance))
        scenario.Get().mImpulseTolerance = impulse_tolerance;
    // intent: bounds of real cars' lines (b0 2-5 m/s, b1 15-40 1/s) with wide margins: a b0 given in km/h gave no
    // model crush at all (every error NaN, reported as 0 % and passed), a b1 of 1e-300 hung the plot
    if ((calibrate || campbell_check) &&
        !(line.mNoDamageSpeed >= 0.0 && line.mNoDamageSpeed < 5.5 && line.mSlope >= 1.0 && line.mSlope <= 1000.0))
    {
        std::fprintf(stderr, "crumple-crash: --calibrate and --campbell-check need --b0 in [0, 5.5) m/s (below the "
                             "lowest speed they run, 20 km/h) and --b1 in [1, 1000] 1/s (Campbell's line: crush = (v - b0) / b1)\n");
        return cExitBadInput;
    }
    // intent: Campbell's line is measured in full-width rigid-barrier tests; fitted to another hit it would
    // make a preset that crushes the wrong amount everywhere, and with --sweep it was ignored unsaid
    if (calibrate || campbell_check)
    {
        const TargetSpec& target = scenario.Get().mTarget;
        const ImpactSpec& impact = scenario.Get().mImpact;
        const char* mode = calibrate ? "--calibrate" : "--campbell-check";
        if (calibrate && campbell_check)
        {
            std::fprintf(stderr, "crumple-crash: give --calibrate or --campbell-check, not both\n");
            return cExitBadInput;
        }
        if (!sweep.empty())
        {
            std::fprintf(stderr, "crumple-crash: %s runs its own speeds: it cannot be combined with --sweep\n", mode);
            return cExitBadInput;
        }
        if (target.mType != ETarget::RigidWall || target.mAngleDegrees != 0.0 || impact.mOffset != 0.0 || impact.mHeadingDegrees != 0.0)
        {
            std::fprintf(stderr, "crumple-crash: %s needs a full-frontal rigid-wall scenario (target rigid_wall at 0 degrees, no "
                                 "offset, no heading): Campbell's line comes from such tests\n", mode);
            return cExitBadInput;
        }
    }
    Result<CrashSweepSpec> sweep_spec = CrashSweepSpec{};
    if (!sweep.empty())
    {
        sweep_spec = ParseCrashSweep(sweep);
        if (sweep_spec.HasError())
        {
            std::fprintf(stderr, "crumple-crash: %s\n", sweep_spec.GetError().mMessage.c_str());
            return cExitBadInput;
        }
        if (Status fits = CheckSweepFitsScenario(scenario.Get(), sweep_spec.Get()); fits.HasError())
        {
            std::fprintf(stderr, "crumple-crash: %s\n", fits.GetError().mMessage.c_str());
            return cExitBadInput;
        }
    }
    const int slurm_modes = (emit_slurm.empty() ? 0 : 1) + (sweep_task >= 0 ? 1 : 0) + (sweep_merge ? 1 : 0);
    if (slurm_modes > 1 || (slurm_modes == 1 && sweep.empty()))
    {
        std::fprintf(stderr, "crumple-crash: --emit-slurm, --sweep-task and --sweep-merge each need --sweep, and one at a time\n");
        return cExitBadInput;
    }
    if (!emit_slurm.empty())
    {
        std::error_code self_error;
        slurm.mExecutable = std::filesystem::read_symlink("/proc/self/exe", self_error);
        if (self_error)
            slurm.mExecutable = std::filesystem::absolute(argv[0], self_error);
        Result<std::size_t> tasks = WriteSlurmSweep(scenario_path, sweep, sweep_spec.Get(), slurm, emit_slurm);
        if (tasks.HasError())
        {
            std::fprintf(stderr, "crumple-crash: %s\n", tasks.GetError().mMessage.c_str());
            return cExitBadInput;
        }
        std::printf("crumple-crash: %zu cases as a Slurm array of %zu tasks; submit with %s\n", sweep_spec.Get().GetCaseCount(),
                    tasks.Get(), (emit_slurm / "submit.sh").string().c_str());
        return cExitPass;
    }
    if (out.empty())
        out = std::filesystem::path("crash-output") / scenario_path.stem();
    if (sweep_task >= 0)
    {
        // One array task: its cases' rows, nothing else (the merge decides the verdict).
        const std::size_t first = static_cast<std::size_t>(sweep_task) * slurm.mCasesPerTask;
        if (first >= sweep_spec.Get().GetCaseCount())
        {
            std::fprintf(stderr, "crumple-crash: --sweep-task %lld starts past the sweep's %zu cases\n", sweep_task,
                         sweep_spec.Get().GetCaseCount());
            return cExitBadInput;
        }
        if (Status status = RunCrashSweepCases(scenario.Get(), sweep_spec.Get(), first, slurm.mCasesPerTask, out); status.HasError())
        {
            std::fprintf(stderr, "crumple-crash: %s\n", status.GetError().mMessage.c_str());
            return cExitBadInput;
        }
        return cExitPass;
    }
    if (sweep_merge)
    {
        Result<int> failed = MergeCrashSweep(scenario.Get(), sweep_spec.Get(), out, stdout);
        if (failed.HasError())
        {
            std::fprintf(stderr, "crumple-crash: %s\n", failed.GetError().mMessage.c_str());
            return cExitBadInput;
        }
        std::printf("crumple-crash: %d of %zu cases failed; %s, %s\n", failed.Get(), sweep_spec.Get().GetCaseCount(),
                    (out / "sweep.csv").string().c_str(), (out / "sweep.png").string().c_str());
        return failed.Get() == 0 ? cExitPass : cExitFail;
    }
    std::error_code error;
    // The folders this run makes: the output folder and the parents of it that do not exist yet (--out a/b/c
    // in an empty folder makes a, a/b and a/b/c).
    const std::vector<std::filesystem::path> made_folders = FoldersToMake(out);
    std::filesystem::create_directories(out, error);
    if (error)
    {
        std::fprintf(stderr, "crumple-crash: cannot create %s: %s\n", out.string().c_str(), error.message().c_str());
        RemoveMadeFolders(made_folders); // the parents it made before it failed
        return cExitBadInput;
    }
    // A run that fails (a mesh that assimp cannot read, a recording that cannot be written) leaves nothing,
    // not even the parent folders it made.
    const int status = Run(scenario.Get(), sweep, sweep_spec.Get(), workers, calibrate || campbell_check, calibrate,
                           line, preset_name, source, pictures, colour_max, strict, out);
    if (status == cExitBadInput)
        RemoveMadeFolders(made_folders);
    return status;
}

int Run(const CrashScenario& inScenario, const std::string& inSweep, const CrashSweepSpec& inSweepSpec, int inWorkers,
        bool inCampbell, bool inCalibrate, const CampbellLine& inLine, const std::string& inPresetName,
        const std::string& inSource, bool inPictures, double inColourMax, bool inStrict, const std::filesystem::path& inOut)
{
    const CrashScenario& scenario = inScenario;
    const std::filesystem::path& out = inOut;

    if (!inSweep.empty())
    {
        std::printf("crumple-crash: sweeping %s over %zu cases in %d workers\n", scenario.mName.c_str(),
                    inSweepSpec.GetCaseCount(), inWorkers);
        Result<int> failed = RunCrashSweep(scenario, inSweepSpec, inWorkers, out, stdout);
        if (failed.HasError())
        {
            std::fprintf(stderr, "crumple-crash: %s\n", failed.GetError().mMessage.c_str());
            return cExitBadInput;
        }
        std::printf("crumple-crash: %d of %zu cases failed; %s, %s\n", failed.Get(), inSweepSpec.GetCaseCount(),
                    (out / "sweep.csv").string().c_str(), (out / "sweep.png").string().c_str());
        return failed.Get() == 0 ? cExitPass : cExitFail;
    }
    if (inCampbell)
        return RunCampbell(scenario, inLine, inCalibrate, inPresetName, inSource, out);

    // Run, then the outputs: replay (written during the run), report, deformed mesh, pictures.
    std::printf("crumple-crash: running %s on %s for %.2f s\n", scenario.mName.c_str(),
                ToString(scenario.mEngine), scenario.mDuration);
    Result<CrashOutcome> outcome = RunCrash(scenario, CrashRunOptions{out / "replay.crumple", inStrict});
    if (outcome.HasError())
    {
        std::fprintf(stderr, "crumple-crash: %s\n", outcome.GetError().mMessage.c_str());
        return cExitBadInput;
    }
    const CrashFindings findings = AnalyzeCrash(scenario, outcome.Get());
    if (Status status = WriteReportJson(out / "report.json", scenario, outcome.Get(), findings); status.HasError())
    {
        std::fprintf(stderr, "crumple-crash: %s\n", status.GetError().mMessage.c_str());
        return cExitBadInput;
    }
    if (Status status = WriteTimeSeriesCsv(out / "timeseries.csv", findings.mHistory); status.HasError())
        std::fprintf(stderr, "crumple-crash: %s\n", status.GetError().mMessage.c_str());
    if (Status status = common::WriteObj(out / "deformed.obj", outcome.Get().mPositions, outcome.Get().mNormals,
                                         outcome.Get().mRestMesh.mTriangles);
        status.HasError())
        std::fprintf(stderr, "crumple-crash: %s\n", status.GetError().mMessage.c_str());
    if (inPictures && scenario.mPictures)
    {
        if (Status status = WritePictures(out, outcome.Get(), inColourMax); status.HasError())
            std::printf("crumple-crash: pictures skipped: %s\n", status.GetError().mMessage.c_str());
        if (Status status = WriteTimeHistoryPlots(out, findings.mHistory); status.HasError())
            std::printf("crumple-crash: time-history plots skipped: %s\n", status.GetError().mMessage.c_str());
    }
    if (Status status = WriteReportHtml(out / "report.html", scenario, outcome.Get(), findings, out);
        status.HasError())
        std::fprintf(stderr, "crumple-crash: %s\n", status.GetError().mMessage.c_str());
    PrintSummary(stdout, scenario, outcome.Get(), findings);
    std::printf("crumple-crash: %s; report in %s\n",
                !findings.Sane()              ? "a sanity check FAILED: the run is not physically sound"
                : findings.ExpectationsHold() ? "all expectations hold"
                                              : "an expectation FAILED",
                (out / "report.html").string().c_str());
    return findings.Passed() ? cExitPass : cExitFail;
}
