// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/ffd/FfdDeformer.h>
#include <crumple/ffd/SurfaceProbe.h>

namespace crumple::common
{

/// FfdDeformer::ProbeSurface's answer the plain way, as a crush planner would scan the surface without an
/// index: every current vertex and every triangle tested against the probe's prism (a triangle across its
/// boundary clipped to it). The reference the indexed probe must equal bit for bit.
ffd::SurfaceProbeResult BruteForceProbe(const ffd::FfdDeformer& inDeformer, const ffd::SurfaceProbe& inProbe);

} // namespace crumple::common
