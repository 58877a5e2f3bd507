// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/gpu/EglContext.h>

#include "GlFunctions.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string_view>
#include <vector>

namespace crumple::gpu
{

namespace
{

/// Most EGL devices tried on the device platform; more than any real machine has.
constexpr EGLint cMaxDevices = 16;

/// Symbolic name and hex value of an EGL error code, e.g. "EGL_BAD_MATCH (0x3009)".
std::string EglErrorString(EGLint inError)
{
    const char* name = "unknown EGL error";
    switch (inError)
    {
    case EGL_SUCCESS:
        name = "EGL_SUCCESS";
        break;
    case EGL_NOT_INITIALIZED:
        name = "EGL_NOT_INITIALIZED";
        break;
    case EGL_BAD_ACCESS:
        name = "EGL_BAD_ACCESS";
        break;
    case EGL_BAD_ALLOC:
        name = "EGL_BAD_ALLOC";
        break;
    case EGL_BAD_ATTRIBUTE:
        name = "EGL_BAD_ATTRIBUTE";
        break;
    case EGL_BAD_CONFIG:
        name = "EGL_BAD_CONFIG";
        break;
    case EGL_BAD_CONTEXT:
        name = "EGL_BAD_CONTEXT";
        break;
    case EGL_BAD_CURRENT_SURFACE:
        name = "EGL_BAD_CURRENT_SURFACE";
        break;
    case EGL_BAD_DISPLAY:
        name = "EGL_BAD_DISPLAY";
        break;
    case EGL_BAD_MATCH:
        name = "EGL_BAD_MATCH";
        break;
    case EGL_BAD_NATIVE_PIXMAP:
        name = "EGL_BAD_NATIVE_PIXMAP";
        break;
    case EGL_BAD_NATIVE_WINDOW:
        name = "EGL_BAD_NATIVE_WINDOW";
        break;
    case EGL_BAD_PARAMETER:
        name = "EGL_BAD_PARAMETER";
        break;
    case EGL_BAD_SURFACE:
        name = "EGL_BAD_SURFACE";
        break;
    case EGL_CONTEXT_LOST:
        name = "EGL_CONTEXT_LOST";
        break;
    default:
        break;
    }
    std::array<char, 16> hex{};
    std::snprintf(hex.data(), hex.size(), "0x%04X", static_cast<unsigned>(inError));
    return std::string(name) + " (" + hex.data() + ")";
}

/// "<step> failed: <EGL error>" with the thread's current EGL error.
std::string EglFailure(const char* inStep)
{
    return std::string(inStep) + " failed: " + EglErrorString(eglGetError());
}

/// True when the space-separated extension list holds inName as a whole word.
bool HasExtension(const char* inList, std::string_view inName)
{
    if (inList == nullptr)
        return false;
    std::string_view list(inList);
    std::size_t start = 0;
    while (start < list.size())
    {
        const std::size_t end = std::min(list.find(' ', start), list.size());
        if (list.substr(start, end - start) == inName)
            return true;
        start = end + 1;
    }
    return false;
}

/// True when CRUMPLE_DISABLE_EGL is set to anything but "" or "0".
bool IsEglDisabledByEnvironment()
{
    const char* value = std::getenv("CRUMPLE_DISABLE_EGL");
    return value != nullptr && value[0] != '\0' && std::strcmp(value, "0") != 0;
}

/// eglGetProcAddress as the loader GlFunctions expects.
EglContext::GlProc LoadEglProc(const char* inName)
{
    return eglGetProcAddress(inName);
}

/// eglGetPlatformDisplay (EGL 1.5) or eglGetPlatformDisplayEXT, whichever the library has.
struct PlatformDisplayGetter
{
    PFNEGLGETPLATFORMDISPLAYPROC mCore = nullptr;   ///< EGL 1.5 entry point (EGLAttrib attributes)
    PFNEGLGETPLATFORMDISPLAYEXTPROC mExt = nullptr; ///< EGL_EXT_platform_base entry point (EGLint attributes)
    bool mTrackReferences = false;                  ///< Ask for a reference-counted display

    /// The display of a platform, or EGL_NO_DISPLAY.
    EGLDisplay Get(EGLenum inPlatform, void* inNativeDisplay) const
    {
        if (mCore != nullptr)
        {
            std::array<EGLAttrib, 3> attributes{EGL_NONE, EGL_NONE, EGL_NONE};
#if defined(EGL_KHR_display_reference)
            if (mTrackReferences)
                attributes = {EGL_TRACK_REFERENCES_KHR, EGL_TRUE, EGL_NONE};
#endif
            return mCore(inPlatform, inNativeDisplay, attributes.data());
        }
        std::array<EGLint, 3> attributes{EGL_NONE, EGL_NONE, EGL_NONE};
#if defined(EGL_KHR_display_reference)
        if (mTrackReferences)
            attributes = {EGL_TRACK_REFERENCES_KHR, EGL_TRUE, EGL_NONE};
#endif
        return mExt(inPlatform, inNativeDisplay, attributes.data());
    }
};

/// Requested version as one comparable number, e.g. 43.
int VersionKey(int inMajor, int inMinor)
{
    return inMajor * 10 + inMinor;
}

/// Creates a context on one display and fills ioContext; appends the reason to ioLog on failure.
/// The display is left initialized on failure unless it counts references: terminating a display without
/// reference counting would also end every other EglContext of this process on the same display.
bool TryDisplay(EGLDisplay inDisplay, bool inTrackReferences, const EglContextSettings& inSettings,
                const std::string& inLabel, EGLContext& outContext, std::string& ioLog)
{
    const auto fail = [&](const std::string& inWhy)
    {
        ioLog += inLabel + ": " + inWhy + "; ";
        return false;
    };
    const auto release_display = [&]()
    {
        if (inTrackReferences)
            eglTerminate(inDisplay);
    };

    // Display and its version.
    if (inDisplay == EGL_NO_DISPLAY)
        return fail(EglFailure("eglGetPlatformDisplay"));
    EGLint egl_major = 0;
    EGLint egl_minor = 0;
    if (eglInitialize(inDisplay, &egl_major, &egl_minor) == EGL_FALSE)
        return fail(EglFailure("eglInitialize"));

    // Surfaceless contexts and versioned core-profile contexts are extensions before EGL 1.5.
    const char* extensions = eglQueryString(inDisplay, EGL_EXTENSIONS);
    const bool egl15 = VersionKey(egl_major, egl_minor) >= 15;
    if (!HasExtension(extensions, "EGL_KHR_surfaceless_context"))
    {
        release_display();
        return fail("EGL_KHR_surfaceless_context not supported");
    }
    if (!egl15 && !HasExtension(extensions, "EGL_KHR_create_context"))
    {
        release_display();
        return fail("EGL " + std::to_string(egl_major) + "." + std::to_string(egl_minor) +
                    " without EGL_KHR_create_context cannot make a core-profile context");
    }
    if (eglBindAPI(EGL_OPENGL_API) == EGL_FALSE)
    {
        release_display();
        return fail(EglFailure("eglBindAPI(EGL_OPENGL_API)"));
    }

    // A config only when the display needs one (no surface is ever made).
    EGLConfig config = EGL_NO_CONFIG_KHR;
    if (!HasExtension(extensions, "EGL_KHR_no_config_context"))
    {
        EGLint count = 0;
        std::array<EGLint, 5> attributes{EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                                         EGL_OPENGL_BIT, EGL_NONE};
        if (eglChooseConfig(inDisplay, attributes.data(), &config, 1, &count) == EGL_FALSE || count < 1)
        {
            // Some device displays have no pbuffer configs; any OpenGL config will do.
            attributes[1] = 0;
            if (eglChooseConfig(inDisplay, attributes.data(), &config, 1, &count) == EGL_FALSE || count < 1)
            {
                release_display();
                return fail(count < 1 ? std::string("eglChooseConfig found no OpenGL config")
                                      : EglFailure("eglChooseConfig"));
            }
        }
    }

    // Core profile of at least the requested version.
    std::vector<EGLint> attributes{EGL_CONTEXT_MAJOR_VERSION,       inSettings.mMajorVersion,
                                   EGL_CONTEXT_MINOR_VERSION,       inSettings.mMinorVersion,
                                   EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT};
    if (inSettings.mDebugContext)
    {
        if (egl15)
            attributes.insert(attributes.end(), {EGL_CONTEXT_OPENGL_DEBUG, EGL_TRUE});
        else
            attributes.insert(attributes.end(), {EGL_CONTEXT_FLAGS_KHR, EGL_CONTEXT_OPENGL_DEBUG_BIT_KHR});
    }
    attributes.push_back(EGL_NONE);
    EGLContext context = eglCreateContext(inDisplay, config, EGL_NO_CONTEXT, attributes.data());
    if (context == EGL_NO_CONTEXT)
    {
        const std::string why = EglFailure("eglCreateContext") + " for OpenGL " +
                                std::to_string(inSettings.mMajorVersion) + "." +
                                std::to_string(inSettings.mMinorVersion) + " core";
        release_display();
        return fail(why);
    }

    // Surfaceless: all drawing goes to framebuffer objects.
    if (eglMakeCurrent(inDisplay, EGL_NO_SURFACE, EGL_NO_SURFACE, context) == EGL_FALSE)
    {
        const std::string why = EglFailure("eglMakeCurrent(EGL_NO_SURFACE)");
        eglDestroyContext(inDisplay, context);
        release_display();
        return fail(why);
    }
    outContext = context;
    return true;
}

} // namespace

EglContext::EglContext() = default;

EglContext::~EglContext()
{
    if (mContext != nullptr)
    {
        // Un-current only if it is current on this thread; another thread's binding is its owner's business.
        if (eglGetCurrentContext() == mContext)
            eglMakeCurrent(mDisplay, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(mDisplay, mContext);
    }
    if (mDisplay != nullptr && mTerminateDisplay)
        eglTerminate(mDisplay);
}

Result<std::unique_ptr<EglContext>> EglContext::Create(const EglContextSettings& inSettings)
{
    // Refuse versions without a core profile or beyond OpenGL 4.6 before touching EGL.
    const int requested = VersionKey(inSettings.mMajorVersion, inSettings.mMinorVersion);
    const bool valid_minor =
        inSettings.mMinorVersion >= 0 && inSettings.mMinorVersion <= (inSettings.mMajorVersion == 3 ? 3 : 6);
    if (inSettings.mMajorVersion < 3 || inSettings.mMajorVersion > 4 || !valid_minor || requested < 32)
        return MakeError(EError::InvalidArgument, "EglContextSettings version " +
                                                      std::to_string(inSettings.mMajorVersion) + "." +
                                                      std::to_string(inSettings.mMinorVersion) +
                                                      " is not an OpenGL core profile version (3.2 to 4.6)");

    // The switch tests use to simulate a machine without EGL.
    if (IsEglDisabledByEnvironment())
        return MakeError(EError::IoError, "EglContext::Create: EGL disabled by CRUMPLE_DISABLE_EGL=" +
                                              std::string(std::getenv("CRUMPLE_DISABLE_EGL")) +
                                              " (unset it to use EGL)");

    // Platform displays need client extensions and eglGetPlatformDisplay(EXT).
    const char* client_extensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (client_extensions == nullptr)
        return MakeError(EError::IoError,
                         "EglContext::Create: no usable EGL: " +
                             EglFailure("eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS)") +
                             " (EGL_EXT_client_extensions missing; install libegl-mesa0 or a "
                             "GPU driver's EGL)");
    PlatformDisplayGetter getter;
    getter.mCore = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYPROC>(eglGetProcAddress("eglGetPlatformDisplay"));
    if (getter.mCore == nullptr && HasExtension(client_extensions, "EGL_EXT_platform_base"))
        getter.mExt =
            reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (getter.mCore == nullptr && getter.mExt == nullptr)
        return MakeError(EError::IoError,
                         "EglContext::Create: no usable EGL: neither eglGetPlatformDisplay nor "
                         "eglGetPlatformDisplayEXT is available");
    getter.mTrackReferences = HasExtension(client_extensions, "EGL_KHR_display_reference");

    std::unique_ptr<EglContext> context(new EglContext());
    std::string log;
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLContext egl_context = EGL_NO_CONTEXT;
    bool created = false;

    // 1. Device platform: the first device that gives a context (a GPU, or Mesa's software device).
    const bool want_device =
        inSettings.mPlatform == EEglPlatform::Any || inSettings.mPlatform == EEglPlatform::Device;
    if (want_device && !HasExtension(client_extensions, "EGL_EXT_platform_device"))
        log += "device platform: EGL_EXT_platform_device not supported; ";
    else if (want_device)
    {
        const auto query_devices =
            reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
        std::array<EGLDeviceEXT, cMaxDevices> devices{};
        EGLint device_count = 0;
        if (query_devices == nullptr)
            log += "device platform: eglQueryDevicesEXT not available; ";
        else if (query_devices(cMaxDevices, devices.data(), &device_count) == EGL_FALSE)
            log += "device platform: " + EglFailure("eglQueryDevicesEXT") + "; ";
        else if (device_count == 0)
            log += "device platform: no EGL devices; ";
        for (EGLint i = 0; i < device_count && !created; ++i)
        {
            display = getter.Get(EGL_PLATFORM_DEVICE_EXT, devices[static_cast<std::size_t>(i)]);
            created = TryDisplay(display, getter.mTrackReferences, inSettings, "device " + std::to_string(i),
                                 egl_context, log);
            if (created)
                context->mPlatform = EEglPlatform::Device;
        }
    }

    // 2. Mesa's surfaceless platform.
    const bool want_surfaceless =
        inSettings.mPlatform == EEglPlatform::Any || inSettings.mPlatform == EEglPlatform::Surfaceless;
    if (!created && want_surfaceless)
    {
        if (!HasExtension(client_extensions, "EGL_MESA_platform_surfaceless"))
            log += "surfaceless platform: EGL_MESA_platform_surfaceless not supported; ";
        else
        {
            display = getter.Get(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY);
            created = TryDisplay(display, getter.mTrackReferences, inSettings, "surfaceless platform",
                                 egl_context, log);
            if (created)
                context->mPlatform = EEglPlatform::Surfaceless;
        }
    }

    const std::string what = "an OpenGL " + std::to_string(inSettings.mMajorVersion) + "." +
                             std::to_string(inSettings.mMinorVersion) + " core context";
    if (!created)
    {
        if (log.size() >= 2)
            log.resize(log.size() - 2);
        return MakeError(EError::IoError, "EglContext::Create: no usable EGL for " + what + ": " + log);
    }
    context->mDisplay = display;
    context->mContext = egl_context;
    context->mTerminateDisplay = getter.mTrackReferences;

    // GL entry points; the destructor releases the context if any is missing.
    context->mGl = std::make_unique<GlFunctions>();
    const std::string missing = context->mGl->Load(&LoadEglProc);
    if (!missing.empty())
        return MakeError(EError::IoError, "EglContext::Create: eglGetProcAddress has no " + missing);

    // Version and renderer as the driver reports them.
    GlFunctions& gl = *context->mGl;
    gl.mGetIntegerv(GL_MAJOR_VERSION, &context->mVersion.mMajor);
    gl.mGetIntegerv(GL_MINOR_VERSION, &context->mVersion.mMinor);
    const auto as_string = [&](GLenum inName)
    {
        const GLubyte* value = gl.mGetString(inName);
        return value != nullptr ? std::string(reinterpret_cast<const char*>(value)) : std::string();
    };
    context->mRenderer = as_string(GL_RENDERER);
    context->mVersionString = as_string(GL_VERSION);
    if (VersionKey(context->mVersion.mMajor, context->mVersion.mMinor) < requested)
        return MakeError(EError::IoError, "EglContext::Create: asked for " + what + ", the " +
                                              ToString(context->mPlatform) + " platform gave " +
                                              context->mVersionString + " (" + context->mRenderer + ")");
    while (gl.mGetError() != GL_NO_ERROR)
    {
    }
    return context;
}

Status EglContext::MakeCurrent()
{
    // eglMakeCurrent binds for the thread's current API, so bind OpenGL on this thread first.
    if (eglBindAPI(EGL_OPENGL_API) == EGL_FALSE)
        return MakeError(EError::IoError,
                         "EglContext::MakeCurrent: " + EglFailure("eglBindAPI(EGL_OPENGL_API)"));
    if (eglGetCurrentContext() == mContext)
        return Status::Ok();
    if (eglMakeCurrent(mDisplay, EGL_NO_SURFACE, EGL_NO_SURFACE, mContext) == EGL_FALSE)
        return MakeError(EError::IoError, "EglContext::MakeCurrent: " + EglFailure("eglMakeCurrent") +
                                              " (a context is current on one thread at a time)");
    return Status::Ok();
}

EglContext::GlProc EglContext::GetProcAddress(const char* inName) const
{
    return eglGetProcAddress(inName);
}

} // namespace crumple::gpu
