// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>
#include <crumple/base/Result.h>
#include <crumple/gpu/EEglPlatform.h>
#include <crumple/gpu/EglContextSettings.h>

#include <memory>
#include <string>

namespace crumple::gpu
{

struct GlFunctions;

/// An OpenGL version as reported by the driver (GL_MAJOR_VERSION, GL_MINOR_VERSION).
struct CRUMPLE_API GlVersion
{
    int mMajor = 0; ///< Major version, e.g. 4
    int mMinor = 0; ///< Minor version, e.g. 5
};

/// A headless OpenGL core-profile context made through EGL, with no window and no surface (rendering goes to
/// framebuffer objects). Create tries the EGL device platform (first device that works), then Mesa's
/// surfaceless platform, so it runs on a GPU as well as on Mesa's llvmpipe software driver.
///
/// The environment variable CRUMPLE_DISABLE_EGL=1 makes Create fail as if no EGL existed (tests use it to
/// simulate such machines). No global state: each context owns its EGL handles and GL entry points.
///
/// Threading: a context is current on at most one thread. Call MakeCurrent on the thread that issues GL
/// calls before issuing them; objects built on the context (renderers, compute kernels) do this themselves.
class CRUMPLE_API EglContext
{
public:
    /// A GL entry point as returned by eglGetProcAddress; cast it to its PFNGL...PROC type.
    using GlProc = void (*)();

    /// Creates the context and leaves it current on the calling thread. Fails with EError::InvalidArgument
    /// for a version below 3.2 or above 4.6, and with EError::IoError when no EGL platform gives a usable
    /// context (the message names each step that failed and its EGL error code).
    static Result<std::unique_ptr<EglContext>> Create(const EglContextSettings& inSettings = {});

    /// Releases the context (un-current on this thread if it is current here) and, when the display counts
    /// references (EGL_KHR_display_reference), terminates the display.
    ~EglContext();

    EglContext(const EglContext&) = delete;
    EglContext& operator=(const EglContext&) = delete;

    /// Makes the context current on the calling thread (no surface). Cheap when it already is.
    Status MakeCurrent();

    /// Looks up a GL (or EGL) entry point by name; nullptr when the driver does not have it.
    GlProc GetProcAddress(const char* inName) const;

    /// GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
    const std::string& GetRendererString() const { return mRenderer; }
    /// GL_VERSION as a string, e.g. "4.5 (Core Profile) Mesa 22.3.6".
    const std::string& GetVersionString() const { return mVersionString; }
    /// The context's OpenGL version, at least the one requested.
    GlVersion GetVersion() const { return mVersion; }
    /// The EGL platform the context was created on (Device or Surfaceless).
    EEglPlatform GetPlatform() const { return mPlatform; }

private:
    EglContext();

    void* mDisplay = nullptr;       ///< EGLDisplay
    void* mContext = nullptr;       ///< EGLContext
    bool mTerminateDisplay = false; ///< The display counts references, so eglTerminate releases only ours
    EEglPlatform mPlatform = EEglPlatform::Any; ///< Platform actually used
    GlVersion mVersion;                         ///< Version reported by the context
    std::string mRenderer;                      ///< GL_RENDERER
    std::string mVersionString;                 ///< GL_VERSION
    std::unique_ptr<GlFunctions> mGl;           ///< The few GL entry points this class uses
};

} // namespace crumple::gpu
