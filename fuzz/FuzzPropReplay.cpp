// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// Fuzz target: a replay file with props (PropWorld's extension records), decoded and its props replayed as
// crumple-replay does, without a physics engine.
#include <crumple/plugin/ReplayFormat.h>
#include <crumple/props/PropRecording.h>

#include <cstddef>
#include <cstdint>
#include <span>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* inData, std::size_t inSize)
{
    using namespace crumple;
    const std::span<const std::byte> bytes(reinterpret_cast<const std::byte*>(inData), inSize);
    const Result<plugin::Replay> replay = plugin::DecodeReplay(bytes);
    if (replay.HasError())
        return 0;
    // The replay steps every prop at every step record: keep the inputs that fit a fuzzing run's time
    // (small props, few steps, solver limits near the defaults). Oversized limits are valid input, just slow.
    if (replay.Get().mExtensions.size() > 32 || replay.Get().mCollisions.size() > 32)
        return 0;
    for (const plugin::RecordedExtension& extension : replay.Get().mExtensions)
    {
        if (extension.mTag != static_cast<std::uint32_t>(props::EPropRecord::Added))
            continue;
        const Result<props::PropSetup> setup = props::DecodePropSetup(extension.mPayload);
        if (setup.HasError())
            continue; // ReplayProps refuses it: still worth running
        const fem::TetSolverSettings& settings = setup.Get().mSettings;
        if (setup.Get().mTets.size() > 2000 || settings.mMaxSubSteps > 200 || settings.mCgMaxIterations > 2000 ||
            settings.mImplicitMaxIterations > 8 || settings.mMaxStepSplits > 4)
            return 0;
    }
    (void)props::ReplayProps(replay.Get());
    return 0;
}
