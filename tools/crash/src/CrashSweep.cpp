// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/crash/CrashRun.h>
#include <crumple/crash/CrashReport.h>
#include <crumple/crash/CrashSweep.h>

#include "PlotCanvas.h"

#include <crumple/base/FileBytes.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <thread>

namespace crumple::crash
{

namespace
{

constexpr double cKmhPerMs = 3.6;

// One value list "a,b,c" into numbers; false on anything else.
bool ParseList(std::string_view inText, std::vector<double>& outValues)
{
    outValues.clear();
    std::string item;
    std::stringstream stream{std::string(inText)};
    while (std::getline(stream, item, ','))
    {
        char* end = nullptr;
        const double value = std::strtod(item.c_str(), &end);
        if (item.empty() || end != item.c_str() + item.size() || !std::isfinite(value))
            return false;
        outValues.push_back(value);
    }
    return !outValues.empty();
}

std::string CasePath(std::size_t inCase)
{
    char name[32];
    std::snprintf(name, sizeof(name), "case_%06zu.csv", inCase);
    return name;
}

// The case's scenario: speed fastest, then offset, then angle.
CrashScenario CaseScenario(const CrashScenario& inScenario, const CrashSweepSpec& inSpec, std::size_t inCase,
                           double& outSpeed, double& outAngle, double& outOffset)
{
    const std::size_t speeds = inSpec.mSpeeds.size(), offsets = inSpec.mOffsets.size();
    outSpeed = inSpec.mSpeeds[inCase % speeds];
    outOffset = inSpec.mOffsets[(inCase / speeds) % offsets];
    outAngle = inSpec.mAngles[inCase / (speeds * offsets)];
    CrashScenario scenario = inScenario;
    scenario.mImpact.mSpeed = outSpeed;
    // intent: a list not given leaves the scenario's own value (a 30-degree wall stays at 30 degrees)
    if (inSpec.mSweepOffsets)
        scenario.mImpact.mOffset = outOffset;
    else
        outOffset = scenario.mImpact.mOffset;
    if (inSpec.mSweepAngles)
        scenario.mTarget.mAngleDegrees = outAngle;
    else
        outAngle = scenario.mTarget.mAngleDegrees;
    scenario.mPictures = false;
    return scenario;
}

// Runs one case and writes its CSV row (no header) to the cases folder.
void RunCase(const CrashScenario& inScenario, const CrashSweepSpec& inSpec, std::size_t inCase,
             const std::filesystem::path& inCases)
{
    double speed = 0.0, angle = 0.0, offset = 0.0;
    const CrashScenario scenario = CaseScenario(inScenario, inSpec, inCase, speed, angle, offset);
    const Result<CrashOutcome> outcome = RunCrash(scenario, CrashRunOptions{});
    char row[512];
    std::string status; // the row's last field
    if (outcome.HasError())
    {
        std::snprintf(row, sizeof(row), "%zu,%.6g,%.6g,%.6g,,,,,,,,", inCase, speed * cKmhPerMs, angle,
                      offset);
        status = "failed: " + outcome.GetError().mMessage;
    }
    else
    {
        const CrashOutcome& o = outcome.Get();
        // The verdict: ok, or every expectation and sanity check that failed ("failed: a; b").
        const CrashFindings findings = AnalyzeCrash(scenario, o);
        std::string failures;
        for (const ExpectationResult& result : findings.mExpectations)
            if (!result.mPassed)
                failures += (failures.empty() ? "" : "; ") + result.mExpectation.mText;
        for (const SanityResult& check : findings.mSanity)
            if (!check.mPassed)
                failures += (failures.empty() ? "sanity " : "; sanity ") + check.mName;
        // The wall gap's mean where the target is a wall, an empty field otherwise.
        char gap[32] = "";
        if (o.mWallGap)
            std::snprintf(gap, sizeof(gap), "%.9g", o.mWallGap->mMean);
        std::snprintf(row, sizeof(row), "%zu,%.6g,%.6g,%.6g,%.9g,%.9g,%.9g,%.9g,%.9g,%zu,%s,", inCase,
                      speed * cKmhPerMs, angle, offset, o.mResidualCrush[static_cast<int>(EZone::Front)],
                      o.mResidualCrush[static_cast<int>(EZone::Any)], o.DeltaV() * cKmhPerMs,
                      o.EnergyAbsorbed(), o.mTotalImpulse, o.mCollisions.size(), gap);
        status = findings.Passed() ? std::string("ok") : "failed: " + failures;
    }
    // The status is one CSV field: no commas or line breaks inside it.
    std::replace_if(status.begin(), status.end(), [](char c) { return c == ',' || c == '\n'; }, ' ');
    const std::string text = row + status + "\n";
    (void)WriteFileAtomically(inCases / CasePath(inCase), std::as_bytes(std::span(text.data(), text.size())),
                              "crumple-crash sweep");
}

// Field inIndex (0-based) of a CSV row, as a number.
double CsvField(const std::string& inRow, int inIndex)
{
    std::size_t at = 0;
    for (int comma = 0; comma < inIndex && at != std::string::npos; ++comma)
        at = inRow.find(',', at) == std::string::npos ? std::string::npos : inRow.find(',', at) + 1;
    return at == std::string::npos ? std::nan("") : std::strtod(inRow.c_str() + at, nullptr);
}

void DrawProgress(std::FILE* inStream, std::size_t inDone, std::size_t inTotal)
{
    if (inStream == nullptr)
        return;
    constexpr int cBar = 40;
    const int filled = static_cast<int>(cBar * inDone / std::max<std::size_t>(inTotal, 1));
    std::fprintf(inStream, "\r  [%s%s] %zu/%zu cases", std::string(filled, '#').c_str(),
                 std::string(cBar - filled, ' ').c_str(), inDone, inTotal);
    std::fflush(inStream);
}

} // namespace

Status CheckSweepFitsScenario(const CrashScenario& inScenario, const CrashSweepSpec& inSpec)
{
    // intent: only a rigid wall turns: on other targets every angle would be the same case, labelled apart
    const bool turned = std::any_of(inSpec.mAngles.begin(), inSpec.mAngles.end(), [](double inAngle) { return inAngle != 0.0; });
    if (inSpec.mSweepAngles && turned && inScenario.mTarget.mType != ETarget::RigidWall)
        return MakeError(EError::InvalidArgument, "--sweep: angles_deg other than 0 turn a rigid_wall target only");
    return Status::Ok();
}

Result<CrashSweepSpec> ParseCrashSweep(std::string_view inText)
{
    CrashSweepSpec spec;
    std::string part;
    std::stringstream stream{std::string(inText)};
    while (std::getline(stream, part, ';'))
    {
        const std::size_t equals = part.find('=');
        const std::string name = part.substr(0, equals);
        std::vector<double> values;
        if (equals == std::string::npos || !ParseList(std::string_view(part).substr(equals + 1), values))
            return MakeError(EError::InvalidArgument, "--sweep: '" + part + "' is not name=v1,v2,...");
        if (name == "speeds_km_h")
        {
            // intent: the scenario file's ranges (a speed of 1e300 km/h killed the worker, and its row said so
            // for every case)
            for (double& value : values)
            {
                if (!(value > 0.0 && value <= 3600.0))
                    return MakeError(EError::InvalidArgument, "--sweep: speeds_km_h must lie in (0, 3600]");
                value /= cKmhPerMs;
            }
            spec.mSpeeds = values;
        }
        else if (name == "speeds_m_s")
        {
            for (double value : values)
                if (!(value > 0.0 && value <= 1000.0))
                    return MakeError(EError::InvalidArgument, "--sweep: speeds_m_s must lie in (0, 1000]");
            spec.mSpeeds = values;
        }
        else if (name == "angles_deg")
        {
            for (double value : values)
                if (!(value > -90.0 && value < 90.0))
                    return MakeError(EError::InvalidArgument, "--sweep: angles_deg must lie in (-90, 90)");
            spec.mAngles = values;
            spec.mSweepAngles = true;
        }
        else if (name == "offsets_m")
        {
            for (double value : values)
                if (!(value > -1000.0 && value < 1000.0))
                    return MakeError(EError::InvalidArgument, "--sweep: offsets_m must lie in (-1000, 1000)");
            spec.mOffsets = values;
            spec.mSweepOffsets = true;
        }
        else
            return MakeError(EError::InvalidArgument, "--sweep: unknown list '" + name +
                                                          "' (known: speeds_km_h, speeds_m_s, angles_deg, offsets_m)");
    }
    if (spec.mSpeeds.empty())
        return MakeError(EError::InvalidArgument, "--sweep: speeds_km_h (or speeds_m_s) is required");
    return spec;
}

Status RunCrashSweepCases(const CrashScenario& inScenario, const CrashSweepSpec& inSpec, std::size_t inFirst,
                          std::size_t inCount, const std::filesystem::path& inFolder)
{
    if (Status fits = CheckSweepFitsScenario(inScenario, inSpec); fits.HasError())
        return fits;
    const std::filesystem::path cases = inFolder / "cases";
    std::error_code error;
    std::filesystem::create_directories(cases, error);
    if (error)
        return MakeError(EError::IoError, "cannot create " + cases.string() + ": " + error.message());
    const std::size_t total = inSpec.GetCaseCount();
    for (std::size_t index = inFirst; index < total && index - inFirst < inCount; ++index)
        RunCase(inScenario, inSpec, index, cases);
    return Status::Ok();
}

Result<int> RunCrashSweep(const CrashScenario& inScenario, const CrashSweepSpec& inSpec, int inWorkers,
                          const std::filesystem::path& inFolder, std::FILE* inProgress)
{
    if (inWorkers < 1)
        return MakeError(EError::InvalidArgument, "--workers must be >= 1");
    if (Status fits = CheckSweepFitsScenario(inScenario, inSpec); fits.HasError())
        return fits.GetError();
    const std::filesystem::path cases = inFolder / "cases";
    std::error_code error;
    std::filesystem::remove_all(cases, error);
    std::filesystem::create_directories(cases, error);
    if (error)
        return MakeError(EError::IoError, "cannot create " + cases.string() + ": " + error.message());
    const std::size_t total = inSpec.GetCaseCount();
    // Worker processes: case i in worker i mod N. Each case is a separate, deterministic run, so which
    // process runs it does not change its row.
    std::fflush(nullptr);
    std::vector<pid_t> workers;
    for (int worker = 0; worker < inWorkers; ++worker)
    {
        const pid_t pid = fork();
        if (pid < 0)
            return MakeError(EError::IoError, "cannot start a worker process");
        if (pid == 0)
        {
            for (std::size_t index = static_cast<std::size_t>(worker); index < total; index += inWorkers)
                RunCase(inScenario, inSpec, index, cases);
            std::_Exit(0);
        }
        workers.push_back(pid);
    }

    // Progress: count the rows written, until every worker has finished.
    std::size_t running = workers.size();
    while (running > 0)
    {
        for (pid_t& pid : workers)
            if (pid > 0 && waitpid(pid, nullptr, WNOHANG) == pid)
            {
                pid = 0;
                --running;
            }
        std::size_t done = 0;
        for (std::size_t index = 0; index < total; ++index)
            done += std::filesystem::exists(cases / CasePath(index)) ? 1 : 0;
        DrawProgress(inProgress, done, total);
        if (running > 0)
            std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    if (inProgress != nullptr)
        std::fprintf(inProgress, "\n");

    return MergeCrashSweep(inScenario, inSpec, inFolder, inProgress);
}

Result<int> MergeCrashSweep(const CrashScenario& inScenario, const CrashSweepSpec& inSpec,
                            const std::filesystem::path& inFolder, std::FILE* inProgress)
{
    const std::filesystem::path cases = inFolder / "cases";
    const std::size_t total = inSpec.GetCaseCount();
    // Rows in case order, then the plot.
    std::string csv = "case,speed_km_h,wall_angle_deg,offset_m,front_crush_m,max_crush_m,delta_v_km_h,"
                      "energy_absorbed_J,total_impulse_N_s,collisions,wall_gap_m,status\n";
    int failed = 0;
    std::vector<std::array<double, 2>> points, failed_points;
    for (std::size_t index = 0; index < total; ++index)
    {
        Result<std::vector<std::byte>> row = ReadFileBytes(cases / CasePath(index));
        if (row.HasError())
        {
            ++failed;
            csv += std::to_string(index) + ",,,,,,,,,,,failed: the worker wrote no row\n";
            continue;
        }
        const std::string text(reinterpret_cast<const char*>(row.Get().data()), row.Get().size());
        csv += text;
        const bool ok = text.find(",ok\n") != std::string::npos;
        if (!ok)
        {
            ++failed;
            // Say which case and why (the row's last field).
            if (inProgress != nullptr)
                std::fprintf(inProgress, "  case %zu %s", index, text.substr(text.rfind(',') + 1).c_str());
        }
        // A case that ran but failed a check still has its crush: it is drawn in its own colour.
        double speed = 0.0, angle = 0.0, offset = 0.0;
        (void)CaseScenario(inScenario, inSpec, index, speed, angle, offset);
        const double crush = CsvField(text, 4);
        if (std::isfinite(crush))
            (ok ? points : failed_points).push_back({speed * cKmhPerMs, crush});
    }
    if (Status status = WriteFileAtomically(inFolder / "sweep.csv", std::as_bytes(std::span(csv.data(), csv.size())),
                                            "crumple-crash sweep");
        status.HasError())
        return status.GetError();

    // Plot: front residual crush against impact speed (x to 10 km/h above the fastest, y from 0).
    CrushSpeedChart chart;
    chart.mRightKmh = 10.0;
    for (const auto& point : points)
    {
        chart.mRightKmh = std::max(chart.mRightKmh, point[0]);
        chart.mTop = std::max(chart.mTop, point[1]);
    }
    for (const auto& point : failed_points)
    {
        chart.mRightKmh = std::max(chart.mRightKmh, point[0]);
        chart.mTop = std::max(chart.mTop, point[1]);
    }
    chart.mRightKmh = std::ceil(chart.mRightKmh / 10.0 + 1.0) * 10.0;
    chart.mTop = std::ceil(chart.mTop * 10.0 + 0.5) / 10.0;
    PlotCanvas canvas = chart.Draw();
    auto x_of = [&](double inKmh) { return chart.X(inKmh); };
    auto y_of = [&](double inCrush) { return chart.Y(inCrush); };
    for (const auto& point : points)
        canvas.Disc(x_of(point[0]), y_of(point[1]), 6.0, {210, 30, 30});
    for (const auto& point : failed_points)
        canvas.Disc(x_of(point[0]), y_of(point[1]), 6.0, {240, 150, 20});
    CrushSpeedChart::AddLegend(canvas, 1, {210, 30, 30}, "simulated cases");
    if (!failed_points.empty())
        CrushSpeedChart::AddLegend(canvas, 2, {240, 150, 20}, "cases that failed a check (sweep.csv says which)");
    if (Status status = canvas.Save(inFolder / "sweep.png"); status.HasError())
        return status.GetError();
    return failed;
}

} // namespace crumple::crash
