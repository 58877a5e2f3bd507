// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Math.h>
#include <crumple/fem/TetMesh.h>
#include <crumple/plugin/ReplayFormat.h>

#include <string>
#include <vector>

namespace crumple::tools
{

/// One replayed prop as it ended: what its report line and its mesh need, read off the prop on the thread
/// that replayed it.
struct ReplayedPropSummary
{
    std::string mNote;            ///< A line before the report (a GPU prop replayed on the CPU), or empty
    std::string mReport;          ///< Its report line up to the mesh's path ("... -> ")
    std::vector<Vec3> mPositions; ///< Node positions at the end (m)
    std::vector<fem::TetIndices> mElements; ///< Its tetrahedra, cracks and all
};

/// What replaying a recording's props did, and the time it took on the thread that ran it.
struct PropsReplayOutcome
{
    std::string mError;                      ///< Empty when every prop replayed
    std::vector<ReplayedPropSummary> mProps; ///< In prop order
    double mWallMs = 0.0;                    ///< Wall time of the replay (ms)
    double mCpuMs = 0.0; ///< CPU time of the thread that ran it (ms; the element passes' workers not counted)
};

/// Replays the props of inReplay (props::ReplayProps), the element passes on a job system of inThreads
/// threads (1: none). Everything it makes, a GPU prop's device and context included, is made and destroyed
/// on the calling thread, and it reads inReplay only and writes nothing: it may run on a thread of its own
/// beside the objects' replay.
PropsReplayOutcome ReplayPropsOf(const plugin::Replay& inReplay, int inThreads);

} // namespace crumple::tools
