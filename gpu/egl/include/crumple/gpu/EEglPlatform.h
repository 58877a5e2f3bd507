// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

namespace crumple::gpu
{

/// The EGL platform a headless context is created on.
enum class EEglPlatform
{
    Any,         ///< Try Device first, then Surfaceless (the default)
    Device,      ///< EGL_EXT_platform_device: a GPU (or Mesa's software device) without any window system
    Surfaceless, ///< EGL_MESA_platform_surfaceless: Mesa's display without a native display
};

/// Short name of a platform, for messages and logs.
CRUMPLE_API const char* ToString(EEglPlatform inPlatform);

} // namespace crumple::gpu
