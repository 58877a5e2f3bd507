// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "RunProcess.h"
#include "TemporaryDirectory.h"

#include <crumple/base/FileBytes.h>
#include <crumple/fem/ExactNumber.h>
#include <crumple/fem/TetVolume.h>
#include <crumple/fem_import/TetgenOutput.h>
#include <crumple/fem_import/Tetrahedralize.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

namespace crumple::fem
{

namespace
{

// A double as text that tetgen's switch parser reads: fixed notation (it stops at an exponent), shortest
// exact.
std::string FixedNumber(double inValue)
{
    char buffer[512];
    const std::to_chars_result result =
        std::to_chars(buffer, buffer + sizeof(buffer), inValue, std::chars_format::fixed);
    return std::string(buffer, result.ptr);
}

// The last few lines of a program's output, for an error message.
std::string OutputTail(const std::string& inOutput)
{
    constexpr std::size_t cMaxChars = 2000;
    std::string tail =
        inOutput.size() > cMaxChars ? "..." + inOutput.substr(inOutput.size() - cMaxChars) : inOutput;
    while (!tail.empty() && (tail.back() == '\n' || tail.back() == ' '))
        tail.pop_back();
    return tail.empty() ? "(no output)" : tail;
}

// Checks the ranges documented in TetgenSettings.
Status ValidateSettings(const TetgenSettings& inSettings)
{
    if (inSettings.mExecutable.empty())
        return MakeError(EError::InvalidArgument, "TetgenSettings.mExecutable is empty");
    const double ratio = inSettings.mMaxRadiusEdgeRatio;
    if (!std::isfinite(ratio) || (ratio != 0.0 && ratio < TetgenSettings::cMinRadiusEdgeRatio))
        return MakeError(EError::InvalidArgument,
                         "TetgenSettings.mMaxRadiusEdgeRatio = " + ExactNumber(ratio) +
                             " must be 0 (no refinement) or >= 1.1");
    if (!std::isfinite(inSettings.mMaxVolume) || inSettings.mMaxVolume < 0.0)
        return MakeError(EError::InvalidArgument,
                         "TetgenSettings.mMaxVolume = " + ExactNumber(inSettings.mMaxVolume) +
                             " m^3 must be >= 0 (0 = no limit)");
    return Status::Ok();
}

// The surface as an OFF file (0-based faces), coordinates exact.
Status WriteOff(const std::filesystem::path& inPath, const SurfaceMesh& inSurface)
{
    std::string text = "OFF\n" + std::to_string(inSurface.mPositions.size()) + " " +
                       std::to_string(inSurface.mTriangles.size()) + " 0\n";
    for (const Vec3& p : inSurface.mPositions)
        text += ExactNumber(p.x()) + " " + ExactNumber(p.y()) + " " + ExactNumber(p.z()) + "\n";
    for (const TriangleIndices& t : inSurface.mTriangles)
        text += "3 " + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) + "\n";
    std::ofstream file(inPath, std::ios::binary | std::ios::trunc);
    file << text;
    file.close();
    if (!file)
        return MakeError(EError::IoError, "cannot write " + inPath.string());
    return Status::Ok();
}

// "exit status 1" or "killed by signal 6 (Aborted)".
std::string DescribeEnd(const ProcessOutcome& inOutcome)
{
    if (inOutcome.mSignal != 0)
        return "killed by signal " + std::to_string(inOutcome.mSignal) + " (" + strsignal(inOutcome.mSignal) +
               ")";
    return "exit status " + std::to_string(inOutcome.mExitCode);
}

// After a failure: TetGen 1.5 aborts without a reason when its output is a file (the reason stays in its
// stdio buffer), so run its self-intersection check (-d, not quiet: -Q silences it) and describe the first
// pair found. Empty when tetgen finds none or cannot run.
std::string DiagnoseSelfIntersection(const std::filesystem::path& inExecutable,
                                     const std::filesystem::path& inInput, const SurfaceMesh& inSurface)
{
    const std::filesystem::path log = inInput.parent_path() / "diagnose.log";
    Result<ProcessOutcome> run = RunProcess(inExecutable, {"-pzd", inInput.string()}, log);
    if (run.HasError())
        return {};
    // "!! Found 668 pairs of faces are intersecting." and "  Facet #30 intersects facet #330 at triangles:"
    // then "    (  15,   56,   54) and ( 176,  211,  210)" with 0-based surface vertex indices (-z).
    const std::string& output = run.Get().mOutput;
    const std::size_t found = output.find("!! Found ");
    const std::size_t facet = output.find(" intersects facet #");
    if (found == std::string::npos || facet == std::string::npos)
        return {};
    long long pairs = 0;
    std::from_chars(output.data() + found + 9, output.data() + output.size(), pairs);
    std::string message = "the surface intersects itself (tetgen -d found " + std::to_string(pairs) +
                          " pairs of intersecting triangles";
    const std::size_t line = output.find('(', facet);
    long long corners[6] = {};
    const char* cursor = line == std::string::npos ? nullptr : output.data() + line;
    const char* end = output.data() + output.size();
    int read = 0;
    while (cursor != nullptr && read < 6 && cursor < end)
    {
        while (cursor < end && (*cursor == ' ' || *cursor == '(' || *cursor == ')' || *cursor == ',' ||
                                *cursor == 'a' || *cursor == 'n' || *cursor == 'd'))
            ++cursor;
        const std::from_chars_result number = std::from_chars(cursor, end, corners[read]);
        if (number.ec != std::errc())
            break;
        cursor = number.ptr;
        ++read;
    }
    const long long count = static_cast<long long>(inSurface.mPositions.size());
    if (read == 6 &&
        std::all_of(corners, corners + 6, [&](long long inV) { return inV >= 0 && inV < count; }))
    {
        const Vec3& p = inSurface.mPositions[static_cast<std::size_t>(corners[0])];
        message += ", e.g. the triangle of vertices " + std::to_string(corners[0]) + ", " +
                   std::to_string(corners[1]) + ", " + std::to_string(corners[2]) + " near (" +
                   ExactNumber(p.x()) + ", " + ExactNumber(p.y()) + ", " + ExactNumber(p.z()) +
                   ") m and that of vertices " + std::to_string(corners[3]) + ", " +
                   std::to_string(corners[4]) + ", " + std::to_string(corners[5]);
    }
    return message + ")";
}

} // namespace

Result<TetMesh> Tetrahedralize(const SurfaceMesh& inSurface, const TetgenSettings& inSettings)
{
    // Everything that can be checked without tetgen, first.
    if (Status closed = ValidateClosedSurface(inSurface); !closed)
        return MakeError(closed.GetError().mCode, "Tetrahedralize: " + closed.GetError().mMessage);
    if (Status valid = ValidateSettings(inSettings); !valid)
        return valid.GetError();
    // intent: a volume bound that asks for more elements than a TetMesh holds is refused before tetgen runs
    // (1e-9 m^3 in a 1 m^3 cube ran past a minute and 4 GB); the enclosed volume by the divergence theorem
    if (inSettings.mMaxVolume > 0.0)
    {
        double volume = 0.0;
        for (const TriangleIndices& t : inSurface.mTriangles)
            volume += inSurface.mPositions[t[0]].dot(inSurface.mPositions[t[1]].cross(inSurface.mPositions[t[2]])) / 6.0;
        if (std::abs(volume) / inSettings.mMaxVolume > static_cast<double>(TetMesh::cMaxCount))
            return MakeError(EError::InvalidArgument, "TetgenSettings.mMaxVolume = " + ExactNumber(inSettings.mMaxVolume) +
                                                          " m^3 asks for more than TetMesh::cMaxCount elements in a volume of " +
                                                          ExactNumber(std::abs(volume)) + " m^3");
    }
    Result<std::filesystem::path> executable = FindExecutable(inSettings.mExecutable);
    if (executable.HasError())
        return MakeError(EError::IoError,
                         "tetgen not found (looked for '" + inSettings.mExecutable +
                             (inSettings.mExecutable.find('/') == std::string::npos ? "' on PATH" : "'") +
                             "): install Debian's tetgen package (apt-get install tetgen) or set "
                             "TetgenSettings::mExecutable");

    // A private folder for tetgen's files, removed on every return below.
    Result<TemporaryDirectory> folder =
        TemporaryDirectory::Create(inSettings.mTemporaryDirectory, "crumple-tetgen-");
    if (folder.HasError())
        return MakeError(EError::IoError, "Tetrahedralize: " + folder.GetError().mMessage);
    const std::filesystem::path& work = folder.Get().GetPath();
    const std::filesystem::path input = work / "surface.off";
    if (Status written = WriteOff(input, inSurface); !written)
        return MakeError(EError::IoError, "Tetrahedralize: " + written.GetError().mMessage);

    // tetgen -pzQ[Y] [-q<ratio>] [-a<volume>] surface.off: a PLC, 0-based output, quiet, [surface kept].
    std::vector<std::string> arguments = {inSettings.mKeepSurface ? "-pzQY" : "-pzQ"};
    if (inSettings.mMaxRadiusEdgeRatio > 0.0)
        arguments.push_back("-q" + FixedNumber(inSettings.mMaxRadiusEdgeRatio));
    if (inSettings.mMaxVolume > 0.0)
        arguments.push_back("-a" + FixedNumber(inSettings.mMaxVolume));
    arguments.push_back(input.string());
    Result<ProcessOutcome> run = RunProcess(executable.Get(), arguments, work / "tetgen.log");
    if (run.HasError())
        return MakeError(EError::IoError, "Tetrahedralize: " + run.GetError().mMessage);
    const ProcessOutcome& outcome = run.Get();
    std::string command = executable.Get().string();
    for (const std::string& argument : arguments)
        command += " " + argument;
    if (outcome.mExitCode != 0)
    {
        const std::string intersection = DiagnoseSelfIntersection(executable.Get(), input, inSurface);
        return MakeError(EError::DegenerateGeometry,
                         "tetgen failed (" + DescribeEnd(outcome) + ") on a surface of " +
                             std::to_string(inSurface.mPositions.size()) + " vertices and " +
                             std::to_string(inSurface.mTriangles.size()) + " triangles" +
                             (intersection.empty() ? "" : ": " + intersection) + "; command: " + command +
                             "; its output: " + OutputTail(outcome.mOutput));
    }

    // Its nodes and elements.
    Result<std::vector<std::byte>> node_bytes = ReadFileBytes(work / "surface.1.node");
    if (node_bytes.HasError())
        return MakeError(EError::CorruptData, "tetgen wrote no surface.1.node; its output: " + OutputTail(outcome.mOutput));
    Result<std::vector<std::byte>> ele_bytes = ReadFileBytes(work / "surface.1.ele");
    if (ele_bytes.HasError())
        return MakeError(EError::CorruptData, "tetgen wrote no surface.1.ele; its output: " + OutputTail(outcome.mOutput));
    Result<TetgenOutput> output = ParseTetgenOutput(
        std::string_view(reinterpret_cast<const char*>(node_bytes.Get().data()), node_bytes.Get().size()),
        std::string_view(reinterpret_cast<const char*>(ele_bytes.Get().data()), ele_bytes.Get().size()));
    if (output.HasError())
        return output.GetError();
    std::vector<Vec3>& nodes = output.Get().mNodes;
    std::vector<TetIndices>& tets = output.Get().mTets;

    // The surface vertices come first, in order: check, then restore them bit for bit.
    const int surface_count = static_cast<int>(inSurface.mPositions.size());
    if (static_cast<int>(nodes.size()) < surface_count)
        return MakeError(EError::CorruptData, "tetgen output has " + std::to_string(nodes.size()) +
                                                  " nodes, fewer than the " + std::to_string(surface_count) +
                                                  " surface vertices");
    double scale = 0.0;
    for (const Vec3& p : inSurface.mPositions)
        scale = std::max(scale, p.cwiseAbs().maxCoeff());
    const double tolerance = 1.0e-13 * std::max(scale, 1.0e-300);
    for (int vertex = 0; vertex < surface_count; ++vertex)
    {
        if ((nodes[vertex] - inSurface.mPositions[vertex]).cwiseAbs().maxCoeff() > tolerance)
            return MakeError(EError::CorruptData, "tetgen output node " + std::to_string(vertex) +
                                                      " is not surface vertex " + std::to_string(vertex));
        nodes[vertex] = inSurface.mPositions[vertex];
    }

    // Every surface vertex must be used; tetgen drops near-duplicates within its tolerance.
    std::vector<char> used(nodes.size(), 0);
    for (const TetIndices& tet : tets)
        for (int node : tet)
            used[node] = 1;
    for (int vertex = 0; vertex < surface_count; ++vertex)
        if (!used[vertex])
        {
            const Vec3& p = inSurface.mPositions[vertex];
            return MakeError(EError::DegenerateGeometry,
                             "tetgen dropped surface vertex " + std::to_string(vertex) + " at (" +
                                 ExactNumber(p.x()) + ", " + ExactNumber(p.y()) + ", " + ExactNumber(p.z()) +
                                 ") m: it nearly coincides with another vertex, or lies inside a face");
        }

    // Positive orientation (tetgen 1.5 already writes it; swap two corners otherwise).
    for (TetIndices& tet : tets)
        if (TetVolume(nodes[tet[0]], nodes[tet[1]], nodes[tet[2]], nodes[tet[3]]) < 0.0)
            std::swap(tet[2], tet[3]);
    Result<TetMesh> mesh = TetMesh::Create(std::move(nodes), std::move(tets));
    if (mesh.HasError())
        return MakeError(mesh.GetError().mCode,
                         "Tetrahedralize: tetgen's mesh is refused: " + mesh.GetError().mMessage);
    return mesh;
}

} // namespace crumple::fem
