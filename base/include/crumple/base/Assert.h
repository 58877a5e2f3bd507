// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#pragma once

#include <crumple/base/Export.h>

namespace crumple
{

/// Called when a CRUMPLE_ASSERT fails. Return true to trap into the debugger (abort), false to go on.
/// The library then refuses the bad input through its Result as it would without asserts.
using AssertHandler = bool (*)(const char* inExpression, const char* inMessage, const char* inFile, int inLine);

/// Replace the assert handler (nullptr restores the default, which prints to stderr and aborts).
/// Like Box2D's b2SetAssertFcn and Jolt's AssertFailed this is the one process-wide hook: an assert
/// is a programmer error in the host, not per-world state. Set it once before creating worlds.
CRUMPLE_API void SetAssertHandler(AssertHandler inHandler);

/// Internal: dispatches to the installed handler.
CRUMPLE_API bool ReportAssertFailure(const char* inExpression, const char* inMessage, const char* inFile,
                                     int inLine);

} // namespace crumple

#if defined(CRUMPLE_ENABLE_ASSERTS) || !defined(NDEBUG)
/// Checks a programmer-facing precondition. Active in Debug and under CRUMPLE_ENABLE_ASSERTS.
#define CRUMPLE_ASSERT(inCondition, inMessage)                                                               \
    do                                                                                                       \
    {                                                                                                        \
        if (!(inCondition) && ::crumple::ReportAssertFailure(#inCondition, inMessage, __FILE__, __LINE__))  \
            __builtin_trap();                                                                                \
    } while (false)
#else
#define CRUMPLE_ASSERT(inCondition, inMessage) ((void)0)
#endif

#if defined(CRUMPLE_ENABLE_VALIDATE)
/// Expensive invariant checks, behind their own option (Box2D's B2_VALIDATE).
#define CRUMPLE_VALIDATE(inCondition, inMessage) CRUMPLE_ASSERT(inCondition, inMessage)
#else
#define CRUMPLE_VALIDATE(inCondition, inMessage) ((void)0)
#endif
