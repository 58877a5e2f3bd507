// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

namespace crumple::common
{

/// CPU time the calling thread has used (ms, from an arbitrary origin): with wall time, it tells work from
/// waiting when other jobs share the machine.
double ThreadCpuMs();

} // namespace crumple::common
