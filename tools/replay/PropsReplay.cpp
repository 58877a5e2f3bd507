// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "PropsReplay.h"

#include "MeshHash.h"
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

PropsReplayOutcome ReplayPropsOf(const plugin::Replay& inReplay, int inThreads)
{
    PropsReplayOutcome outcome;
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = common::ThreadCpuMs();
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
    outcome.mWallMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    outcome.mCpuMs = common::ThreadCpuMs() - cpu_start;
    if (!replayed)
    {
        outcome.mError = replayed.GetError().mMessage;
        return outcome;
    }
    for (std::size_t index = 0; index < replayed.Get().size(); ++index)
    {
        const props::ReplayedProp& prop = replayed.Get()[index];
        ReplayedPropSummary summary;
        // intent: the fixed parts formatted, the reason (any length) appended
        char line[256];
        if (prop.mRecordedBackend != prop.mProp.GetBackend())
        {
            std::snprintf(line, sizeof(line), "prop %zu ran on the %s live and replays on the %s (", index,
                          props::ToString(prop.mRecordedBackend), props::ToString(prop.mProp.GetBackend()));
            summary.mNote = line + prop.mProp.GetFallbackReason() + "): close, not bitwise";
        }
        prop.mProp.ReadPositions(summary.mPositions);
        summary.mElements = prop.mProp.GetElementNodes();
        std::snprintf(
            line, sizeof(line),
            "prop %zu (body %u, %s%s): %d nodes, %d links broken, %zu pieces, position hash %016llx -> ",
            index, prop.mBody.mValue, props::ToString(prop.mProp.GetBackend()),
            prop.mRemoved ? ", removed live: as it was then" : "", prop.mProp.GetNodeCount(),
            prop.mProp.GetBrokenLinkCount(), prop.mProp.ComputeFragments().size(),
            static_cast<unsigned long long>(common::HashPositions(summary.mPositions)));
        summary.mReport = line;
        outcome.mProps.push_back(std::move(summary));
    }
    return outcome;
}

} // namespace crumple::tools
