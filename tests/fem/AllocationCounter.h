// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>

namespace crumple::test
{

/// Counts the calls of the global operator new (every form) made by this thread between construction and
/// Count(); test_fem replaces operator new for this (AllocationCounter.cpp), forwarding to malloc. Not under
/// AddressSanitizer, whose runtime owns operator new: IsAvailable() is false there and tests skip.
class AllocationCounter
{
public:
    /// True when this build counts allocations
    static bool IsAvailable();

    AllocationCounter();
    ~AllocationCounter();
    AllocationCounter(const AllocationCounter&) = delete;
    AllocationCounter& operator=(const AllocationCounter&) = delete;

    /// Allocations by this thread since construction
    std::uint64_t Count() const;

private:
    std::uint64_t mStart = 0;
};

} // namespace crumple::test
