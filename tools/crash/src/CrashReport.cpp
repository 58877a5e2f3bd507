// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/crash/CrashReport.h>

#include "ScenePainter.h"

#include <crumple/base/FileBytes.h>
#include <crumple/ffd/BoundingBox.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <initializer_list>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>

namespace crumple::crash
{

namespace
{

constexpr double cKmhPerMs = 3.6;

nlohmann::json ToJson(const Vec3& inValue)
{
    return nlohmann::json::array({inValue.x(), inValue.y(), inValue.z()});
}

// RFC 4648 base64 of a byte string (for data: URLs).
std::string Base64(std::span<const std::byte> inBytes)
{
    static constexpr char cAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string text;
    text.reserve((inBytes.size() + 2) / 3 * 4);
    for (std::size_t i = 0; i < inBytes.size(); i += 3)
    {
        const std::size_t count = std::min<std::size_t>(3, inBytes.size() - i);
        std::uint32_t chunk = 0;
        for (std::size_t k = 0; k < 3; ++k)
            chunk = (chunk << 8) | (k < count ? std::to_integer<std::uint32_t>(inBytes[i + k]) : 0u);
        for (std::size_t k = 0; k < 4; ++k)
            text += k <= count ? cAlphabet[(chunk >> (18 - 6 * k)) & 63u] : '=';
    }
    return text;
}

// Text safe inside HTML.
std::string Escape(const std::string& inText)
{
    std::string escaped;
    for (char c : inText)
        escaped += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : c == '"' ? "&quot;" : std::string(1, c);
    return escaped;
}

std::string Number(double inValue, int inDigits)
{
    char text[64];
    std::snprintf(text, sizeof(text), "%.*f", inDigits, inValue);
    return text;
}

// One line on how the mesh was re-cut: the counts a user checks against the file and the flips that moved
// its surface within the stated deviation.
std::string MeshPreparationText(const MeshPreparation& inMesh)
{
    std::string text = "mesh: " + std::to_string(inMesh.mFileTriangles) + " triangles and " +
                       std::to_string(inMesh.mFileVertices) + " vertices from the file";
    if (!(inMesh.mMaxEdge > 0.0))
        return text + ", as they are (mesh_max_edge_m 0)";
    text += ", re-cut to " + std::to_string(inMesh.mTriangles) + " and " + std::to_string(inMesh.mVertices) +
            " (edges up to " + Number(inMesh.mMaxEdge, 3) + " m; ";
    if (inMesh.mLooseSlivers > 0)
        text += std::to_string(inMesh.mLooseSlivers) + " zero-area triangles that bounded nothing removed, ";
    text += std::to_string(inMesh.mFlatFlips) + " flips in flat parts";
    if (inMesh.mFlipDeviation > 0.0)
        text += ", " + std::to_string(inMesh.mNearlyFlatFlips) + " within " + Number(inMesh.mFlipDeviation, 4) + " m";
    return text + ", " + std::to_string(inMesh.mCapSplitVertices) + " vertices added to split caps)";
}

} // namespace

std::vector<ExpectationResult> CheckExpectations(const CrashScenario& inScenario, const CrashOutcome& inOutcome)
{
    std::vector<ExpectationResult> results;
    for (const Expectation& expectation : inScenario.mExpectations)
    {
        const double value = inOutcome.Measure(expectation);
        results.push_back({expectation, value, value >= expectation.mMin && value <= expectation.mMax});
    }
    return results;
}

bool CrashFindings::ExpectationsHold() const
{
    return std::all_of(mExpectations.begin(), mExpectations.end(),
                       [](const ExpectationResult& inResult) { return inResult.mPassed; });
}

CrashFindings AnalyzeCrash(const CrashScenario& inScenario, const CrashOutcome& inOutcome)
{
    return {CheckExpectations(inScenario, inOutcome), CheckSanity(inScenario, inOutcome), MakeTimeHistory(inOutcome)};
}

Status WriteReportJson(const std::filesystem::path& inPath, const CrashScenario& inScenario,
                       const CrashOutcome& inOutcome, const CrashFindings& inFindings)
{
    nlohmann::json report;
    report["scenario"] = inScenario.mName;
    report["engine"] = ToString(inScenario.mEngine);
    report["impact_speed_m_s"] = inScenario.mImpact.mSpeed;
    report["mass_kg"] = inOutcome.mMass;
    nlohmann::json crush;
    for (EZone zone : {EZone::Any, EZone::Front, EZone::Rear, EZone::Left, EZone::Right, EZone::Roof})
        crush[ToString(zone)] = inOutcome.mResidualCrush[static_cast<int>(zone)];
    report["residual_crush_m"] = crush;
    if (!std::isnan(inOutcome.mTargetResidualCrush))
        report["target_vehicle_residual_crush_m"] = inOutcome.mTargetResidualCrush;
    if (inOutcome.mBarrierFragments > 0)
    {
        report["barrier_fragments"] = inOutcome.mBarrierFragments;
        report["barrier_broken_links"] = inOutcome.mBarrierBrokenLinks;
        report["barrier_momentum_N_s"] = ToJson(inOutcome.mBarrierMomentum);
        report["barrier_breached_at_s"] = std::isnan(inOutcome.mBarrierBreachTime) ? nlohmann::json(nullptr)
                                                                                  : nlohmann::json(inOutcome.mBarrierBreachTime);
    }
    report["total_impulse_N_s"] = inOutcome.mTotalImpulse;
    report["peak_impulse_N_s"] = inOutcome.mPeakImpulse;
    report["delta_v_m_s"] = inOutcome.DeltaV();
    report["delta_v_km_h"] = inOutcome.DeltaV() * cKmhPerMs;
    report["energy_absorbed_J"] = inOutcome.EnergyAbsorbed();
    report["start_velocity_m_s"] = ToJson(inOutcome.mStartVelocity);
    report["end_velocity_m_s"] = ToJson(inOutcome.mEndVelocity);
    nlohmann::json collisions = nlohmann::json::array();
    for (const CrashCollisionRecord& collision : inOutcome.mCollisions)
        collisions.push_back({{"start_s", collision.mStartTime},
                              {"end_s", collision.mEndTime},
                              {"impulse_N_s", collision.mImpulse},
                              {"contacts", collision.mContacts}});
    report["collisions"] = collisions;
    report["folded_vertices"] = inOutcome.mFoldedVertices;
    report["folded_triangles"] = inOutcome.mFoldedTriangles;
    report["warnings"] = inOutcome.mWarnings;
    if (const std::optional<MeshPreparation>& mesh = inOutcome.mMeshPreparation)
        report["mesh_preparation"] = {{"file_triangles", mesh->mFileTriangles},
                                      {"file_vertices", mesh->mFileVertices},
                                      {"triangles", mesh->mTriangles},
                                      {"vertices", mesh->mVertices},
                                      {"max_edge_m", mesh->mMaxEdge},
                                      {"flat_flips", mesh->mFlatFlips},
                                      {"flip_deviation_m", mesh->mFlipDeviation},
                                      {"nearly_flat_flips", mesh->mNearlyFlatFlips},
                                      {"cap_split_vertices", mesh->mCapSplitVertices},
                                      {"loose_slivers", mesh->mLooseSlivers}};
    else
        report["mesh_preparation"] = nullptr;
    report["crush_profile"] = {{"face", CarFaceName(inOutcome.mCrushProfile.mFace)},
                               {"damage_width_m", inOutcome.mCrushProfile.mDamageWidth},
                               {"C_m", inOutcome.mCrushProfile.mC},
                               {"average_m", inOutcome.mCrushProfile.Average()}};
    report["outward_displacement_m"] = inOutcome.mOutwardDisplacement;
    if (const std::optional<WallGap>& gap = inOutcome.mWallGap)
        report["wall_gap"] = {
            {"mean_m", gap->mMean}, {"largest_m", gap->mLargest}, {"squares", gap->mSquares}};
    else
        report["wall_gap"] = nullptr;
    report["limited_dents"] = inOutcome.mLimitedDents;
    report["stacked_up_dents"] = inOutcome.mStackedUpDents;
    const TimeHistory& history = inFindings.mHistory;
    report["time_history"] = {{"file", "timeseries.csv"},
                              {"step_s", history.mStep},
                              {"acceleration_filter", history.mAccelerationCfc60.empty()
                                                          ? "none: the engine step samples below 600 Hz (SAE J211 CFC 60)"
                                                          : "CFC 60 (SAE J211/1)"},
                              {"peak_deceleration_m_s2", history.mPeakDeceleration},
                              {"peak_deceleration_g", history.mPeakDeceleration / 9.80665},
                              {"clip_3ms_m_s2", std::isnan(history.mClip3ms) ? nlohmann::json(nullptr)
                                                                              : nlohmann::json(history.mClip3ms)},
                              {"time_to_zero_velocity_s", history.mTimeToZeroVelocity},
                              {"pulse_steps", history.mPulseSteps},
                              {"pulse_note", "the engine stops the car's rigid collision box; the crush is a dent on "
                                             "the body, not compliance in the engine"}};
    nlohmann::json expectations = nlohmann::json::array();
    for (const ExpectationResult& result : inFindings.mExpectations)
    {
        expectations.push_back({{"expectation", result.mExpectation.mText},
                                {"quantity", ToString(result.mExpectation.mQuantity)},
                                {"value", result.mValue},
                                {"value_in_expectation_unit", result.mValue * result.mExpectation.mDisplayScale},
                                {"passed", result.mPassed}});
    }
    report["expectations"] = expectations;
    nlohmann::json sanity = nlohmann::json::array();
    for (const SanityResult& check : inFindings.mSanity)
    {
        sanity.push_back({{"check", check.mName},
                          {"applies", check.mApplies},
                          {"value", check.mValue},
                          {"limit", check.mLimit},
                          {"detail", check.mDetail},
                          {"passed", check.mPassed}});
    }
    report["sanity"] = sanity;
    report["passed"] = inFindings.Passed();
    const std::string text = report.dump(2) + "\n";
    return WriteFileAtomically(inPath, std::as_bytes(std::span(text.data(), text.size())), "crumple-crash report");
}

void PrintSummary(std::FILE* inStream, const CrashScenario& inScenario, const CrashOutcome& inOutcome,
                  const CrashFindings& inFindings)
{
    std::fprintf(inStream, "%s (%s, %.1f km/h)\n", inScenario.mName.c_str(), ToString(inScenario.mEngine),
                 inScenario.mImpact.mSpeed * cKmhPerMs);
    std::fprintf(inStream, "  residual crush: front %.3f m, rear %.3f m, left %.3f m, right %.3f m, roof %.3f m\n",
                 inOutcome.mResidualCrush[static_cast<int>(EZone::Front)],
                 inOutcome.mResidualCrush[static_cast<int>(EZone::Rear)],
                 inOutcome.mResidualCrush[static_cast<int>(EZone::Left)],
                 inOutcome.mResidualCrush[static_cast<int>(EZone::Right)],
                 inOutcome.mResidualCrush[static_cast<int>(EZone::Roof)]);
    std::fprintf(inStream, "  delta-v %.2f km/h, energy absorbed %.1f kJ, %zu collisions, impulse %.0f N s (peak %.0f)\n",
                 inOutcome.DeltaV() * cKmhPerMs, inOutcome.EnergyAbsorbed() / 1000.0, inOutcome.mCollisions.size(),
                 inOutcome.mTotalImpulse, inOutcome.mPeakImpulse);
    std::fprintf(inStream, "  outward displacement %.3f m (largest forward move of a vertex, against the crush)\n",
                 inOutcome.mOutwardDisplacement);
    if (const std::optional<WallGap>& gap = inOutcome.mWallGap)
        std::fprintf(inStream,
                     "  wall gap %.3f m mean, %.3f m largest over %d squares of 10 cm (how far the struck "
                     "front ended behind the wall's final plane)\n",
                     gap->mMean, gap->mLargest, gap->mSquares);
    if (const std::optional<MeshPreparation>& mesh = inOutcome.mMeshPreparation)
        std::fprintf(inStream, "  %s\n", MeshPreparationText(*mesh).c_str());
    for (const std::string& warning : inOutcome.mWarnings)
        std::fprintf(inStream, "  WARNING %s\n", warning.c_str());
    const CrushProfile& profile = inOutcome.mCrushProfile;
    std::fprintf(inStream,
                 "  %s crush profile over %.2f m: C1..C6 %.3f %.3f %.3f %.3f %.3f %.3f m, average %.3f m\n",
                 CarFaceName(profile.mFace), profile.mDamageWidth, profile.mC[0], profile.mC[1],
                 profile.mC[2], profile.mC[3], profile.mC[4], profile.mC[5], profile.Average());
    if (inOutcome.mLimitedDents > 0)
        std::fprintf(inStream, "  %d dent(s) clamped by the material's maximum deformation: the crush is a lower bound\n",
                     inOutcome.mLimitedDents);
    if (inOutcome.mStackedUpDents > 0)
        std::fprintf(inStream,
                     "  %d crush(es) stacked up against the occupant cell (crush_zone_fraction): the front crushed less "
                     "than Campbell's law asks, the cabin not at all\n",
                     inOutcome.mStackedUpDents);
    if (inOutcome.mFoldedTriangles > 0)
        std::fprintf(inStream, "  surface folded: %d of %zu triangles turned over\n", inOutcome.mFoldedTriangles,
                     inOutcome.mRestMesh.mTriangles.size());
    if (inOutcome.mFoldedVertices > 0)
        std::fprintf(inStream, "  %d of %zu vertex normals turned over\n", inOutcome.mFoldedVertices,
                     inOutcome.mRestMesh.mPositions.size());
    if (!std::isnan(inOutcome.mTargetResidualCrush))
        std::fprintf(inStream, "  target vehicle residual crush %.3f m\n", inOutcome.mTargetResidualCrush);
    if (inOutcome.mBarrierFragments > 0)
        std::fprintf(inStream, "  barrier: %d pieces, %d links broken, took %.0f N s, %s\n", inOutcome.mBarrierFragments,
                     inOutcome.mBarrierBrokenLinks, inOutcome.mBarrierMomentum.norm(),
                     std::isnan(inOutcome.mBarrierBreachTime)
                         ? "held"
                         : ("breached at " + std::to_string(inOutcome.mBarrierBreachTime) + " s").c_str());
    const TimeHistory& history = inFindings.mHistory;
    std::fprintf(inStream, "  peak deceleration %.1f g over %d engine steps (%s), velocity zero at %s (timeseries.csv)\n",
                 history.mPeakDeceleration / 9.80665, history.mPulseSteps,
                 history.mAccelerationCfc60.empty() ? "unfiltered: the engine step is too coarse for CFC 60" : "CFC 60",
                 history.mTimeToZeroVelocity < 0.0 ? "never" : (std::to_string(history.mTimeToZeroVelocity) + " s").c_str());
    for (const ExpectationResult& result : inFindings.mExpectations)
        std::fprintf(inStream, "  %s %s: measured %.6g\n", result.mPassed ? "PASS" : "FAIL",
                     result.mExpectation.mText.c_str(), result.mValue * result.mExpectation.mDisplayScale);
    for (const SanityResult& check : inFindings.mSanity)
        std::fprintf(inStream, "  %s sanity %s: %s\n", !check.mApplies ? "n/a " : check.mPassed ? "PASS" : "FAIL",
                     check.mName.c_str(), check.mDetail.c_str());
}

Status WriteReportHtml(const std::filesystem::path& inPath, const CrashScenario& inScenario,
                       const CrashOutcome& inOutcome, const CrashFindings& inFindings,
                       const std::filesystem::path& inPictureFolder)
{
    const bool passed = inFindings.ExpectationsHold(), sane = inFindings.Sane();
    std::string html = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" +
                       Escape(inScenario.mName) +
                       "</title><style>body{font-family:sans-serif;margin:2em;background:#fff;color:#222}"
                       "table{border-collapse:collapse}td,th{border:1px solid #bbb;padding:4px 10px;text-align:left}"
                       ".pass{color:#070}.fail{color:#b00;font-weight:bold}img{max-width:480px;margin:4px;"
                       "border:1px solid #ccc}</style></head><body>\n";
    html += "<h1>" + Escape(inScenario.mName) + "</h1>\n<p>Engine " + ToString(inScenario.mEngine) + ", " +
            Number(inScenario.mImpact.mSpeed * cKmhPerMs, 1) + " km/h, mass " + Number(inOutcome.mMass, 0) +
            " kg. Verdict: <span class=\"" +
            (!sane ? "fail\">a sanity check failed: the run is not physically sound"
             : passed ? "pass\">all expectations hold"
                      : "fail\">an expectation failed") +
            "</span></p>\n<table><tr><th>quantity</th><th>value</th></tr>\n";
    const auto row = [&html](const std::string& inName, const std::string& inValue)
    { html += "<tr><td>" + inName + "</td><td>" + inValue + "</td></tr>\n"; };
    for (EZone zone : {EZone::Front, EZone::Rear, EZone::Left, EZone::Right, EZone::Roof})
        row(std::string("residual crush, ") + ToString(zone), Number(inOutcome.mResidualCrush[static_cast<int>(zone)], 3) + " m");
    row("delta-v", Number(inOutcome.DeltaV() * cKmhPerMs, 2) + " km/h");
    row("energy absorbed", Number(inOutcome.EnergyAbsorbed() / 1000.0, 2) + " kJ");
    row("total impulse", Number(inOutcome.mTotalImpulse, 0) + " N s (peak " + Number(inOutcome.mPeakImpulse, 0) + ")");
    row("collisions", std::to_string(inOutcome.mCollisions.size()));
    row("folded triangles", std::to_string(inOutcome.mFoldedTriangles) + " of " +
                                  std::to_string(inOutcome.mRestMesh.mTriangles.size()));
    row("folded vertices (normal turned over)", std::to_string(inOutcome.mFoldedVertices) + " of " +
                                                     std::to_string(inOutcome.mRestMesh.mPositions.size()));
    {
        const CrushProfile& profile = inOutcome.mCrushProfile;
        std::string stations;
        for (double c : profile.mC)
            stations += Number(c, 3) + " ";
        row(std::string(CarFaceName(profile.mFace)) + " crush profile C1..C6 (CRASH3)",
            stations + "m over " + Number(profile.mDamageWidth, 2) + " m, average " +
                Number(profile.Average(), 3) + " m");
    }
    row("dents clamped by a material bound", std::to_string(inOutcome.mLimitedDents) +
                                                 (inOutcome.mLimitedDents > 0 ? " (the crush is a lower bound)" : ""));
    row("crushes stacked up against the occupant cell", std::to_string(inOutcome.mStackedUpDents));
    row("outward displacement", Number(inOutcome.mOutwardDisplacement, 3) + " m");
    if (const std::optional<WallGap>& gap = inOutcome.mWallGap)
        row("wall gap (struck front behind the wall's final plane)",
            Number(gap->mMean, 3) + " m mean, " + Number(gap->mLargest, 3) + " m largest over " +
                std::to_string(gap->mSquares) + " squares of 10 cm");
    const TimeHistory& history = inFindings.mHistory;
    row("peak deceleration", Number(history.mPeakDeceleration / 9.80665, 1) + " g over " +
                                 std::to_string(history.mPulseSteps) + " engine steps (" +
                                 (history.mAccelerationCfc60.empty() ? "unfiltered: step too coarse for CFC 60" : "CFC 60") +
                                 "; the engine's rigid-box pulse, timeseries.csv)");
    if (const std::optional<MeshPreparation>& mesh = inOutcome.mMeshPreparation)
        row("mesh preparation", Escape(MeshPreparationText(*mesh)));
    for (const std::string& warning : inOutcome.mWarnings)
        row("<span class=\"fail\">warning</span>", Escape(warning));
    if (!std::isnan(inOutcome.mTargetResidualCrush))
        row("target vehicle residual crush", Number(inOutcome.mTargetResidualCrush, 3) + " m");
    html += "</table>\n<h2>Expectations</h2>\n<table><tr><th>expectation</th><th>measured</th><th>verdict</th></tr>\n";
    for (const ExpectationResult& result : inFindings.mExpectations)
        html += "<tr><td>" + Escape(result.mExpectation.mText) + "</td><td>" + Number(result.mValue * result.mExpectation.mDisplayScale, 4) +
                "</td><td class=\"" + (result.mPassed ? "pass\">PASS" : "fail\">FAIL") + "</td></tr>\n";
    html += "</table>\n<h2>Sanity checks</h2>\n<table><tr><th>check</th><th>what was measured</th><th>verdict</th></tr>\n";
    for (const SanityResult& check : inFindings.mSanity)
        html += "<tr><td>" + Escape(check.mName) + "</td><td>" + Escape(check.mDetail) + "</td><td class=\"" +
                (!check.mApplies ? "pass\">n/a" : check.mPassed ? "pass\">PASS" : "fail\">FAIL") + "</td></tr>\n";
    // Each PNG that was written, embedded with its name as caption.
    auto figures = [&](std::initializer_list<const char*> inNames, const std::string& inNote) {
        for (const char* name : inNames)
        {
            Result<std::vector<std::byte>> png = ReadFileBytes(inPictureFolder / (std::string(name) + ".png"));
            if (png.IsValid())
                html += "<figure style=\"display:inline-block\"><img alt=\"" + std::string(name) +
                        "\" src=\"data:image/png;base64," + Base64(png.Get()) + "\"><figcaption>" + name + inNote +
                        "</figcaption></figure>";
        }
    };
    html += "</table>\n<h2>Time histories</h2>\n<div>";
    figures({"deceleration", "velocity", "energy"}, " (timeseries.csv)");
    html += "</div>\n<h2>Pictures</h2>\n<div>";
    figures({"before_front", "after_front", "before_side", "after_side", "before_top", "after_top", "heat_map"}, "");
    html += "</div>\n</body></html>\n";
    return WriteFileAtomically(inPath, std::as_bytes(std::span(html.data(), html.size())), "crumple-crash report");
}

Status WritePictures(const std::filesystem::path& inFolder, const CrashOutcome& inOutcome, double inColourMax)
{
    const std::vector<double> depths = samples::DentDepths(inOutcome.mPositions, inOutcome.mRestMesh.mPositions);
    const double deepest = depths.empty() ? 0.0 : *std::max_element(depths.begin(), depths.end());
    const double scale = inColourMax > 0.0 ? inColourMax : samples::DentColorScale(deepest);
    Result<std::unique_ptr<samples::ScenePainter>> created = samples::ScenePainter::Create(960, 540, scale);
    if (created.HasError())
        return created.GetError();
    samples::ScenePainter& painter = *created.Get();
    const ffd::AlignedBox bounds = ffd::BoundingBox(inOutcome.mRestMesh.mPositions);
    const Vec3 margin = Vec3::Constant(0.05);
    const double aspect = painter.GetWidth() / static_cast<double>(painter.GetHeight());
    const std::vector<double>& dents = depths;
    const struct
    {
        render::EView mView;
        const char* mName;
    } views[] = {{render::EView::Front, "front"}, {render::EView::Side, "side"}, {render::EView::Top, "top"}};
    for (const bool after : {false, true})
        for (const auto& view : views)
        {
            // Body frame, the car centred: before uncoloured, after coloured by residual displacement.
            painter.Clear();
            painter.Add(after ? inOutcome.mPositions : inOutcome.mRestMesh.mPositions,
                        after ? inOutcome.mNormals : inOutcome.mRestNormals, inOutcome.mRestMesh.mTriangles,
                        after ? std::span<const double>(dents) : std::span<const double>(), Transform{});
            const render::Camera camera = render::Camera::LookAtBounds(bounds.mMin - margin, bounds.mMax + margin,
                                                                       view.mView, Vec3::UnitZ(), Vec3::UnitX(),
                                                                       30.0, aspect);
            const std::string name = std::string(after ? "after_" : "before_") + view.mName + ".png";
            if (Status status = painter.Paint(camera, inFolder / name); status.HasError())
                return status;
        }
    painter.Clear();
    painter.Add(inOutcome.mPositions, inOutcome.mNormals, inOutcome.mRestMesh.mTriangles, dents, Transform{});
    const render::Camera iso = render::Camera::LookAtBounds(bounds.mMin - margin, bounds.mMax + margin,
                                                            render::EView::Iso, Vec3::UnitZ(), Vec3::UnitX(), 30.0,
                                                            aspect);
    return painter.Paint(iso, inFolder / "heat_map.png");
}

} // namespace crumple::crash
