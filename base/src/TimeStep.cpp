// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/base/TimeStep.h>

#include <cmath>
#include <sstream>

namespace crumple
{

Status CheckTimeStep(double inDeltaTime, std::string_view inCaller)
{
    if (std::isfinite(inDeltaTime) && inDeltaTime > 0.0)
        return Status::Ok();
    std::ostringstream message;
    message << inCaller << ": time step " << inDeltaTime << " s must be finite and > 0";
    return MakeError(std::isfinite(inDeltaTime) ? EError::InvalidArgument : EError::NonFinite, message.str());
}

} // namespace crumple
