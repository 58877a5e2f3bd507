// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/plugin/ReplayFormat.h>

#include <filesystem>
#include <string>
#include <vector>

namespace crumple::tools
{

/// What replaying a recording's props did: the report's lines (one per prop) or the refusal, and the time it
/// took on the thread that ran it.
struct PropsReplayOutcome
{
    std::string mError;              ///< Empty when every prop replayed (and its mesh, if asked, was written)
    std::vector<std::string> mLines; ///< Printed after the objects' lines, in prop order
    double mWallMs = 0.0;            ///< Wall time of the whole replay of the props (ms)
    double mCpuMs = 0.0; ///< CPU time of the thread that ran it (ms; the element passes' workers not counted)
};

/// Replays the props of inReplay (props::ReplayProps), each one's boundary written as it ended to
/// inOut/prop<N>.obj where inMeshes, on a job system of inThreads threads for the element passes (1: none).
/// Everything it makes, a GPU prop's device and context included, is made and destroyed on the calling
/// thread, so it may run on a thread of its own beside the collisions' replay: it reads inReplay only.
PropsReplayOutcome ReplayAndWriteProps(const plugin::Replay& inReplay, const std::filesystem::path& inOut,
                                       bool inMeshes, int inThreads);

} // namespace crumple::tools
