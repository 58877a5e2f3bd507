// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

namespace crumple
{

/// Whether readers verify the CRC-32 of what they read. Always, except in a fuzzing build: there
/// FUZZING_BUILD_MODE_UNSAFE_FOR_PRODUCTION (the macro libFuzzer and OSS-Fuzz builds define) turns the
/// check off, so that mutated inputs reach the decoders behind it instead of stopping at the checksum.
#ifdef FUZZING_BUILD_MODE_UNSAFE_FOR_PRODUCTION
constexpr bool cVerifyChecksums = false;
#else
constexpr bool cVerifyChecksums = true;
#endif

} // namespace crumple
