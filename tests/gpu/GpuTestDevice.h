// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/gpu/ComputeDevice.h>

#include <catch2/catch.hpp>

#include <memory>

namespace crumple::test
{

/// A compute device for a GPU test, or nullptr after a WARN saying why (no usable EGL here): the test then
/// returns, Catch2 v2's nearest thing to a skip.
inline std::shared_ptr<gpu::ComputeDevice> DeviceOrSkip()
{
    gpu::ComputeDeviceProvider provider;
    Result<std::shared_ptr<gpu::ComputeDevice>> device = provider.Acquire();
    if (device.HasError())
    {
        WARN("skipped: no compute device: " << device.GetError().mMessage);
        return nullptr;
    }
    return device.Get();
}

} // namespace crumple::test
