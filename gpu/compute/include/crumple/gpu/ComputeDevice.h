// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

#include <crumple/base/Result.h>
#include <crumple/gpu/EglContext.h>

#include <memory>
#include <string>

namespace crumple::gpu
{

struct ComputeGlFunctions;

/// A headless OpenGL 4.3+ context for compute shaders (an EglContext plus the compute entry points). Props
/// that run on the GPU share one device through shared_ptr; create it through a ComputeDeviceProvider so a
/// scene without a GPU prop never makes a context.
///
/// Threading: one thread at a time; every GPU object makes the context current before its GL calls.
class CRUMPLE_API ComputeDevice
{
public:
    /// Creates the context (OpenGL 4.3 core at least: compute shaders and shader storage buffers) and loads the
    /// entry points. Fails with the reason (no EGL, CRUMPLE_DISABLE_EGL set, version too low, entry point
    /// missing).
    static Result<std::shared_ptr<ComputeDevice>> Create(const EglContextSettings& inSettings = {});
    ~ComputeDevice();
    ComputeDevice(const ComputeDevice&) = delete;
    ComputeDevice& operator=(const ComputeDevice&) = delete;

    /// Makes the context current on the calling thread.
    Status MakeCurrent();
    /// Renderer and version, e.g. "llvmpipe (LLVM 15.0.6, 256 bits), OpenGL 4.5 (Core Profile) Mesa 22.3.6"
    std::string GetDescription() const;
    /// True for Mesa's software rasterisers (llvmpipe, softpipe): the "GPU" is the CPU
    bool IsSoftware() const;
    /// The compute entry points (private type, for the module's own classes)
    const ComputeGlFunctions& GetGl() const { return *mGl; }

private:
    ComputeDevice() = default;

    std::unique_ptr<EglContext> mContext;
    std::unique_ptr<ComputeGlFunctions> mGl;
};

/// Creates the shared ComputeDevice on the first Acquire() and hands the same one to every later caller; a
/// failure is remembered (with its reason) and not retried, so a machine without EGL pays for one attempt.
/// Owned by the game (one per scene or world): not a global.
class CRUMPLE_API ComputeDeviceProvider
{
public:
    explicit ComputeDeviceProvider(const EglContextSettings& inSettings = {}) : mSettings(inSettings) {}

    /// The shared device, or why there is none.
    Result<std::shared_ptr<ComputeDevice>> Acquire();
    /// True once Acquire() has been called (whether it succeeded or not)
    bool HasTried() const { return mTried; }

private:
    EglContextSettings mSettings;
    bool mTried = false;
    std::shared_ptr<ComputeDevice> mDevice;
    std::string mFailure;
    EError mFailureCode = EError::IoError;
};

} // namespace crumple::gpu
