// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

// A GPU case of test_props that got a CPU prop back passes only where there is no compute device: a
// fallback for any other reason (a shader the device refused, a setting the GPU path dropped) must fail the
// case, not let it pass as if it had run. (Without a device the cases end as before: skipped or warned.)

#include <catch2/catch.hpp>

#include <string>

#if defined(CRUMPLE_TEST_PROPS_WITH_GPU)
#include <crumple/gpu/ComputeDevice.h>
#endif

namespace crumple::test
{

#if defined(CRUMPLE_TEST_PROPS_WITH_GPU)
/// Fails the running case when ioProvider (null: none) has a device, naming inReason, the prop's fallback
/// reason. The provider caches its device or its failure: asking again makes no second context.
inline void RequireNoComputeDevice(gpu::ComputeDeviceProvider* ioProvider, const std::string& inReason)
{
    INFO("the GPU case ran on the CPU although a compute device exists: " << inReason);
    REQUIRE_FALSE((ioProvider != nullptr && ioProvider->Acquire().IsValid()));
}
#else
/// A build without the GPU backend has no device: every GPU case falls back.
template <class Provider> inline void RequireNoComputeDevice(Provider*, const std::string&) {}
#endif

} // namespace crumple::test
