// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// Fuzz target: a replay file (DamageRecorder's output, crumple-replay's input), decoded and then replayed
// as crumple-replay does, without a physics engine.
#include <crumple/plugin/ReplayDamage.h>
#include <crumple/plugin/ReplayFormat.h>

#include <cstddef>
#include <cstdint>
#include <span>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* inData, std::size_t inSize)
{
    const std::span<const std::byte> bytes(reinterpret_cast<const std::byte*>(inData), inSize);
    const crumple::Result<crumple::plugin::Replay> replay = crumple::plugin::DecodeReplay(bytes);
    if (replay.HasError())
        return 0;
    // The replay builds every object: keep the inputs whose meshes fit a fuzzing run's time.
    std::size_t vertices = 0, controls = 0;
    for (const crumple::plugin::RecordedObject& object : replay.Get().mObjects)
    {
        vertices += object.mSettings.mMesh.mPositions.size();
        for (const crumple::ffd::FfdZoneSettings& zone : object.mSettings.mDeformer.mZones)
            controls += static_cast<std::size_t>(zone.mLattice.mControlCount[0]) * zone.mLattice.mControlCount[1] *
                        zone.mLattice.mControlCount[2];
    }
    if (vertices > 20000 || controls > 200000 || replay.Get().mCollisions.size() > 64)
        return 0;
    (void)crumple::plugin::ReplayDamage(replay.Get());
    return 0;
}
