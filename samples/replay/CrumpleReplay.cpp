// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// crumple-replay: replays a recorded damage file headless, with no physics engine linked, and writes the
// deformed meshes. Exit 0 on success, 2 on a bad file or arguments (nothing is written then).
#include "ObjWriter.h"
#include "WorldFixture.h"

#include <crumple/base/FileBytes.h>
#include <crumple/base/Version.h>
#include <crumple/plugin/ReplayDamage.h>

#include <cstdio>
#include <string>

using namespace crumple;
using namespace crumple::plugin;

int main(int argc, char** argv)
{
    std::filesystem::path input, out;
    for (int i = 1; i < argc; ++i)
    {
        const std::string arg = argv[i];
        if (arg == "--help" || arg == "-h")
        {
            std::printf("usage: crumple-replay FILE --out DIR\n"
                        "  Replays a Crumple recording (written by DamageRecorder) without a physics engine and\n"
                        "  writes each object's deformed mesh as DIR/object<ID>.obj, with one line per object.\n");
            return 0;
        }
        if (arg == "--version")
        {
            std::printf("crumple-replay %s\n", VersionString());
            return 0;
        }
        if (arg == "--out" && i + 1 < argc)
            out = argv[++i];
        else if (!arg.starts_with("-") && input.empty())
            input = arg;
        else
        {
            std::fprintf(stderr, "crumple-replay: unexpected argument '%s' (see --help)\n", arg.c_str());
            return 2;
        }
    }
    if (input.empty() || out.empty())
    {
        std::fprintf(stderr, "crumple-replay: a FILE and --out DIR are required (see --help)\n");
        return 2;
    }

    // Read and check everything before writing anything.
    Result<std::vector<std::byte>> bytes = ReadFileBytes(input);
    if (!bytes)
    {
        std::fprintf(stderr, "crumple-replay: %s\n", bytes.GetError().mMessage.c_str());
        return 2;
    }
    Result<Replay> replay = DecodeReplay(bytes.Get());
    if (!replay)
    {
        std::fprintf(stderr, "crumple-replay: %s: %s\n", input.string().c_str(), replay.GetError().mMessage.c_str());
        return 2;
    }
    std::printf("crumple-replay: %zu objects, %zu collisions\n", replay.Get().mObjects.size(), replay.Get().mCollisions.size());
    Result<std::vector<ReplayedObject>> objects = ReplayDamage(replay.Get());
    if (!objects)
    {
        std::fprintf(stderr, "crumple-replay: %s\n", objects.GetError().mMessage.c_str());
        return 2;
    }

    std::error_code error;
    std::filesystem::create_directories(out, error);
    if (error)
    {
        std::fprintf(stderr, "crumple-replay: cannot create %s: %s\n", out.string().c_str(), error.message().c_str());
        return 2;
    }
    for (const ReplayedObject& object : objects.Get())
    {
        const ffd::FfdDeformer& deformer = object.mDeformable.GetDeformer();
        const std::filesystem::path path = out / ("object" + std::to_string(object.mObject.mValue) + ".obj");
        if (Status written = common::WriteObj(path, deformer.GetPositions(), deformer.GetNormals(), deformer.GetRestMesh().mTriangles); !written)
        {
            std::fprintf(stderr, "crumple-replay: %s\n", written.GetError().mMessage.c_str());
            return 2;
        }
        double deepest = 0.0;
        for (std::size_t v = 0; v < deformer.GetPositions().size(); ++v)
            deepest = std::max(deepest, (deformer.GetPositions()[v] - deformer.GetRestMesh().mPositions[v]).norm());
        std::printf("object %u (body %u): %zu vertices, deepest dent %.4f m, mesh hash %016llx -> %s\n",
                    object.mObject.mValue, object.mBody.mValue, deformer.GetPositions().size(), deepest,
                    static_cast<unsigned long long>(common::HashPositions(deformer.GetPositions())), path.string().c_str());
    }
    return 0;
}
