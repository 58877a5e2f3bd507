// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/base/Assert.h>

#include <atomic>
#include <cstdio>

namespace crumple
{

namespace
{

// The default handler prints and asks for a trap: an assert is a bug in the calling code.
bool DefaultAssertHandler(const char* inExpression, const char* inMessage, const char* inFile, int inLine)
{
    std::fprintf(stderr, "%s:%d: crumple assert failed: %s (%s)\n", inFile, inLine, inMessage, inExpression);
    return true;
}

// Atomic so that a handler installed on one thread is seen by worlds stepping on another.
std::atomic<AssertHandler> sAssertHandler{&DefaultAssertHandler};

} // namespace

void SetAssertHandler(AssertHandler inHandler)
{
    sAssertHandler.store(inHandler != nullptr ? inHandler : &DefaultAssertHandler);
}

bool ReportAssertFailure(const char* inExpression, const char* inMessage, const char* inFile, int inLine)
{
    return sAssertHandler.load()(inExpression, inMessage, inFile, inLine);
}

} // namespace crumple
