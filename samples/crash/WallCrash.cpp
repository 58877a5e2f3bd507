// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// A box-shaped car driven into a rigid wall through the core API, with a scripted stand-in for the
// physics engine (tests/common/WallCrashScene). Prints one line per collision and writes the rest and
// deformed meshes as OBJ plus a summary. Exit 0 on success, 2 on bad input (nothing written).
#include "ObjWriter.h"
#include "WallCrashScene.h"
#include "MeshHash.h"

#include <crumple/base/Version.h>
#include <crumple/plugin/DamageRecorder.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

using namespace crumple;
using namespace crumple::plugin;

namespace
{

void PrintHelp()
{
    std::printf("usage: crumple-wall-crash [--speed M_PER_S] [--angle DEGREES] [--mass KG] [--triangles N] --out DIR\n"
                "  Drives a 4.2 m x 1.8 m x 1.4 m box car into a rigid wall and dents it.\n"
                "  --speed      impact speed in m/s (default 15, > 0, <= 100)\n"
                "  --angle      heading relative to the wall normal in degrees (default 0, |angle| < 80)\n"
                "  --mass       car mass in kg (default 1200, > 0)\n"
                "  --triangles  approximate render mesh size (default 20000, 12..2000000)\n"
                "  --out        output folder: rest.obj, deformed.obj, summary.txt\n"
                "  --replay     also record the run to this file, for crumple-replay\n");
}

bool ParseNumber(const char* inText, double& outValue)
{
    char* end = nullptr;
    outValue = std::strtod(inText, &end);
    return end != inText && *end == '\0' && std::isfinite(outValue);
}

// Prints one line per dispatched collision.
class CollisionPrinter : public DamageListener
{
public:
    void OnCollision(const Collision& inCollision, std::span<const ObjectDent> inDents) override
    {
        std::uint32_t moved = 0;
        double error = 0.0;
        for (const ObjectDent& dent : inDents)
        {
            moved += dent.mReport.mVerticesMoved;
            error = std::max(error, dent.mReport.mMaxPointError);
        }
        double approach = 0.0;
        for (const CollisionContact& c : inCollision.mContacts)
            approach = std::max(approach, c.mApproachSpeed);
        char line[256];
        std::snprintf(line, sizeof(line),
                      "collision %zu: t %.3f-%.3f s, bodies %u-%u, %zu contacts, impulse %.1f N s, approach %.2f m/s, "
                      "%u vertices moved, contact error %.2e m\n",
                      mLines.size(), inCollision.mStartTime, inCollision.mEndTime, inCollision.mBodyA.mValue,
                      inCollision.mBodyB.mValue, inCollision.mContacts.size(), inCollision.TotalImpulse(), approach,
                      moved, error);
        std::fputs(line, stdout);
        mLines.emplace_back(line);
    }
    std::vector<std::string> mLines;
};

} // namespace

int main(int argc, char** argv)
{
    common::WallCrashSettings settings;
    settings.mDuration = 0.5;
    std::filesystem::path out, replay;
    for (int i = 1; i < argc; ++i)
    {
        const std::string arg = argv[i];
        if (arg == "--help" || arg == "-h")
        {
            PrintHelp();
            return 0;
        }
        if (arg == "--version")
        {
            std::printf("crumple-wall-crash %s\n", VersionString());
            return 0;
        }
        if (i + 1 >= argc)
        {
            std::fprintf(stderr, "crumple-wall-crash: %s needs a value (see --help)\n", arg.c_str());
            return 2;
        }
        const char* value = argv[++i];
        double number = 0.0;
        if (arg == "--out")
            out = value;
        else if (arg == "--replay")
            replay = value;
        else if (!ParseNumber(value, number))
        {
            std::fprintf(stderr, "crumple-wall-crash: %s %s: not a finite number\n", arg.c_str(), value);
            return 2;
        }
        else if (arg == "--speed" && number > 0.0 && number <= 100.0)
            settings.mSpeed = number;
        else if (arg == "--angle" && std::abs(number) < 80.0)
            settings.mYawDegrees = number;
        else if (arg == "--mass" && number > 0.0)
            settings.mMass = number;
        else if (arg == "--triangles" && number >= 12.0 && number <= 2.0e6)
            settings.mTriangles = static_cast<int>(number);
        else
        {
            std::fprintf(stderr, "crumple-wall-crash: %s %s: unknown option or out of range (see --help)\n", arg.c_str(), value);
            return 2;
        }
    }
    if (out.empty())
    {
        std::fprintf(stderr, "crumple-wall-crash: --out DIR is required (see --help)\n");
        return 2;
    }

    Result<common::WallCrashScene> created = common::WallCrashScene::Create(settings);
    if (!created)
    {
        std::fprintf(stderr, "crumple-wall-crash: %s\n", created.GetError().mMessage.c_str());
        return 2;
    }
    common::WallCrashScene& scene = created.Get();
    CollisionPrinter printer;
    scene.GetWorld().AddListener(&printer);
    std::printf("crumple-wall-crash: %.0f kg box car at %.1f m/s, heading %.0f degrees, into a rigid wall\n",
                settings.mMass, settings.mSpeed, settings.mYawDegrees);
    std::unique_ptr<DamageRecorder> recorder;
    if (!replay.empty())
    {
        Result<std::unique_ptr<DamageRecorder>> created_recorder = DamageRecorder::Create(replay, scene.GetWorld());
        if (!created_recorder)
        {
            std::fprintf(stderr, "crumple-wall-crash: %s\n", created_recorder.GetError().mMessage.c_str());
            return 2;
        }
        recorder = std::move(created_recorder).Get();
    }
    scene.Run();
    if (recorder != nullptr)
    {
        if (Status closed = recorder->Close(); !closed)
        {
            std::fprintf(stderr, "crumple-wall-crash: %s\n", closed.GetError().mMessage.c_str());
            return 2;
        }
        std::printf("recorded %llu collisions to %s\n", static_cast<unsigned long long>(recorder->GetCollisionCount()),
                    replay.string().c_str());
    }

    // Results: deepest dent and the meshes.
    const ffd::FfdDeformer& car = scene.GetWorld().GetObject(scene.GetCarObject())->GetDeformer();
    const ffd::TriangleMesh& rest = car.GetRestMesh();
    double deepest = 0.0;
    for (std::size_t v = 0; v < rest.mPositions.size(); ++v)
        deepest = std::max(deepest, (car.GetPositions()[v] - rest.mPositions[v]).norm());
    std::error_code error;
    std::filesystem::create_directories(out, error);
    if (error)
    {
        std::fprintf(stderr, "crumple-wall-crash: cannot create %s: %s\n", out.string().c_str(), error.message().c_str());
        return 2;
    }
    std::vector<Vec3> rest_normals;
    for (Status status : {common::WriteObj(out / "rest.obj", rest.mPositions, {}, rest.mTriangles),
                          common::WriteObj(out / "deformed.obj", car.GetPositions(), car.GetNormals(), rest.mTriangles)})
        if (!status)
        {
            std::fprintf(stderr, "crumple-wall-crash: %s\n", status.GetError().mMessage.c_str());
            return 2;
        }
    std::ofstream summary(out / "summary.txt");
    for (const std::string& line : printer.mLines)
        summary << line;
    char text[256];
    std::snprintf(text, sizeof(text), "deepest dent %.3f m over %zu vertices, %zu triangles; final speed %.2f m/s\n",
                  deepest, rest.mPositions.size(), rest.mTriangles.size(), scene.GetCarState().mLinearVelocity.norm());
    summary << text;
    std::fputs(text, stdout);
    std::printf("wrote %s (mesh hash %016llx)\n", (out / "deformed.obj").string().c_str(),
                static_cast<unsigned long long>(common::HashPositions(car.GetPositions())));
    return 0;
}
