// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/gpu/EEglPlatform.h>

namespace crumple::gpu
{

/// How to create a headless OpenGL context. The context is a core profile of at least the requested version;
/// drivers usually return their highest compatible version (Mesa llvmpipe: 4.5).
struct CRUMPLE_API EglContextSettings
{
    int mMajorVersion = 4; ///< Lowest acceptable OpenGL core major version, 3 or 4
    int mMinorVersion = 3; ///< Lowest acceptable minor version; 4.3 has compute shaders, >= 3.2 (core)
    EEglPlatform mPlatform = EEglPlatform::Any; ///< Which EGL platform(s) to try
    bool mDebugContext = false;                 ///< Request a debug context (slower; for driver messages)
};

} // namespace crumple::gpu
