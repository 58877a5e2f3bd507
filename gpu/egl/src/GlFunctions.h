// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/gpu/EglContext.h>

#include <GL/glcorearb.h>

#include <string>

namespace crumple::gpu
{

/// The GL entry points EglContext itself needs, loaded through eglGetProcAddress (no GLEW/GLAD). Owned by
/// the context: no global function pointers. Modules that draw or compute load their own table the same way
/// through EglContext::GetProcAddress.
struct GlFunctions
{
    PFNGLGETSTRINGPROC mGetString = nullptr;     ///< glGetString
    PFNGLGETINTEGERVPROC mGetIntegerv = nullptr; ///< glGetIntegerv
    PFNGLGETERRORPROC mGetError = nullptr;       ///< glGetError
    PFNGLFINISHPROC mFinish = nullptr;           ///< glFinish

    /// Loads every entry point with inLoad (a context must be current). Returns the names that could not be
    /// loaded, space separated; empty on success.
    std::string Load(EglContext::GlProc (*inLoad)(const char*));
};

} // namespace crumple::gpu
