// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include "AllocationCounter.h"

#include <cstdlib>
#include <new>

// AddressSanitizer's runtime defines the global operator new and delete itself.
#if defined(__SANITIZE_ADDRESS__)
#define CRUMPLE_COUNT_ALLOCATIONS 0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define CRUMPLE_COUNT_ALLOCATIONS 0
#endif
#endif
#if !defined(CRUMPLE_COUNT_ALLOCATIONS)
#define CRUMPLE_COUNT_ALLOCATIONS 1
#endif

namespace
{

// Per thread, so that Catch2 or another thread cannot change a count.
thread_local std::uint64_t tAllocations = 0;

#if CRUMPLE_COUNT_ALLOCATIONS
void* CountedAllocate(std::size_t inSize)
{
    ++tAllocations;
    if (void* memory = std::malloc(inSize == 0 ? 1 : inSize))
        return memory;
    throw std::bad_alloc();
}

void* CountedAllocateAligned(std::size_t inSize, std::align_val_t inAlignment)
{
    ++tAllocations;
    const std::size_t alignment = static_cast<std::size_t>(inAlignment);
    const std::size_t size = (inSize + alignment - 1) / alignment * alignment;
    if (void* memory = std::aligned_alloc(alignment, size == 0 ? alignment : size))
        return memory;
    throw std::bad_alloc();
}

#endif

} // namespace

#if CRUMPLE_COUNT_ALLOCATIONS
// The replaced global allocation functions of test_fem (sized and unsized, aligned and not, nothrow).
void* operator new(std::size_t inSize) { return CountedAllocate(inSize); }
void* operator new[](std::size_t inSize) { return CountedAllocate(inSize); }
void* operator new(std::size_t inSize, const std::nothrow_t&) noexcept
{
    try
    {
        return CountedAllocate(inSize);
    }
    catch (...)
    {
        return nullptr;
    }
}
void* operator new[](std::size_t inSize, const std::nothrow_t& inTag) noexcept { return operator new(inSize, inTag); }
void* operator new(std::size_t inSize, std::align_val_t inAlignment) { return CountedAllocateAligned(inSize, inAlignment); }
void* operator new[](std::size_t inSize, std::align_val_t inAlignment)
{
    return CountedAllocateAligned(inSize, inAlignment);
}
void operator delete(void* inMemory) noexcept { std::free(inMemory); }
void operator delete[](void* inMemory) noexcept { std::free(inMemory); }
void operator delete(void* inMemory, std::size_t) noexcept { std::free(inMemory); }
void operator delete[](void* inMemory, std::size_t) noexcept { std::free(inMemory); }
void operator delete(void* inMemory, std::align_val_t) noexcept { std::free(inMemory); }
void operator delete[](void* inMemory, std::align_val_t) noexcept { std::free(inMemory); }
void operator delete(void* inMemory, std::size_t, std::align_val_t) noexcept { std::free(inMemory); }
void operator delete[](void* inMemory, std::size_t, std::align_val_t) noexcept { std::free(inMemory); }
void* operator new(std::size_t inSize, std::align_val_t inAlignment, const std::nothrow_t&) noexcept
{
    try
    {
        return CountedAllocateAligned(inSize, inAlignment);
    }
    catch (...)
    {
        return nullptr;
    }
}
void* operator new[](std::size_t inSize, std::align_val_t inAlignment, const std::nothrow_t& inTag) noexcept
{
    return operator new(inSize, inAlignment, inTag);
}
void operator delete(void* inMemory, const std::nothrow_t&) noexcept { std::free(inMemory); }
void operator delete[](void* inMemory, const std::nothrow_t&) noexcept { std::free(inMemory); }
void operator delete(void* inMemory, std::align_val_t, const std::nothrow_t&) noexcept { std::free(inMemory); }
void operator delete[](void* inMemory, std::align_val_t, const std::nothrow_t&) noexcept { std::free(inMemory); }
#endif

namespace crumple::test
{

bool AllocationCounter::IsAvailable() { return CRUMPLE_COUNT_ALLOCATIONS != 0; }

AllocationCounter::AllocationCounter() : mStart(tAllocations) {}
AllocationCounter::~AllocationCounter() = default;

std::uint64_t AllocationCounter::Count() const { return tAllocations - mStart; }

} // namespace crumple::test
