// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// crumple-replay: replays a recorded damage file headless, with no physics engine linked, and writes the
// deformed meshes. Exit 0 on success, 2 on a bad file or arguments (nothing is written then).
#include "ObjWriter.h"
#include "MeshHash.h"
#include "ThreadCpuTime.h"

#include <crumple/base/FileBytes.h>
#include <crumple/base/Version.h>
#include <crumple/ffd/BoundingBox.h>
#include <crumple/plugin/ReplayDamage.h>
#if defined(CRUMPLE_REPLAY_PROPS)
#include "PropsReplay.h"
#include "TetSurface.h"
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <future>
#include <map>
#include <string>
#include <system_error>

#if defined(CRUMPLE_REPLAY_PICTURES)
#include "ScenePainter.h"
#endif

using namespace crumple;
using namespace crumple::plugin;

int main(int argc, char** argv)
{
    std::filesystem::path input, out;
    bool pictures = false;
    bool meshes = true;
    double colour_max = 0.0; // 0: per object, its deepest dent rounded up (samples::DentColorScale)
    // intent: threads in all: above 1 the props replay beside the objects, their element passes on the rest
    // (unused without props)
    [[maybe_unused]] int threads = 1;
    for (int i = 1; i < argc; ++i)
    {
        const std::string arg = argv[i];
        if (arg == "--help" || arg == "-h")
        {
            std::printf(
                "usage: crumple-replay FILE --out DIR [--pictures [--colour-max M]] [--no-meshes] [--threads "
                "N]\n"
                "  Replays a Crumple recording (written by DamageRecorder) without a physics engine and\n"
                "  writes each object's deformed mesh as DIR/object<ID>.obj, with one line per object\n"
                "  (its deepest dent and a hash of its positions) and the replay's time.\n"
                "  --no-meshes  writes no OBJ (the hash line still checks the result)\n"
                "  --pictures  also DIR/object<ID>_before.png, _after.png (coloured by dent depth) and\n"
                "              DIR/frames/object<ID>_NNNN.png after each collision that dents it\n"
                "  --colour-max M  the dent colour scale's top (m; default: each object's deepest dent at\n"
                "              the end, rounded up to 1, 2, 2.5 or 5 x 10^k, as crumple-crash does)\n"
                "  --threads N  threads in all (1-256, default 1): above 1 the props replay on a thread of\n"
                "              their own beside the objects, their FEM element passes on N - 1 threads: the\n"
                "              same results bit for bit, sooner on a machine with the cores\n");
            return 0;
        }
        if (arg == "--version")
        {
            std::printf("crumple-replay %s\n", VersionString());
            return 0;
        }
        if (arg == "--out" && i + 1 < argc)
            out = argv[++i];
        else if (arg == "--pictures")
            pictures = true;
        else if (arg == "--no-meshes")
            meshes = false;
        else if (arg == "--threads" && i + 1 < argc)
        {
            char* end = nullptr;
            const long value = std::strtol(argv[++i], &end, 10);
            if (end == argv[i] || *end != '\0' || value < 1 || value > 256)
            {
                std::fprintf(stderr,
                             "crumple-replay: --threads needs a whole number from 1 to 256, got '%s'\n",
                             argv[i]);
                return 2;
            }
            threads = static_cast<int>(value);
        }
        else if (arg == "--colour-max" && i + 1 < argc)
        {
            char* end = nullptr;
            colour_max = std::strtod(argv[++i], &end);
            if (end == argv[i] || *end != '\0' || !std::isfinite(colour_max) || !(colour_max > 0.0))
            {
                std::fprintf(stderr, "crumple-replay: --colour-max needs a number > 0 (m), got '%s'\n", argv[i]);
                return 2;
            }
        }
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
    // Build every object once, before anything is written: a recording whose objects cannot be rebuilt is
    // refused and leaves no output.
    const auto replay_start = std::chrono::steady_clock::now();
    const double replay_cpu_start = common::ThreadCpuMs();
    Result<std::vector<ReplayedObject>> objects = CreateReplayedObjects(replay.Get());
    const double build_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - replay_start).count();
    if (!objects)
    {
        std::fprintf(stderr, "crumple-replay: %s\n", objects.GetError().mMessage.c_str());
        return 2;
    }
    std::error_code error;
    std::filesystem::create_directories(out / "frames", error);
    if (error)
    {
        std::fprintf(stderr, "crumple-replay: cannot create %s: %s\n", out.string().c_str(), error.message().c_str());
        return 2;
    }

    // Pictures: each object alone, in its body frame, coloured by dent depth.
    std::function<void(const ReplayedObject&, const std::filesystem::path&)> paint;
#if defined(CRUMPLE_REPLAY_PICTURES)
    std::unique_ptr<samples::ScenePainter> painter;
    if (pictures)
    {
        Result<std::unique_ptr<samples::ScenePainter>> created = samples::ScenePainter::Create(800, 600, 0.25);
        if (created)
            painter = std::move(created).Get();
        else
            std::printf("note: no pictures: %s\n", created.GetError().mMessage.c_str());
    }
    // The colour scale of each object: the given one, or its deepest dent at the end, which a first replay
    // finds (only when pictures are asked for), so its frames share the scale of its last picture.
    std::map<ObjectId, double> scales;
    if (painter != nullptr && colour_max == 0.0)
    {
        Result<std::vector<ReplayedObject>> ended = ReplayDamage(replay.Get());
        if (ended)
            for (const ReplayedObject& object : ended.Get())
            {
                const ffd::FfdDeformer& d = object.mDeformable.GetDeformer();
                const std::vector<double> depths = samples::DentDepths(d.GetPositions(), d.GetRestMesh().mPositions);
                scales[object.mObject] = samples::DentColorScale(depths.empty() ? 0.0 : *std::max_element(depths.begin(), depths.end()));
            }
    }
    if (painter != nullptr)
        paint = [&](const ReplayedObject& inObject, const std::filesystem::path& inPath) {
            const auto scale = scales.find(inObject.mObject);
            (void)painter->SetScalarMax(colour_max > 0.0 ? colour_max : scale != scales.end() ? scale->second : 0.25);
            const ffd::FfdDeformer& d = inObject.mDeformable.GetDeformer();
            const ffd::AlignedBox bounds = ffd::BoundingBox(d.GetRestMesh().mPositions);
            const Vec3 lo = bounds.mMin, hi = bounds.mMax;
            painter->Clear();
            painter->Add(d.GetPositions(), d.GetNormals(), d.GetRestMesh().mTriangles,
                         samples::DentDepths(d.GetPositions(), d.GetRestMesh().mPositions), {});
            const render::Camera camera = render::Camera::LookAtBounds(lo, hi, render::EView::Iso, Vec3::UnitZ(), Vec3::UnitX(), 30.0, 800.0 / 600.0);
            if (Status painted = painter->Paint(camera, inPath); !painted)
                std::printf("note: %s\n", painted.GetError().mMessage.c_str());
        };
#else
    if (pictures)
        std::printf("note: this build has no renderer (CRUMPLE_WITH_RENDER and assimp); no pictures\n");
#endif
    auto name = [](const ReplayedObject& inObject, const char* inSuffix) {
        return "object" + std::to_string(inObject.mObject.mValue) + inSuffix;
    };
    if (paint)
        for (const ReplayedObject& object : objects.Get())
            paint(object, out / name(object, "_before.png"));

#if defined(CRUMPLE_REPLAY_PROPS)
    // Destructible props (crumple::props records them beside the collisions): rebuilt, hit and stepped as
    // recorded; each one's boundary is written as it ended, cracks and all (here, after the objects). They
    // read the recording only and share nothing with the objects' replay: with --threads above 1 they replay
    // on a thread of their own beside it, their element passes on the other threads (the same bits, sooner),
    // else after it.
    const bool has_props = !replay.Get().mExtensions.empty();
    std::future<tools::PropsReplayOutcome> props_beside;
    double props_started_ms = 0.0; // after replay_start, where they replay beside the objects
    if (threads > 1 && has_props)
    {
        props_started_ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - replay_start)
                .count();
        try
        {
            props_beside = std::async(std::launch::async,
                                      [&] { return tools::ReplayPropsOf(replay.Get(), threads - 1); });
        }
        catch (const std::system_error&)
        {
            props_started_ms = 0.0; // no thread to be had: they replay after the objects
        }
    }
#endif

    std::size_t frame = 0;
    const Status applied = ApplyReplayedCollisions(
        replay.Get(), objects.Get(),
        [&](std::size_t inIndex, const std::vector<ReplayedObject>& inObjects)
        {
            if (!paint)
                return;
            const Collision& collision = replay.Get().mCollisions[inIndex];
            for (const ReplayedObject& object : inObjects)
                if (object.mBody == collision.mBodyA || object.mBody == collision.mBodyB)
                {
                    char suffix[32];
                    std::snprintf(suffix, sizeof(suffix), "_%04zu.png", frame++);
                    paint(object, out / "frames" / name(object, suffix));
                }
        });
    const double replay_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - replay_start).count();
    const double replay_cpu_ms = common::ThreadCpuMs() - replay_cpu_start;
    // intent: unreachable for a read file (DecodeReplay checks every collision), kept for the contract
    if (!applied)
    {
        std::fprintf(stderr, "crumple-replay: %s\n", applied.GetError().mMessage.c_str());
        return 2;
    }
    double props_ms = 0.0;     // replaying the props (their FEM steps), when the recording has any
    double props_cpu_ms = 0.0; // the same in the CPU time of the thread that ran them (workers' not counted)
    bool beside = false;       // they replayed on a thread of their own beside the objects
    double props_end_ms = 0.0; // wall time from the start until objects and props were both replayed
    for (const ReplayedObject& object : objects.Get())
    {
        const ffd::FfdDeformer& deformer = object.mDeformable.GetDeformer();
        const std::filesystem::path path = out / ("object" + std::to_string(object.mObject.mValue) + ".obj");
        if (Status written = meshes ? common::WriteObj(path, deformer.GetPositions(), deformer.GetNormals(),
                                                       deformer.GetRestMesh().mTriangles)
                                    : Status::Ok();
            !written)
        {
            std::fprintf(stderr, "crumple-replay: %s\n", written.GetError().mMessage.c_str());
            return 2;
        }
        double deepest = 0.0;
        for (std::size_t v = 0; v < deformer.GetPositions().size(); ++v)
            deepest = std::max(deepest, (deformer.GetPositions()[v] - deformer.GetRestMesh().mPositions[v]).norm());
        if (paint)
            paint(object, out / name(object, "_after.png"));
        std::printf("object %u (body %u): %zu vertices, deepest dent %.4f m, mesh hash %016llx -> %s\n",
                    object.mObject.mValue, object.mBody.mValue, deformer.GetPositions().size(), deepest,
                    static_cast<unsigned long long>(common::HashPositions(deformer.GetPositions())),
                    meshes ? path.string().c_str() : "(no mesh written)");
    }
#if defined(CRUMPLE_REPLAY_PROPS)
    beside = props_beside.valid();
    const tools::PropsReplayOutcome props_outcome =
        beside ? props_beside.get() : tools::ReplayPropsOf(replay.Get(), has_props ? threads : 1);
    if (!props_outcome.mError.empty())
    {
        std::fprintf(stderr, "crumple-replay: %s\n", props_outcome.mError.c_str());
        return 2;
    }
    for (std::size_t index = 0; index < props_outcome.mProps.size(); ++index)
    {
        const tools::ReplayedPropSummary& prop = props_outcome.mProps[index];
        if (!prop.mNote.empty())
            std::printf("%s\n", prop.mNote.c_str());
        const std::filesystem::path path = out / ("prop" + std::to_string(index) + ".obj");
        if (meshes)
        {
            const common::TetSurface surface = common::MakeTetSurface(prop.mPositions, prop.mElements);
            if (Status written =
                    common::WriteObj(path, prop.mPositions, surface.mNormals, surface.mTriangles);
                !written)
            {
                std::fprintf(stderr, "crumple-replay: %s\n", written.GetError().mMessage.c_str());
                return 2;
            }
        }
        std::printf("%s%s\n", prop.mReport.c_str(), meshes ? path.string().c_str() : "(no mesh written)");
    }
    // intent: a recording without props prints no props line
    props_ms = props_outcome.mProps.empty() ? 0.0 : props_outcome.mWallMs;
    props_cpu_ms = props_outcome.mCpuMs;
    // intent: beside the objects, both were done when the later one was (writing excluded, as above)
    props_end_ms = beside ? std::max(replay_ms, props_started_ms + props_ms) : replay_ms + props_ms;
#endif
    // Against the recording's own clock: it runs at least until its last collision closed.
    const auto& collisions = replay.Get().mCollisions;
    const double recorded_s = collisions.empty() ? 0.0 : collisions.back().mEndTime;
    // intent: a recording whose collisions all closed at t = 0 (or that has none) has no clock to compare
    // with
    const auto speed = [&](double inMs)
    {
        if (!(recorded_s > 0.0))
            return std::string("no recorded time to compare with");
        if (!(inMs > 0.0))
            return std::string("too fast to time");
        char text[64];
        std::snprintf(text, sizeof(text), "%.3gx real time", 1.0e3 * recorded_s / inMs);
        return std::string(text);
    };
    // intent: wall time, and this thread's CPU time beside it (the host's other jobs show in the first only;
    // with --threads the props' workers' CPU time is not in the second)
    std::printf("replayed %zu collisions in %.2f ms (%.2f ms of this thread's CPU; building the objects "
                "included: %.2f ms of it; writing excluded); "
                "the last recorded collision closed at t = %.3f s (%s)\n",
                collisions.size(), replay_ms, replay_cpu_ms, build_ms, recorded_s, speed(replay_ms).c_str());
    if (props_ms > 0.0)
        std::printf(
            "replayed the props in %.2f ms %s (%.2f ms of %s CPU; their FEM steps again); with them %.2f "
            "ms in all: %s\n",
            props_ms, beside ? "on a thread of their own beside the objects" : "more", props_cpu_ms,
            beside ? "that thread's" : "this thread's", props_end_ms, speed(props_end_ms).c_str());
    return 0;
}
