// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
// The compute module: a lazily made, shared device; programs that report GLSL errors with the driver's log;
// storage buffers that round-trip; a clean refusal where no EGL exists.
#include "SkipTest.h"

#include <crumple/gpu/ComputeProgram.h>
#include <crumple/gpu/StorageBuffer.h>

#include <catch2/catch.hpp>

#include <cstdlib>
#include <numeric>
#include <vector>

using namespace crumple;
using namespace crumple::gpu;

namespace
{

// A device for a test; without one the test process ends as skipped (SkipTest).
std::shared_ptr<ComputeDevice> DeviceOrSkip(ComputeDeviceProvider& ioProvider)
{
    Result<std::shared_ptr<ComputeDevice>> device = ioProvider.Acquire();
    if (device.HasError())
    {
        common::SkipTest("no compute device: " + device.GetError().mMessage);
    }
    return device.Get();
}

constexpr const char* cDoubleKernel = R"glsl(#version 430
layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer Data { float data[]; };
uniform uint uCount;
void main()
{
    uint i = gl_GlobalInvocationID.x;
    if (i < uCount)
        data[i] = 2.0 * data[i] + 1.0;
}
)glsl";

} // namespace

TEST_CASE("ComputeDeviceProvider makes one device lazily and shares it", "[gpu]")
{
    ComputeDeviceProvider provider;
    CHECK_FALSE(provider.HasTried()); // nothing made until a GPU prop asks
    const std::shared_ptr<ComputeDevice> device = DeviceOrSkip(provider);
    CHECK(provider.HasTried());
    INFO(device->GetDescription());
    Result<std::shared_ptr<ComputeDevice>> again = provider.Acquire();
    REQUIRE(again.IsValid());
    CHECK(again.Get() == device);
}

TEST_CASE("A compute program runs over a storage buffer and the result reads back exactly", "[gpu]")
{
    ComputeDeviceProvider provider;
    const std::shared_ptr<ComputeDevice> device = DeviceOrSkip(provider);
    Result<ComputeProgram> program = ComputeProgram::Create(device, "double", cDoubleKernel);
    REQUIRE(program.IsValid());
    CHECK(program.Get().GetLocalSize() == 64u);

    std::vector<float> data(1000);
    std::iota(data.begin(), data.end(), 0.0f);
    Result<StorageBuffer> buffer = StorageBuffer::Create(device, data.size() * sizeof(float), data.data());
    REQUIRE(buffer.IsValid());
    buffer.Get().Bind(0);
    program.Get().Use();
    program.Get().SetUInt("uCount", 999); // the last element stays as it was
    program.Get().Dispatch(999);
    std::vector<float> result(data.size());
    buffer.Get().Download(0, result.size() * sizeof(float), result.data());
    for (std::size_t i = 0; i < 999; ++i)
        REQUIRE(result[i] == 2.0f * data[i] + 1.0f); // exact in float for these integers
    CHECK(result[999] == 999.0f);
}

TEST_CASE("A GLSL compile error comes back with the driver's log and the program's name", "[gpu]")
{
    ComputeDeviceProvider provider;
    const std::shared_ptr<ComputeDevice> device = DeviceOrSkip(provider);
    Result<ComputeProgram> broken =
        ComputeProgram::Create(device, "broken", "#version 430\nlayout(local_size_x = 1) in;\nvoid main() { undeclared = 1; }\n");
    REQUIRE(broken.HasError());
    CHECK(broken.GetError().mMessage.find("broken") != std::string::npos);
    CHECK(broken.GetError().mMessage.find("undeclared") != std::string::npos);
}

TEST_CASE("Without EGL the provider reports why, once, and never retries", "[gpu]")
{
    // CRUMPLE_DISABLE_EGL makes context creation fail as on a machine without a usable EGL.
    ::setenv("CRUMPLE_DISABLE_EGL", "1", 1);
    ComputeDeviceProvider provider;
    Result<std::shared_ptr<ComputeDevice>> first = provider.Acquire();
    ::unsetenv("CRUMPLE_DISABLE_EGL");
    REQUIRE(first.HasError());
    CHECK(first.GetError().mMessage.find("CRUMPLE_DISABLE_EGL") != std::string::npos);
    // EGL is back, but the provider keeps its answer: one attempt per scene.
    Result<std::shared_ptr<ComputeDevice>> second = provider.Acquire();
    REQUIRE(second.HasError());
    CHECK(second.GetError().mMessage == first.GetError().mMessage);
}
