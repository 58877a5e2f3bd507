// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "PropsReplay.h"

#include "MeshHash.h"
#include "ObjWriter.h"
#include "TetSurface.h"
#include "ThreadCpuTime.h"
#include "ThreadJobSystem.h"

#include <crumple/props/PropRecording.h>
#if defined(CRUMPLE_REPLAY_GPU)
#include <crumple/gpu/ComputeDevice.h>
#endif

#include <chrono>
#include <cstdio>
#include <optional>
#include <string>

namespace crumple::tools
{

PropsReplayOutcome ReplayAndWriteProps(const plugin::Replay& inReplay, const std::filesystem::path& inOut,
                                       bool inMeshes, int inThreads)
{
    PropsReplayOutcome outcome;
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = common::ThreadCpuMs();
    const auto stop_clocks = [&]
    {
        outcome.mWallMs =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        outcome.mCpuMs = common::ThreadCpuMs() - cpu_start;
    };
    // intent: a GPU prop replays on a device of its own (the context is made only if a GPU prop asks)
#if defined(CRUMPLE_REPLAY_GPU)
    gpu::ComputeDeviceProvider devices;
    gpu::ComputeDeviceProvider* const device_provider = &devices;
#else
    gpu::ComputeDeviceProvider* const device_provider = nullptr;
#endif
    // intent: workers only where asked (a replay on one thread makes none)
    std::optional<common::ThreadJobSystem> jobs;
    if (inThreads > 1)
        jobs.emplace(inThreads);
    Result<std::vector<props::ReplayedProp>> replayed =
        props::ReplayProps(inReplay, device_provider, jobs ? &jobs->Get() : nullptr);
    stop_clocks();
    if (!replayed)
    {
        outcome.mError = replayed.GetError().mMessage;
        return outcome;
    }
    for (std::size_t index = 0; index < replayed.Get().size(); ++index)
    {
        const props::ReplayedProp& prop = replayed.Get()[index];
        // intent: the fixed parts formatted, the reason and the path (any length) appended
        char line[256];
        if (prop.mRecordedBackend != prop.mProp.GetBackend())
        {
            std::snprintf(line, sizeof(line), "prop %zu ran on the %s live and replays on the %s (", index,
                          props::ToString(prop.mRecordedBackend), props::ToString(prop.mProp.GetBackend()));
            outcome.mLines.push_back(line + prop.mProp.GetFallbackReason() + "): close, not bitwise");
        }
        std::vector<Vec3> positions;
        prop.mProp.ReadPositions(positions);
        const std::filesystem::path path = inOut / ("prop" + std::to_string(index) + ".obj");
        if (inMeshes)
        {
            const common::TetSurface surface =
                common::MakeTetSurface(positions, prop.mProp.GetElementNodes());
            if (Status written = common::WriteObj(path, positions, surface.mNormals, surface.mTriangles);
                !written)
            {
                outcome.mError = written.GetError().mMessage;
                return outcome;
            }
        }
        std::snprintf(
            line, sizeof(line),
            "prop %zu (body %u, %s%s): %d nodes, %d links broken, %zu pieces, position hash %016llx -> ",
            index, prop.mBody.mValue, props::ToString(prop.mProp.GetBackend()),
            prop.mRemoved ? ", removed live: as it was then" : "", prop.mProp.GetNodeCount(),
            prop.mProp.GetBrokenLinkCount(), prop.mProp.ComputeFragments().size(),
            static_cast<unsigned long long>(common::HashPositions(positions)));
        outcome.mLines.push_back(line + (inMeshes ? path.string() : std::string("(no mesh written)")));
    }
    return outcome;
}

} // namespace crumple::tools
