// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include "Benchmarks.h"

#include <memory>
#include <string>

namespace crumple::gpu
{
class ComputeDevice;
}

namespace crumple::bench
{

/// Rows gpu_implicit (part of the gpu group): the steel cantilever (1,125 and 9,000 tets; --quick the first)
/// from rest under the sudden 1 kN tip load, 10 implicit corotated steps of 1/60 s on the CPU (factored rest
/// system and block Jacobi, double) and on the GPU (block Jacobi, float), one step each in turn; medians of
/// wall and thread CPU time of the steps after the first; error: the tip against a CPU run converged to
/// round-off.
void RunGpuImplicitCases(BenchTable& ioTable, const BenchOptions& inOptions,
                         const std::shared_ptr<gpu::ComputeDevice>& inDevice,
                         const std::string& inDeviceName);

} // namespace crumple::bench
