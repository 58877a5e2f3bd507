// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include "SkipTest.h"

#include <crumple/gpu/ComputeDevice.h>

#include <catch2/catch.hpp>

#include <memory>

namespace crumple::test
{

/// A compute device for a GPU test; without one (no usable EGL here) the test process ends as skipped
/// (SkipTest: CTest shows it skipped, not passed).
inline std::shared_ptr<gpu::ComputeDevice> DeviceOrSkip()
{
    gpu::ComputeDeviceProvider provider;
    Result<std::shared_ptr<gpu::ComputeDevice>> device = provider.Acquire();
    if (device.HasError())
    {
        common::SkipTest("no compute device: " + device.GetError().mMessage);
    }
    return device.Get();
}

} // namespace crumple::test
