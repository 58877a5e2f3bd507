// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>
#include <crumple/base/Result.h>

#include <string_view>

namespace crumple
{

/// The check every Step and Prepare makes of its time step: Ok for a finite step > 0 s; otherwise
/// "<inCaller>: time step <dt> s must be finite and > 0", EError::NonFinite for NaN or infinity and
/// EError::InvalidArgument for zero or a negative step.
CRUMPLE_API Status CheckTimeStep(double inDeltaTime, std::string_view inCaller);

} // namespace crumple
