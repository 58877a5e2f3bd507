// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>
#include <crumple/base/MixBits64.h>

#include <cstdint>

namespace crumple::fem
{

/// Steele, Lea and Flood's SplitMix64 generator (OOPSLA 2014, the reference splitmix64.c by S. Vigna): a
/// 64-bit state advanced by a Weyl increment and mixed by two multiply-xorshift rounds. Every operation is
/// exact unsigned integer arithmetic and NextDouble() converts by an exact power-of-two scaling, so the
/// stream is bitwise identical on every platform and compiler (unlike std::uniform_real_distribution, whose
/// algorithm is implementation-defined).
class CRUMPLE_API SplitMix64
{
  public:
    /// Starts the stream at inSeed; any value (0 included) is a good seed
    explicit SplitMix64(std::uint64_t inSeed) : mState(inSeed) {}

    /// Next 64 random bits
    std::uint64_t Next()
    {
        mState += 0x9e3779b97f4a7c15ULL;
        return MixBits64(mState);
    }

    /// Uniform double in [0, 1): the top 53 bits times 2^-53 (exact)
    double NextDouble() { return static_cast<double>(Next() >> 11) * 0x1.0p-53; }

    /// Uniform double in [-1, 1): 2 NextDouble() - 1 (exact)
    double NextSigned() { return 2.0 * NextDouble() - 1.0; }

  private:
    std::uint64_t mState;
};

} // namespace crumple::fem
