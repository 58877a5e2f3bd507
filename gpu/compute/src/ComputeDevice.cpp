// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/gpu/ComputeDevice.h>

#include "ComputeGlFunctions.h"

namespace crumple::gpu
{

Result<std::shared_ptr<ComputeDevice>> ComputeDevice::Create(const EglContextSettings& inSettings)
{
    // Compute shaders and shader storage buffers are core in OpenGL 4.3.
    EglContextSettings settings = inSettings;
    if (settings.mMajorVersion < 4 || (settings.mMajorVersion == 4 && settings.mMinorVersion < 3))
    {
        settings.mMajorVersion = 4;
        settings.mMinorVersion = 3;
    }
    Result<std::unique_ptr<EglContext>> context = EglContext::Create(settings);
    if (context.HasError())
        return MakeError(context.GetError().mCode, "ComputeDevice: " + context.GetError().mMessage);
    const GlVersion version = context.Get()->GetVersion();
    if (version.mMajor < 4 || (version.mMajor == 4 && version.mMinor < 3))
        return MakeError(EError::IoError, "ComputeDevice: OpenGL " + std::to_string(version.mMajor) + "." +
                                              std::to_string(version.mMinor) +
                                              " has no compute shaders (4.3 needed)");

    std::shared_ptr<ComputeDevice> device(new ComputeDevice());
    device->mContext = std::move(context.Get());
    device->mGl = std::make_unique<ComputeGlFunctions>();
    if (const std::string missing = device->mGl->Load(*device->mContext); !missing.empty())
        return MakeError(EError::IoError, "ComputeDevice: the driver lacks " + missing);
    return device;
}

ComputeDevice::~ComputeDevice() = default;

Status ComputeDevice::MakeCurrent()
{
    return mContext->MakeCurrent();
}

std::string ComputeDevice::GetDescription() const
{
    return mContext->GetRendererString() + ", OpenGL " + mContext->GetVersionString();
}

bool ComputeDevice::IsSoftware() const
{
    const std::string& renderer = mContext->GetRendererString();
    return renderer.find("llvmpipe") != std::string::npos || renderer.find("softpipe") != std::string::npos;
}

Result<std::shared_ptr<ComputeDevice>> ComputeDeviceProvider::Acquire()
{
    if (!mTried)
    {
        mTried = true;
        Result<std::shared_ptr<ComputeDevice>> device = ComputeDevice::Create(mSettings);
        if (device.IsValid())
            mDevice = device.Get();
        else
        {
            mFailure = device.GetError().mMessage;
            mFailureCode = device.GetError().mCode;
        }
    }
    if (mDevice)
        return mDevice;
    return MakeError(mFailureCode, mFailure);
}

} // namespace crumple::gpu
